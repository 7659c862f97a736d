// A plan that needs several batteries, exported from the desktop application: the export dialog
// writes exactly the files `photoflight-cli plan --format` writes for the same mission (one vehicle
// file per sortie, byte for byte the same), lists them in a message with the notes, and warns of a
// flight holding more mission items than its autopilot stores.
#include "tests/short_battery_demo.h"
#include "tests/ui/ui_test_util.h"

#include "core/io/catalog.h"
#include "core/io/mission_file.h"
#include "ui/dialogs/export_dialog.h"
#include "ui/map/plan_layer.h"
#include "ui/mission_document.h"
#include "ui/panels/waypoint_panel.h"
#include "ui/panels/waypoint_table_model.h"
#include "ui/planning/plan_controller.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
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

// Every format ticked but the DJI .kmz: it names a DJI Enterprise aircraft, and the demo's Falcon 8
// and Phantom 4 Pro are none (the export would ask to leave it out).
void tickEveryFormat(ExportDialog& dialog) {
    for (const auto& info : io::waypointFormats()) {
        auto* box = dialog.findChild<QCheckBox*>(
            QStringLiteral("ExportFormat_%1").arg(QString::fromLatin1(info.name)));
        ASSERT_NE(box, nullptr) << info.name;
        box->setChecked(info.format != io::WaypointFormat::WpmlKmz);
    }
}

// The short-battery demo flown by DJI Enterprise aircraft of the catalog: a Matrice 30 (4-minute
// battery: two sorties) and a Mavic 3 Enterprise, with their catalog cameras and the demo's
// altitudes.
mission::Mission shortBatteryDjiDemo() {
    mission::Mission m = pf::test::shortBatteryDemo();
    auto cat = io::loadDefaultCatalog();
    EXPECT_TRUE(cat.ok());
    if (!cat || m.aircraft.size() != 2)
        return m;
    const char* models[] = {"DJI Matrice 30", "DJI Mavic 3 Enterprise"};
    for (std::size_t i = 0; i < 2; ++i) {
        const auto* spec = cat->findAircraft(models[i]);
        EXPECT_NE(spec, nullptr) << models[i];
        if (!spec)
            return m;
        mission::AircraftConfig a =
            mission::aircraftFromCatalog(*spec, cat->findCamera(spec->defaultCamera));
        a.altitudeM = m.aircraft[i].altitudeM;
        a.gsdCm = m.aircraft[i].gsdCm;
        a.colour = m.aircraft[i].colour;
        a.home = m.aircraft[i].home;
        m.aircraft[i] = a;
    }
    m.aircraft.front().enduranceMin = 4.0;
    return m;
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
    auto* box = dialog.findChild<QDialog*>(QStringLiteral("ExportResult"));
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->property("warned").toBool());
    EXPECT_TRUE(result.contains(QStringLiteral("Read the warnings before flying them.")))
        << result.toStdString();
}

// Shown as one flight per sortie: the Waypoints table numbers each row's sortie (the waypoint at
// home between two is the battery change) and the map badges each sortie's start, also once the
// route is edited by hand; the export then still writes one file per sortie.
TEST(SortieExport, TheTableAndTheMapShowEachSortieAlsoOnAnEditedRoute) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto w = openAndPlan(pf::test::shortBatteryDemo(), dir.filePath(QStringLiteral("short.json")));
    const auto& plan = *w->planController()->plan();
    const auto& falcon = plan.aircraft.front();
    ASSERT_EQ(falcon.sorties.size(), 2u);
    auto* model = w->waypointPanel()->model();
    ASSERT_EQ(model->rowCount(), int(falcon.route.waypoints.size()));
    auto sortieText = [&](int row) {
        return model->data(model->index(row, WaypointTableModel::Sortie)).toString();
    };
    const int home = falcon.sorties[1].firstWaypoint - 1;
    EXPECT_EQ(sortieText(0), QStringLiteral("1"));
    EXPECT_EQ(sortieText(home - 1), QStringLiteral("1"));
    EXPECT_EQ(sortieText(home), QStringLiteral("home"));
    EXPECT_EQ(sortieText(home + 1), QStringLiteral("2"));
    EXPECT_EQ(sortieText(model->rowCount() - 1), QStringLiteral("2"));
    EXPECT_TRUE(model->data(model->index(home + 1, WaypointTableModel::Sortie), Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("Sortie 2 of 2")));

    // An edit: the second sortie's first photo waypoint moved. The route is marked edited, and its
    // sorties are still shown and exported.
    int k = home + 1;
    while (k < model->rowCount() &&
           w->document()->routes()[0].route.waypoints[std::size_t(k)].kind !=
               route::WaypointKind::Photo)
        ++k;
    ASSERT_TRUE(model->setData(
        model->index(k, WaypointTableModel::Latitude),
        w->document()->routes()[0].route.waypoints[std::size_t(k)].position.lat + 2e-5));
    ASSERT_TRUE(w->document()->routes()[0].edited);
    const auto& starts = w->planLayer()->routeItems()[0]->data().sortieStarts;
    ASSERT_EQ(starts.size(), 2);
    EXPECT_EQ(starts[0], 0);
    EXPECT_EQ(starts[1], home + 1);
    EXPECT_EQ(sortieText(home), QStringLiteral("home"));
    ExportDialog dialog(w->document(), w->planController(), dir.filePath(QStringLiteral("out")));
    dialog.show();
    const QStringList written = dialog.runExport();
    QStringList names;
    for (const QString& f : written)
        names << QFileInfo(f).fileName();
    EXPECT_TRUE(names.contains(QStringLiteral("mission-Falcon_8-sortie2.plan")))
        << names.join(' ').toStdString();
    EXPECT_FALSE(names.contains(QStringLiteral("mission-Falcon_8.plan")));
}

// Every aircraft a DJI Enterprise model: the dialog ticks the DJI Pilot 2 / FlightHub 2 .kmz by
// default, writes one .kmz per sortie (none flying both) as `photoflight-cli plan --format kmz`
// does, and the files-written window lists each of them.
TEST(SortieExport, DjiAircraftGetTheKmzByDefaultOneFilePerSortie) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString missionPath = dir.filePath(QStringLiteral("dji.json"));
    auto w = openAndPlan(shortBatteryDjiDemo(), missionPath);
    ASSERT_EQ(w->document()->routes().size(), 2u);
    ASSERT_GE(w->planController()->plan()->aircraft.front().sorties.size(), 2u);

    const QString guiDir = dir.filePath(QStringLiteral("gui"));
    ExportDialog dialog(w->document(), w->planController(), guiDir);
    dialog.show();
    auto* kmz = dialog.findChild<QCheckBox*>(QStringLiteral("ExportFormat_kmz"));
    auto* qgc = dialog.findChild<QCheckBox*>(QStringLiteral("ExportFormat_plan"));
    ASSERT_NE(kmz, nullptr);
    ASSERT_NE(qgc, nullptr);
    EXPECT_TRUE(kmz->isChecked());
    EXPECT_FALSE(qgc->isChecked()); // no MAVLink mission for an aircraft that flies none
    const QStringList written = dialog.runExport();
    ASSERT_FALSE(written.isEmpty()) << dialog.resultText().toStdString();

    const QString cliDir = dir.filePath(QStringLiteral("cli"));
    const std::string cmd = std::string("'") + PF_CLI_PATH + "' plan '" +
                            missionPath.toStdString() + "' --format kmz,kml --out '" +
                            cliDir.toStdString() + "' >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::vector<QString> guiNames, cliNames;
    for (const auto& [name, bytes] : filesIn(guiDir))
        guiNames.push_back(name);
    for (const auto& [name, bytes] :
         filesIn(cliDir, {QStringLiteral("plan.geojson"), QStringLiteral("metrics.json")}))
        cliNames.push_back(name);
    EXPECT_EQ(guiNames, cliNames);

    const QString m30 = QStringLiteral("mission-DJI_Matrice_30");
    const QString result = dialog.resultText();
    for (const QString& f :
         {m30 + QStringLiteral("-sortie1.kmz"), m30 + QStringLiteral("-sortie2.kmz"),
          QStringLiteral("mission-DJI_Mavic_3_Enterprise.kmz")}) {
        EXPECT_TRUE(QFileInfo::exists(QDir(guiDir).filePath(f))) << f.toStdString();
        EXPECT_TRUE(result.contains(f)) << result.toStdString();
    }
    EXPECT_FALSE(QFileInfo::exists(QDir(guiDir).filePath(m30 + QStringLiteral(".kmz"))));
}

// Export names as the command line makes them: one '_' where a name has spaces and signs
// ("DJI Mavic 3 Enterprise #1" -> "DJI_Mavic_3_Enterprise_1", never "…Enterprise__1"), and a second
// aircraft whose name reads the same in a file name gets files of its own.
TEST(SortieExport, ExportNamesHaveNoDoubleUnderscoreAndMatchTheCli) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    mission::Mission m = pf::test::shortBatteryDemo();
    m.aircraft[0].name = "DJI Mavic 3 Enterprise #1";
    m.aircraft[1].name = "DJI Mavic 3 Enterprise 1";
    const QString missionPath = dir.filePath(QStringLiteral("names.json"));
    auto w = openAndPlan(m, missionPath);
    const QString guiDir = dir.filePath(QStringLiteral("gui"));
    ExportDialog dialog(w->document(), w->planController(), guiDir);
    dialog.show();
    for (const auto& info : io::waypointFormats()) { // .plan and .kml, as the command line below
        auto* box = dialog.findChild<QCheckBox*>(
            QStringLiteral("ExportFormat_%1").arg(QString::fromLatin1(info.name)));
        ASSERT_NE(box, nullptr) << info.name;
        box->setChecked(info.format == io::WaypointFormat::QgcPlan ||
                        info.format == io::WaypointFormat::Kml);
    }
    const QStringList written = dialog.runExport();
    ASSERT_FALSE(written.isEmpty());
    const auto gui = filesIn(guiDir);
    for (const auto& [name, bytes] : gui)
        EXPECT_FALSE(name.contains(QStringLiteral("__"))) << name.toStdString();
    EXPECT_TRUE(gui.count(QStringLiteral("mission-DJI_Mavic_3_Enterprise_1-sortie1.plan")));
    EXPECT_TRUE(gui.count(QStringLiteral("mission-DJI_Mavic_3_Enterprise_1-sortie2.plan")));
    EXPECT_TRUE(gui.count(QStringLiteral("mission-DJI_Mavic_3_Enterprise_1_2.plan")));

    EXPECT_TRUE(gui.count(QStringLiteral("mission-DJI_Mavic_3_Enterprise_1_2.kml")));

    // The command line writes the same names for the same formats.
    const QString cliDir = dir.filePath(QStringLiteral("cli"));
    const std::string cmd = std::string("'") + PF_CLI_PATH + "' plan '" +
                            missionPath.toStdString() + "' --format plan,kml --out '" +
                            cliDir.toStdString() + "' >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::vector<QString> guiNames, cliNames;
    for (const auto& f : gui)
        guiNames.push_back(f.first);
    for (const auto& f :
         filesIn(cliDir, {QStringLiteral("plan.geojson"), QStringLiteral("metrics.json")}))
        cliNames.push_back(f.first);
    EXPECT_EQ(guiNames, cliNames);
}
