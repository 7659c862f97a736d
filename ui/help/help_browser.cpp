#include "ui/help/help_browser.h"

#include <QDesktopServices>
#include <QHBoxLayout>
#include <QKeySequence>
#include <QLabel>
#include <QLineEdit>
#include <QShortcut>
#include <QStyle>
#include <QTextBrowser>
#include <QToolBar>
#include <QVBoxLayout>

// Resources of a static library must be registered by name from the global namespace.
static void initHelpResources() {
    Q_INIT_RESOURCE(help);
}

namespace pf::ui {

QUrl HelpBrowser::contentsUrl() {
    initHelpResources();
    return QUrl(QStringLiteral("qrc:/help/index.html"));
}

HelpBrowser::HelpBrowser(QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Photoflight user guide"));
    setObjectName(QStringLiteral("HelpBrowser"));
    resize(900, 760);

    m_browser = new QTextBrowser(this);
    // Pages of the guide open here; other links are decided in openLink.
    m_browser->setOpenLinks(false);
    connect(m_browser, &QTextBrowser::anchorClicked, this, &HelpBrowser::openLink);

    auto* bar = new QToolBar(this);
    QAction* back = bar->addAction(style()->standardIcon(QStyle::SP_ArrowBack), tr("Back"),
                                   m_browser, &QTextBrowser::backward);
    back->setShortcut(QKeySequence::Back);
    QAction* forward = bar->addAction(style()->standardIcon(QStyle::SP_ArrowForward), tr("Forward"),
                                      m_browser, &QTextBrowser::forward);
    forward->setShortcut(QKeySequence::Forward);
    connect(m_browser, &QTextBrowser::backwardAvailable, back, &QAction::setEnabled);
    connect(m_browser, &QTextBrowser::forwardAvailable, forward, &QAction::setEnabled);
    bar->addAction(style()->standardIcon(QStyle::SP_DirHomeIcon), tr("Contents"), this,
                   [this] { showPage(QStringLiteral("index.html")); });
    bar->addSeparator();
    m_find = new QLineEdit(this);
    m_find->setPlaceholderText(tr("Find in page"));
    m_find->setClearButtonEnabled(true);
    m_find->setMaximumWidth(260);
    bar->addWidget(m_find);
    connect(m_find, &QLineEdit::returnPressed, this, [this] { findNext(false); });
    auto* findShortcut = new QShortcut(QKeySequence::Find, this);
    connect(findShortcut, &QShortcut::activated, this, [this] {
        m_find->setFocus();
        m_find->selectAll();
    });
    auto* again = new QShortcut(QKeySequence::FindNext, this);
    connect(again, &QShortcut::activated, this, [this] { findNext(false); });
    auto* previous = new QShortcut(QKeySequence::FindPrevious, this);
    connect(previous, &QShortcut::activated, this, [this] { findNext(true); });

    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(bar);
    layout->addWidget(m_browser, 1);
    layout->addWidget(m_status);
    showPage(QStringLiteral("index.html"));
}

void HelpBrowser::showPage(const QString& page) {
    openLink(contentsUrl().resolved(QUrl(page)));
}

void HelpBrowser::openLink(const QUrl& url) {
    m_status->clear();
    if (url.scheme() == QLatin1String("qrc") || url.isRelative()) {
        const QUrl target = url.isRelative() ? m_browser->source().resolved(url) : url;
        // A page of the guide; a link that leaves it (to the source tree) cannot be shown here.
        if (target.path().startsWith(QLatin1String("/help/"))) {
            m_browser->setSource(target);
            return;
        }
        m_status->setText(
            tr("“%1” is a file of the source tree, not part of the guide.").arg(url.toString()));
        return;
    }
    // A web address: the desktop's browser, which needs a network.
    if (!QDesktopServices::openUrl(url))
        m_status->setText(tr("Could not open %1.").arg(url.toString()));
}

void HelpBrowser::findNext(bool backward) {
    const QString text = m_find->text();
    if (text.isEmpty())
        return;
    QTextDocument::FindFlags flags;
    if (backward)
        flags |= QTextDocument::FindBackward;
    if (m_browser->find(text, flags)) {
        m_status->clear();
        return;
    }
    // Wrap around once.
    QTextCursor c = m_browser->textCursor();
    c.movePosition(backward ? QTextCursor::End : QTextCursor::Start);
    m_browser->setTextCursor(c);
    if (!m_browser->find(text, flags))
        m_status->setText(tr("“%1” is not on this page.").arg(text));
}

} // namespace pf::ui
