#include "ui/main_window.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>

#include <gtest/gtest.h>

TEST(MainWindow, HasTitleAndMenus) {
    pf::ui::MainWindow w;
    EXPECT_TRUE(w.windowTitle().contains(QStringLiteral("Photoflight")));
    EXPECT_GE(w.menuBar()->actions().size(), 3);
}

namespace {
QMenu* menuNamed(pf::ui::MainWindow& w, const QString& title) {
    for (QAction* a : w.menuBar()->actions())
        if (a->menu() && a->text().remove(QLatin1Char('&')) == title)
            return a->menu();
    return nullptr;
}
} // namespace

// Export is in File as in Plan; the Mosaic dock, hidden until a mosaic is shown, is reached from
// View; a tool's hint is shown whole (it wraps instead of being cut off).
TEST(MainWindow, ExportInFileMosaicInViewAndHintsShownWhole) {
    pf::ui::MainWindow w(nullptr, false);
    w.resize(900, 600);
    w.show();
    QMenu* file = menuNamed(w, QStringLiteral("File"));
    QMenu* view = menuNamed(w, QStringLiteral("View"));
    ASSERT_TRUE(file && view);
    auto* exportAct = w.findChild<QAction*>(QStringLiteral("ExportAction"));
    ASSERT_NE(exportAct, nullptr);
    EXPECT_TRUE(file->actions().contains(exportAct));
    auto* mosaic = w.findChild<QDockWidget*>(QStringLiteral("MosaicDock"));
    ASSERT_NE(mosaic, nullptr);
    EXPECT_FALSE(mosaic->isVisible());
    EXPECT_TRUE(view->actions().contains(mosaic->toggleViewAction()));
    mosaic->toggleViewAction()->trigger();
    EXPECT_TRUE(mosaic->isVisible());

    w.setTool(pf::ui::ToolId::DrawArea);
    const QString hint = w.statusText();
    EXPECT_TRUE(hint.endsWith(QStringLiteral("Backspace: last corner off. Esc: cancel.")))
        << hint.toStdString();
    auto* label = w.findChild<QLabel*>(QStringLiteral("HintLabel"));
    ASSERT_NE(label, nullptr);
    EXPECT_EQ(label->text(), hint);
    EXPECT_TRUE(label->wordWrap());
}
