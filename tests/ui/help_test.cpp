// Help menu: the bundled user guide opens offline and its pages link to each other; the keyboard
// shortcut list is read from the real menus.
#include "ui/help/help_browser.h"
#include "ui/help/shortcuts_dialog.h"
#include "ui/main_window.h"
#include "ui/mission_document.h"

#include <QAction>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTableWidget>
#include <QTextBrowser>
#include <QUndoStack>

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
        // A link out of the guide (../README.md, a source file) is shown as its text.
        EXPECT_FALSE(html.contains(QStringLiteral("href=\"../")))
            << page.toStdString() << " links into the source tree";
        for (auto it = href.globalMatch(html); it.hasNext();) {
            const auto m = it.next();
            const QString target = m.captured(1);
            EXPECT_TRUE(QFile::exists(dir.filePath(target)))
                << page.toStdString() << " links to " << target.toStdString()
                << ", which the guide lacks";
            // page.html#part: the part is a heading's id on that page.
            if (!m.captured(2).isEmpty() && target.endsWith(QLatin1String(".html"))) {
                QFile t(dir.filePath(target));
                ASSERT_TRUE(t.open(QIODevice::ReadOnly));
                const QString id =
                    QStringLiteral("id=\"") + m.captured(2).mid(1) + QLatin1Char('"');
                EXPECT_TRUE(QString::fromUtf8(t.readAll()).contains(id))
                    << page.toStdString() << " links to " << (target + m.captured(2)).toStdString()
                    << ", which names no heading";
            }
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

TEST(Help, TheContentsPageLinksEveryPageAndAPartOfAnotherPageOpens) {
    pf::ui::HelpBrowser browser;
    const QDir dir(QStringLiteral(":/help"));
    QFile index(dir.filePath(QStringLiteral("index.html")));
    ASSERT_TRUE(index.open(QIODevice::ReadOnly));
    const QString contents = QString::fromUtf8(index.readAll());
    for (const QString& page : dir.entryList({QStringLiteral("*.html")}, QDir::Files)) {
        if (page == QLatin1String("index.html"))
            continue;
        EXPECT_TRUE(contents.contains(QStringLiteral("href=\"") + page + QLatin1Char('"')))
            << "the contents page does not list " << page.toStdString();
    }
    // A click on "upload" in the contents opens that part of the command-line reference.
    emit browser.browser()->anchorClicked(QUrl(QStringLiteral("cli.html#upload")));
    EXPECT_EQ(browser.browser()->source().fileName(), QStringLiteral("cli.html"));
    EXPECT_EQ(browser.browser()->source().fragment(), QStringLiteral("upload"));
    EXPECT_EQ(browser.browser()->documentTitle(),
              QStringLiteral("Command-line reference (photoflight-cli)"));
}

// The planner options that need words say what they do: a tool tip, and "What's this?" (Shift+F1).
TEST(Help, PlannerOptionsExplainThemselves) {
    pf::ui::MainWindow w;
    for (const char* name : {"PlannerBox", "GridAngleBox", "SafetyMarginBox", "CameraTiltBox",
                             "FrontOverlapBox", "SideOverlapBox"}) {
        auto* widget = w.findChild<QWidget*>(QString::fromLatin1(name));
        ASSERT_NE(widget, nullptr) << name;
        EXPECT_FALSE(widget->toolTip().isEmpty()) << name;
        EXPECT_GT(widget->whatsThis().size(), 60) << name;
    }
    for (const char* name : {"KeepInsideAction", "DoubleGridAction"}) {
        auto* action = w.findChild<QAction*>(QString::fromLatin1(name));
        ASSERT_NE(action, nullptr) << name;
        EXPECT_FALSE(action->toolTip().isEmpty()) << name;
        EXPECT_GT(action->whatsThis().size(), 60) << name;
    }
}

// The safety margin, named in the docs as a tool bar control, is an undoable mission edit.
TEST(Help, SafetyMarginBoxEditsTheMissionUndoably) {
    pf::ui::MainWindow w;
    auto* doc = w.document();
    auto* box = w.findChild<QDoubleSpinBox*>(QStringLiteral("SafetyMarginBox"));
    ASSERT_NE(box, nullptr);
    const double before = doc->mission().options.safetyMarginM;
    EXPECT_DOUBLE_EQ(box->value(), before);
    box->setValue(before + 3.0);
    EXPECT_DOUBLE_EQ(doc->mission().options.safetyMarginM, before + 3.0);
    doc->undoStack()->undo();
    EXPECT_DOUBLE_EQ(doc->mission().options.safetyMarginM, before);
    EXPECT_DOUBLE_EQ(box->value(), before); // the box follows the undo
}
