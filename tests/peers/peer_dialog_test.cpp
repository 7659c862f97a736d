// Ground station > Connect and Upload against two simulated vehicles (sim_vehicle.mjs) on loopback,
// offscreen: both rows upload in parallel and show the vehicle and the verified result; a refusal
// shows its reason; an ambiguous binding is refused before anything is sent.
#include "tests/peers/peer_process.h"

#include "core/io/mission_export.h"
#include "core/io/mission_file.h"
#include "core/io/mission_items.h"
#include "core/mission/plan_mission.h"
#include "tests/short_battery_demo.h"
#include "ui/mission_document.h"
#include "ui/vehicle/upload_dialog.h"

#include <QApplication>
#include <QCheckBox>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

#include <gtest/gtest.h>

#include <map>
#include <unistd.h>

using pf::test::Peer;

namespace {

// The demo mission planned, as the main window holds it after F5.
void loadPlannedDemo(pf::ui::MissionDocument& doc) {
    auto m = pf::io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    ASSERT_TRUE(m.ok());
    doc.reset(*m, QString());
    auto plan = pf::mission::planMission(*m);
    ASSERT_TRUE(plan.ok());
    std::vector<pf::route::Route> routes;
    for (const auto& a : plan->aircraft)
        routes.push_back(a.route);
    doc.setPlannedRoutes(routes);
}

} // namespace

TEST(UploadDialog, TwoVehiclesUploadInParallelAndShowTheirAnswers) {
    Peer a({"--udp", "0", "--seconds", "90"});
    Peer b({"--udp", "0", "--seconds", "90", "--sysid", "7", "--autopilot", "px4", "--nack", "3:12",
            "--nack-type", "fence"});
    ASSERT_GT(a.port(), 0);
    ASSERT_GT(b.port(), 0);
    pf::ui::MissionDocument doc;
    loadPlannedDemo(doc);
    ASSERT_EQ(doc.routes().size(), 2u);
    pf::ui::UploadDialog dialog(&doc);
    dialog.show();
    dialog.setConnection(0, QStringLiteral("udp:127.0.0.1:%1").arg(a.port()), 0);
    dialog.setConnection(1, QStringLiteral("udp:127.0.0.1:%1").arg(b.port()), 7);
    QSignalSpy done(&dialog, &pf::ui::UploadDialog::uploadsFinished);
    ASSERT_TRUE(dialog.startUpload());
    EXPECT_TRUE(dialog.isRunning());
    ASSERT_TRUE(done.wait(60000));
    EXPECT_EQ(done.at(0).at(0).toInt(), 1);
    EXPECT_EQ(done.at(0).at(1).toInt(), 1);
    EXPECT_TRUE(dialog.rowResult(0).contains(QStringLiteral("uploaded and read back identical")))
        << dialog.rowResult(0).toStdString();
    EXPECT_TRUE(dialog.rowResult(0).contains(QStringLiteral("quadrotor, ArduPilot, system id 1")))
        << dialog.rowResult(0).toStdString();
    EXPECT_TRUE(dialog.rowResult(0).contains(QStringLiteral("Flight plan received")));
    // The second vehicle takes the mission but refuses a fence vertex: the reason is shown.
    EXPECT_TRUE(dialog.rowResult(1).contains(QStringLiteral("refused the geofence at item 3")))
        << dialog.rowResult(1).toStdString();
    EXPECT_TRUE(dialog.rowResult(1).contains(QStringLiteral("altitude (param7) is invalid")))
        << dialog.rowResult(1).toStdString();
    EXPECT_TRUE(dialog.rowResult(1).contains(QStringLiteral("PX4, system id 7")));
    auto* status = dialog.findChild<QLabel*>(QStringLiteral("UploadStatus"));
    ASSERT_NE(status, nullptr);
    EXPECT_TRUE(status->text().contains(QStringLiteral("1 uploaded, 1 failed"))) << status->text().toStdString();
}

TEST(UploadDialog, TwoAircraftOnOneConnectionNeedTheirSystemIds) {
    pf::ui::MissionDocument doc;
    loadPlannedDemo(doc);
    pf::ui::UploadDialog dialog(&doc);
    dialog.setConnection(0, QStringLiteral("udp::14555"), 0);
    dialog.setConnection(1, QStringLiteral("udp::14555"), 0);
    EXPECT_FALSE(dialog.startUpload());
    auto* status = dialog.findChild<QLabel*>(QStringLiteral("UploadStatus"));
    EXPECT_TRUE(status->text().contains(QStringLiteral("give each its vehicle's system id")))
        << status->text().toStdString();
    dialog.setConnection(1, QStringLiteral("udp:nohost"), 0);
    EXPECT_FALSE(dialog.startUpload());
    EXPECT_TRUE(status->text().contains(QStringLiteral("the port \"nohost\" is not a number from 1 to 65535")))
        << status->text().toStdString();
}

// An aircraft needing two batteries: its row offers the sorties, the upload sends only the chosen
// battery's flight (the vehicle holds exactly its items, one take-off, one return) and read back
// verifies that flight; the next battery is then offered, also to the next dialog.
TEST(UploadDialog, OneBatterysFlightIsSentAndTheNextOneOffered) {
    const std::string dir =
        testing::TempDir() + "pf_peer_dialog_sortie_" + std::to_string(getpid());
    Peer vehicle({"--udp", "0", "--seconds", "90", "--report", dir + ".json"});
    ASSERT_GT(vehicle.port(), 0);
    const pf::mission::Mission m = pf::test::shortBatteryDemo();
    pf::ui::MissionDocument doc;
    doc.reset(m, QString());
    auto plan = pf::mission::planMission(m);
    ASSERT_TRUE(plan.ok());
    std::vector<pf::route::Route> routes;
    for (const auto& a : plan->aircraft)
        routes.push_back(a.route);
    doc.setPlannedRoutes(routes);
    ASSERT_EQ(plan->aircraft[0].sortieRoutes.size(), 2u);

    std::map<QString, int> sent;
    auto expectedItems = [&](std::size_t sortie, const pf::io::ExportOptions& o) {
        const auto ctx = pf::io::makeExportContext(m, {plan->aircraft[0].sortieRoutes[sortie]});
        auto items = pf::io::missionItems(ctx, 0, o);
        EXPECT_TRUE(items.ok());
        return items.ok() ? int(items->size()) + 1 : -1; // ArduPilot: the home is item 0
    };
    for (int expected : {0, 1}) {
        pf::ui::UploadDialog dialog(&doc, nullptr, &sent);
        ASSERT_EQ(dialog.sortieCount(0), 2);
        EXPECT_EQ(dialog.sortieCount(1), 1);
        EXPECT_EQ(dialog.sortie(0), expected); // the first, then the one after the last sent
        dialog.setConnection(0, QStringLiteral("udp:127.0.0.1:%1").arg(vehicle.port()), 0);
        auto* other = dialog.findChild<QTableWidget*>(QStringLiteral("UploadTable"))
                          ->cellWidget(1, 0)
                          ->findChild<QCheckBox*>();
        ASSERT_NE(other, nullptr);
        other->setChecked(false);
        QSignalSpy done(&dialog, &pf::ui::UploadDialog::uploadsFinished);
        ASSERT_TRUE(dialog.startUpload());
        ASSERT_TRUE(done.wait(60000));
        ASSERT_EQ(done.at(0).at(0).toInt(), 1) << dialog.rowResult(0).toStdString();
        EXPECT_TRUE(
            dialog.rowResult(0).contains(QStringLiteral("uploaded and read back identical")))
            << dialog.rowResult(0).toStdString();
        QFile held(QString::fromStdString(dir + ".json"));
        ASSERT_TRUE(held.open(QIODevice::ReadOnly));
        const QJsonArray items = QJsonDocument::fromJson(held.readAll())
                                     .object()
                                     .value(QStringLiteral("mission"))
                                     .toArray();
        EXPECT_EQ(items.size(), expectedItems(std::size_t(expected), dialog.exportOptions()));
        int takeoffs = 0, returns = 0;
        for (const auto& item : items) {
            takeoffs += item.toObject().value(QStringLiteral("command")).toInt() == 22;
            returns += item.toObject().value(QStringLiteral("command")).toInt() == 20;
        }
        EXPECT_EQ(takeoffs, 1);
        EXPECT_EQ(returns, 1);
        EXPECT_EQ(sent[QStringLiteral("Falcon 8")], expected + 1);
    }
}

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("photoflight-tests"));
    QApplication::setOrganizationName(QStringLiteral("Photoflight"));
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
