// photoflight: the desktop application. Wiring only: command line, main window, screenshot mode.
#include "ui/dialogs/export_dialog.h"
#include "ui/help/help_browser.h"
#include "ui/main_window.h"
#include "ui/panels/statistics_panel.h"
#include "ui/planning/plan_controller.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTextBrowser>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace {
// --version and --help print and exit: they need no display, so no GUI application for them.
bool onlyPrints(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "--version" || a == "-v" || a == "--help" || a == "-h" || a == "--help-all") return true;
    }
    return false;
}

bool wantsScreenshot(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (QByteArray(argv[i]).startsWith("--screenshot")) return true;
    return false;
}

// Plans the mission in a main window of 1600x1000 (for the main window also comparing the planners,
// which the Statistics dock shows) and grabs it, or the dialog named: export (of the planned
// mission) or help (the user guide, shown at once).
QImage grabPlanned(pf::ui::MainWindow& w, const QString& dialogName, bool loaded) {
    const bool withDialog = !dialogName.isEmpty();
    // The user guide does not depend on the plan: no need to wait for one.
    if (dialogName == QLatin1String("help")) {
        pf::ui::HelpBrowser h(&w);
        h.show();
        h.showPage(QStringLiteral("user-guide.html"));
        QApplication::processEvents();
        return h.grab().toImage();
    }
    if (!loaded)
        return w.grab().toImage();
    w.planController()->planNow();
    if (!w.planController()->waitForIdle(120000))
        std::fprintf(stderr, "photoflight: planning did not finish in time\n");
    else if (!w.planController()->lastError().isEmpty())
        std::fprintf(stderr, "photoflight: %s\n", qPrintable(w.planController()->lastError()));
    if (!withDialog) {
        w.planController()->compare();
        if (!w.planController()->waitForIdle(180000))
            std::fprintf(stderr, "photoflight: the planner comparison did not finish in time\n");
        w.statisticsPanel()->pages()->setCurrentIndex(0); // the plan's own figures
    }
    w.zoomToMission();
    if (!w.waitForMap(20000))
        std::fprintf(stderr, "photoflight: some map tiles did not load in time\n");
    if (dialogName == QLatin1String("export")) {
        // The folder the desktop application offers first.
        const QString folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        pf::ui::ExportDialog d(w.document(), w.planController(), folder, &w);
        d.show();
        QApplication::processEvents();
        return d.grab().toImage();
    }
    return w.grab().toImage();
}

int takeScreenshot(const QString& out, const QString& missionPath, const QString& map,
                   const QString& dialogName, bool compact) {
    if (!dialogName.isEmpty() && dialogName != QLatin1String("export") &&
        dialogName != QLatin1String("help")) {
        std::fprintf(stderr, "photoflight: --dialog must be export or help, not \"%s\"\n",
                     qPrintable(dialogName));
        return 2;
    }
    pf::ui::MainWindow w(nullptr, /*interactive=*/false);
    w.resize(1600, 1000);
    w.show();
    if (!map.isEmpty())
        w.setBaseMap(map);
    QString error;
    const bool loaded =
        missionPath.isEmpty() ? w.openDemoMission(&error) : w.openMission(missionPath, &error);
    if (!loaded)
        std::fprintf(stderr, "photoflight: %s\n", qPrintable(error));
    QApplication::processEvents();
    QImage image = grabPlanned(w, dialogName, loaded);
    if (compact)
        image = image.convertToFormat(QImage::Format_RGB555, Qt::ThresholdDither | Qt::AvoidDither)
                    .convertToFormat(QImage::Format_RGB888);
    if (!image.save(out)) {
        std::fprintf(stderr, "photoflight: cannot write %s\n", qPrintable(out));
        return 2;
    }
    std::printf("%s\n", qPrintable(QFileInfo(out).absoluteFilePath()));
    return loaded ? 0 : 2;
}
} // namespace

int main(int argc, char** argv) {
    // A screenshot needs no screen: render offscreen unless a platform was chosen.
    if (wantsScreenshot(argc, argv) && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    std::unique_ptr<QCoreApplication> application;
    if (onlyPrints(argc, argv))
        application = std::make_unique<QCoreApplication>(argc, argv);
    else
        application = std::make_unique<QApplication>(argc, argv);
    QCoreApplication& app = *application;
    QApplication::setApplicationName(QStringLiteral("Photoflight"));
    QApplication::setOrganizationName(QStringLiteral("Photoflight"));
    QApplication::setApplicationVersion(QStringLiteral(PF_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Photo-survey flight planning for one or several UAVs."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                        QStringLiteral("Plan the mission, render the main window at 1600x1000 to FILE.png and exit."),
                                        QStringLiteral("FILE.png"));
    const QCommandLineOption map(QStringLiteral("map"),
                                 QStringLiteral("Base map: demo, osm, none or a raster file (GeoTIFF, MBTiles, VRT)."),
                                 QStringLiteral("MAP"));
    const QCommandLineOption compact(QStringLiteral("compact"),
                                     QStringLiteral("With --screenshot: store 15-bit colour, a third of the size "
                                                    "(for documentation images)."));
    const QCommandLineOption dialog(
        QStringLiteral("dialog"),
        QStringLiteral("With --screenshot: render a window of the planned mission instead of the "
                       "main window: export (the Export dialog) or help (the user guide)."),
        QStringLiteral("NAME"));
    parser.addOption(screenshot);
    parser.addOption(compact);
    parser.addOption(dialog);
    parser.addOption(map);
    parser.addPositionalArgument(QStringLiteral("mission"), QStringLiteral("Mission file to open."), QStringLiteral("[MISSION]"));
    parser.process(app);
    const QString missionPath = parser.positionalArguments().value(0);

    if (parser.isSet(screenshot))
        return takeScreenshot(parser.value(screenshot), missionPath,
                              parser.isSet(map) ? parser.value(map) : QString(),
                              parser.value(dialog), parser.isSet(compact));

    pf::ui::MainWindow w;
    if (parser.isSet(map)) w.setBaseMap(parser.value(map));
    w.show();
    // After show(): recovery and error dialogs need a visible parent.
    QTimer::singleShot(0, &w, [&w, missionPath] { w.startup(missionPath); });
    return QApplication::exec();
}
