// Help menu: the bundled user guide opens offline and its pages link to each other; the keyboard
// shortcut list is read from the real menus.
#include "ui/help/help_browser.h"
#include "ui/help/shortcuts_dialog.h"
#include "ui/main_window.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTableWidget>
#include <QTextBrowser>

#include <gtest/gtest.h>

namespace {

QMenu* helpMenu(pf::ui::MainWindow& w) {
    return w.menuBar()->findChild<QMenu*>(QStringLiteral("HelpMenu"));
}

QStringList rows(const QTableWidget* t) {
    QStringList out;
    for (int r = 0; r < t->rowCount(); ++r)
        out << t->item(r, 0)->text() + QLatin1Char('|') + t->item(r, 1)->text() + QLatin1Char('|') +
                   t->item(r, 2)->text();
    return out;
}

} // namespace

TEST(Help, UserGuideOpensTheBundledContentsPage) {
    pf::ui::MainWindow w;
    QMenu* help = helpMenu(w);
    ASSERT_NE(help, nullptr);
    auto* guide = help->findChild<QAction*>(QStringLiteral("UserGuideAction"));
    ASSERT_NE(guide, nullptr);
    EXPECT_EQ(guide->shortcut(), QKeySequence(QKeySequence::HelpContents));
    guide->trigger();
    auto* browser = w.findChild<pf::ui::HelpBrowser*>(QStringLiteral("HelpBrowser"));
    ASSERT_NE(browser, nullptr);
    EXPECT_TRUE(browser->isVisible());
    EXPECT_EQ(browser->browser()->source(), pf::ui::HelpBrowser::contentsUrl());
    EXPECT_EQ(browser->browser()->documentTitle(), QStringLiteral("Photoflight documentation"));
    // Triggered again, the same window comes forward instead of a second one.
    guide->trigger();
    EXPECT_EQ(w.findChildren<pf::ui::HelpBrowser*>().size(), 1);
}

TEST(Help, EveryPageLoadsAndItsLinksToOtherPagesResolve) {
    pf::ui::HelpBrowser::contentsUrl(); // registers the guide's resources
    const QDir dir(QStringLiteral(":/help"));
    const QStringList pages = dir.entryList({QStringLiteral("*.html")}, QDir::Files);
    ASSERT_FALSE(pages.isEmpty());
    ASSERT_TRUE(pages.contains(QStringLiteral("index.html")));
    const QRegularExpression href(QStringLiteral("(?:href|src)=\"([^\"#:]+)(#[^\"]*)?\""));
    for (const QString& page : pages) {
        QFile f(dir.filePath(page));
        ASSERT_TRUE(f.open(QIODevice::ReadOnly)) << page.toStdString();
        const QString html = QString::fromUtf8(f.readAll());
        EXPECT_TRUE(html.contains(QStringLiteral("<h1")))
            << page.toStdString() << " has no heading";
        for (auto it = href.globalMatch(html); it.hasNext();) {
            const QString target = it.next().captured(1);
            if (target.startsWith(QLatin1String("../")))
                continue; // the source tree, not the guide
            EXPECT_TRUE(QFile::exists(dir.filePath(target)))
                << page.toStdString() << " links to " << target.toStdString()
                << ", which the guide lacks";
        }
    }
}

TEST(Help, ShortcutListIsReadFromTheMenus) {
    pf::ui::MainWindow w;
    pf::ui::ShortcutsDialog dialog(w.menuBar());
    const QStringList list = rows(dialog.table());
    auto has = [&](const QString& what, const QKeySequence& keys) {
        const QString k = keys.toString(QKeySequence::NativeText);
        return std::any_of(list.begin(), list.end(), [&](const QString& r) {
            const QStringList parts = r.split(QLatin1Char('|'));
            return parts.value(1) == what && parts.value(2).split(QStringLiteral(", ")).contains(k);
        });
    };
    EXPECT_TRUE(has(QStringLiteral("Save"), QKeySequence::Save)) << list.join('\n').toStdString();
    EXPECT_TRUE(has(QStringLiteral("User guide"), QKeySequence::HelpContents));
    EXPECT_TRUE(has(QStringLiteral("Undo"), QKeySequence::Undo));
    // A shortcut added to any menu shows up without touching the dialog.
    QMenu* extra = w.menuBar()->addMenu(QStringLiteral("Extra"));
    extra->addAction(QStringLiteral("Something new"))
        ->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_J));
    pf::ui::ShortcutsDialog again(w.menuBar());
    const QStringList list2 = rows(again.table());
    EXPECT_TRUE(
        list2.contains(QStringLiteral("Extra|Something new|") +
                       QKeySequence(Qt::CTRL | Qt::Key_J).toString(QKeySequence::NativeText)));
}
