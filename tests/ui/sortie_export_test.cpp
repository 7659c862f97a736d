// A plan that needs several batteries, exported from the desktop application: the export dialog
// writes exactly the files `photoflight-cli plan --format` writes for the same mission (one vehicle
// file per sortie, byte for byte the same), lists them in a message with the notes, and warns of a
// flight holding more mission items than its autopilot stores.
#include "tests/short_battery_demo.h"
#include "tests/ui/ui_test_util.h"

#include "core/io/mission_file.h"
#include "ui/dialogs/export_dialog.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <map>

using namespace pf;
using namespace pf::ui;

namespace {

// The mission written to `dir`, opened and planned in the main window (as File > Open and F5 do).
std::unique_ptr<MainWindow> openAndPlan(const mission::Mission& m, const QString& path) {
    EXPECT_TRUE(io::writeMissionFile(m, path.toStdString()).ok());
    auto w = ui::test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    EXPECT_TRUE(w->openMission(path, &error)) << error.toStdString();
    w->planNow();
    EXPECT_TRUE(w->planController()->waitForIdle(120000));
    EXPECT_TRUE(w->planController()->lastError().isEmpty())
        << w->planController()->lastError().toStdString();
    return w;
}

std::map<QString, QByteArray> filesIn(const QString& dir, const QStringList& skip = {}) {
    std::map<QString, QByteArray> out;
    for (const QString& f : QDir(dir).entryList(QDir::Files)) {
        if (skip.contains(f))
            continue;
        QFile file(QDir(dir).filePath(f));
        EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << f.toStdString();
        out[f] = file.readAll();
    }
    return out;
}

void tickEveryFormat(ExportDialog& dialog) {
    for (const auto& info : io::waypointFormats()) {
        auto* box = dialog.findChild<QCheckBox*>(
            QStringLiteral("ExportFormat_%1").arg(QString::fromLatin1(info.name)));
        ASSERT_NE(box, nullptr) << info.name;
        box->setChecked(true);
    }
}

} // namespace

TEST(SortieExport, TheExportDialogWritesTheCliFilesOneVehicleFilePerSortie) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString missionPath = dir.filePath(QStringLiteral("short_battery.json"));
    auto w = openAndPlan(pf::test::shortBatteryDemo(), missionPath);
    ASSERT_EQ(w->document()->routes().size(), 2u);

    // The export dialog, every format ticked, as a user would.
    const QString guiDir = dir.filePath(QStringLiteral("gui"));
    ExportDialog dialog(w->document(), w->planController(), guiDir);
    dialog.show();
    tickEveryFormat(dialog);
    const QStringList written = dialog.runExport();
    ASSERT_FALSE(written.isEmpty());

    // The command line on the same mission file.
    const QString cliDir = dir.filePath(QStringLiteral("cli"));
    const std::string cmd = std::string("'") + PF_CLI_PATH + "' plan '" +
                            missionPath.toStdString() +
                            "' --format plan,waypoints,kml,gpx,geojson,csv --out '" +
                            cliDir.toStdString() + "' >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;

    const auto gui = filesIn(guiDir);
    const auto cli =
        filesIn(cliDir, {QStringLiteral("plan.geojson"), QStringLiteral("metrics.json")});
    ASSERT_EQ(int(gui.size()), written.size());
    std::vector<QString> guiNames, cliNames;
    for (const auto& [name, bytes] : gui)
        guiNames.push_back(name);
    for (const auto& [name, bytes] : cli)
        cliNames.push_back(name);
    EXPECT_EQ(guiNames, cliNames);
    for (const auto& [name, bytes] : gui) {
        auto it = cli.find(name);
        if (it != cli.end()) {
            EXPECT_TRUE(bytes == it->second) << name.toStdString() << " differs";
        }
    }
    // Each battery's flight in its own vehicle file; none flying both.
    for (const QString& ext : {QStringLiteral(".plan"), QStringLiteral(".waypoints")}) {
        EXPECT_TRUE(gui.count(QStringLiteral("mission-Falcon_8-sortie1") + ext));
        EXPECT_TRUE(gui.count(QStringLiteral("mission-Falcon_8-sortie2") + ext));
        EXPECT_FALSE(gui.count(QStringLiteral("mission-Falcon_8") + ext));
        EXPECT_TRUE(gui.count(QStringLiteral("mission-Phantom_4_Pro") + ext));
    }
    // The message lists the files and says why there are two for the Falcon 8.
    const QString result = dialog.resultText();
    EXPECT_TRUE(result.contains(QStringLiteral("Wrote %1 files into").arg(written.size())))
        << result.toStdString();
    EXPECT_TRUE(result.contains(QStringLiteral("mission-Falcon_8-sortie1.plan")))
        << result.toStdString();
    EXPECT_TRUE(result.contains(QStringLiteral("Falcon 8 needs 2 batteries: written as 2 flights")))
        << result.toStdString();
}

TEST(SortieExport, AFlightOverTheAutopilotsItemLimitIsWarnedOfInTheMessage) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    mission::Mission m = pf::test::shortBatteryDemo();
    m.aircraft.front().enduranceMin = 20.0;
    m.aircraft.front().altitudeM =
        20.0; // about 560 items in one flight: over PX4's 500, not ArduPilot's 650
    auto w = openAndPlan(m, dir.filePath(QStringLiteral("low.json")));
    ExportDialog dialog(w->document(), w->planController(), dir.filePath(QStringLiteral("out")));
    dialog.show();
    ASSERT_FALSE(dialog.runExport().isEmpty());
    EXPECT_FALSE(dialog.resultText().contains(QStringLiteral("mission items")))
        << dialog.resultText().toStdString();
    auto* firmware = dialog.findChild<QComboBox*>(QStringLiteral("ExportFirmware"));
    ASSERT_NE(firmware, nullptr);
    firmware->setCurrentIndex(firmware->findData(int(io::QgcFirmware::PX4)));
    ASSERT_FALSE(dialog.runExport().isEmpty());
    const QString result = dialog.resultText();
    EXPECT_TRUE(result.contains(QStringLiteral("Falcon 8 (mission-Falcon_8.plan): ")))
        << result.toStdString();
    EXPECT_TRUE(
        result.contains(QStringLiteral("mission items, more than an autopilot holds: PX4 500")))
        << result.toStdString();
    EXPECT_FALSE(result.contains(QStringLiteral("Phantom 4 Pro (mission-")))
        << result.toStdString();
    auto* box = dialog.findChild<QMessageBox*>(QStringLiteral("ExportResult"));
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->icon(), QMessageBox::Warning);
}
