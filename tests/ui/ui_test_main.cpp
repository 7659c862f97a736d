// Entry point of pf_ui_tests: one QApplication for all tests, offscreen unless told otherwise.
#include <QApplication>
#include <QStandardPaths>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    ::testing::InitGoogleTest(&argc, argv);
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("photoflight-tests"));
    QApplication::setOrganizationName(QStringLiteral("Photoflight"));
    // Settings, autosaves and caches go to test locations, never the user's.
    QStandardPaths::setTestModeEnabled(true);
    return RUN_ALL_TESTS();
}
