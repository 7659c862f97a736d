#include "ui/main_window.h"

#include <QMenuBar>

#include <gtest/gtest.h>

TEST(MainWindow, HasTitleAndMenus) {
    pf::ui::MainWindow w;
    EXPECT_TRUE(w.windowTitle().contains(QStringLiteral("Photoflight")));
    EXPECT_GE(w.menuBar()->actions().size(), 3);
}
