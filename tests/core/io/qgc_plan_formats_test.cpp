#include "core/io/qgc_plan.h"

#include "core/io/waypoint_formats.h"
#include "tests/core/io/formats_test_util.h"

#include <cpl_json.h>
#include <gtest/gtest.h>

using namespace pf;
using namespace pf::io;

namespace {

ExportContext demoContext(std::mt19937& rng) {
    return makeExportContext(test::demoMission(), {test::randomRoute(rng, "Falcon 8 #1")});
}

CPLJSONObject parse(const std::string& text) {
    CPLJSONDocument doc;
    EXPECT_TRUE(doc.LoadMemory(text));
    return doc.GetRoot();
}

} // namespace

TEST(QgcPlanRules, EveryExportSatisfiesQGroundControlsLoader) {
    std::mt19937 rng(31);
    for (int trial = 0; trial < 20; ++trial) {
        ExportContext ctx = demoContext(rng);
        ExportOptions opt;
        opt.firmware = trial % 2 ? QgcFirmware::PX4 : QgcFirmware::ArduPilot;
        opt.end = trial % 3 ? MissionEnd::ReturnToLaunch : MissionEnd::Land;
        opt.capture =
            trial % 4 ? CaptureCommand::ImageStartCapture : CaptureCommand::DigicamControl;
        auto json = qgcPlanJson(ctx, 0, opt);
        ASSERT_TRUE(json.ok());
        const auto v = test::qgcPlanViolations(*json);
        EXPECT_TRUE(v.empty()) << "trial " << trial << ": " << (v.empty() ? "" : v.front());
    }
}

TEST(QgcPlanRules, TheCheckerCatchesEachBrokenRule) {
    std::mt19937 rng(32);
    ExportContext ctx = demoContext(rng);
    const std::string good = *qgcPlanJson(ctx, 0);
    ASSERT_TRUE(test::qgcPlanViolations(good).empty());
    auto broken = [&](auto&& edit) {
        CPLJSONDocument doc;
        doc.LoadMemory(good);
        CPLJSONObject root = doc.GetRoot();
        edit(root);
        return test::qgcPlanViolations(root.Format(CPLJSONObject::PrettyFormat::Plain));
    };
    EXPECT_FALSE(broken([](CPLJSONObject& r) { r.Delete("rallyPoints"); }).empty());
    EXPECT_FALSE(broken([](CPLJSONObject& r) { r.GetObj("mission").Set("version", 1); }).empty());
    EXPECT_FALSE(broken([](CPLJSONObject& r) {
                     CPLJSONObject item = r.GetObj("mission").GetArray("items")[3];
                     item.Delete("AltitudeMode");
                 }).empty());
    EXPECT_FALSE(broken([](CPLJSONObject& r) {
                     CPLJSONObject item = r.GetObj("mission").GetArray("items")[1];
                     item.Delete("params");
                     CPLJSONArray six;
                     for (int i = 0; i < 6; ++i)
                         six.Add(0.0);
                     item.Add("params", six);
                 }).empty());
    EXPECT_FALSE(broken([](CPLJSONObject& r) {
                     CPLJSONObject item = r.GetObj("mission").GetArray("items")[2];
                     item.Set("doJumpId", 1);
                 }).empty());
}

TEST(QgcPlan, ItemsAreTakeoffWaypointsWithCaptureAndReturn) {
    std::mt19937 rng(33);
    ExportContext ctx = demoContext(rng);
    const auto& wps = ctx.routes[0].waypoints;
    const CPLJSONObject root = parse(*qgcPlanJson(ctx, 0));
    EXPECT_EQ(root.GetString("groundStation"), "Photoflight");
    const CPLJSONObject m = root.GetObj("mission");
    EXPECT_EQ(m.GetInteger("firmwareType"), 3);
    EXPECT_EQ(m.GetInteger("vehicleType"), 2);
    EXPECT_DOUBLE_EQ(m.GetDouble("cruiseSpeed"), ctx.routes[0].cruiseSpeedMps);
    const CPLJSONArray home = m.GetArray("plannedHomePosition");
    EXPECT_DOUBLE_EQ(home[0].ToDouble(), 49.010741);
    EXPECT_DOUBLE_EQ(home[1].ToDouble(), 8.3270554);
    const CPLJSONArray items = m.GetArray("items");
    int photos = 0;
    for (const auto& w : wps)
        photos += w.kind == route::WaypointKind::Photo;
    // Take-off, speed, gimbal, the waypoints with their captures, return.
    ASSERT_EQ(items.Size(), 3 + static_cast<int>(wps.size()) + photos + 1);
    EXPECT_EQ(items[0].GetInteger("command"), 22);
    EXPECT_EQ(items[1].GetInteger("command"), 178);
    EXPECT_DOUBLE_EQ(items[1].GetArray("params")[1].ToDouble(), ctx.routes[0].cruiseSpeedMps);
    EXPECT_EQ(items[2].GetInteger("command"), 205);
    EXPECT_DOUBLE_EQ(items[2].GetArray("params")[0].ToDouble(), -90.0);
    int k = 3;
    for (const auto& w : wps) {
        const CPLJSONObject it = items[k++];
        EXPECT_EQ(it.GetInteger("command"), 16);
        EXPECT_EQ(it.GetInteger("frame"), 3);
        const CPLJSONArray p = it.GetArray("params");
        EXPECT_NEAR(p[3].ToDouble(), w.headingDeg, 1e-9); // yaw = heading
        EXPECT_DOUBLE_EQ(p[4].ToDouble(), w.position.lat);
        EXPECT_DOUBLE_EQ(p[5].ToDouble(), w.position.lon);
        EXPECT_DOUBLE_EQ(p[6].ToDouble(), w.altitudeM);
        EXPECT_DOUBLE_EQ(it.GetDouble("Altitude"), w.altitudeM);
        EXPECT_EQ(it.GetInteger("AltitudeMode"), 1);
        if (w.kind == route::WaypointKind::Photo) {
            const CPLJSONObject cap = items[k++];
            EXPECT_EQ(cap.GetInteger("command"), 2000);
            EXPECT_DOUBLE_EQ(cap.GetArray("params")[2].ToDouble(), 1.0); // one image
            EXPECT_FALSE(cap.GetObj("Altitude").IsValid());
        }
    }
    EXPECT_EQ(items[k].GetInteger("command"), 20);
    for (int i = 0; i < items.Size(); ++i)
        EXPECT_EQ(items[i].GetInteger("doJumpId"), i + 1);

    const CPLJSONArray fence = root.GetObj("geoFence").GetArray("polygons");
    ASSERT_EQ(fence.Size(), 2);
    EXPECT_FALSE(fence[0].GetBool("inclusion", true));
    EXPECT_EQ(fence[1].GetArray("polygon").Size(), 16);
    EXPECT_DOUBLE_EQ(fence[0].GetArray("polygon")[0].ToArray()[0].ToDouble(),
                     49.0118201); // [lat, lon]
    EXPECT_EQ(root.GetObj("geoFence").GetArray("circles").Size(), 0);
    EXPECT_EQ(root.GetObj("rallyPoints").GetArray("points").Size(), 1);
}

TEST(QgcPlan, Px4LandAndDigicamOptions) {
    std::mt19937 rng(34);
    ExportContext ctx = demoContext(rng);
    ctx.routes[0].waypoints.front().kind = route::WaypointKind::Photo;
    ExportOptions opt;
    opt.firmware = QgcFirmware::PX4;
    opt.end = MissionEnd::Land;
    opt.capture = CaptureCommand::DigicamControl;
    opt.hoverSpeedMps = 3.5;
    const CPLJSONObject m = parse(*qgcPlanJson(ctx, 0, opt)).GetObj("mission");
    EXPECT_EQ(m.GetInteger("firmwareType"), 12);
    EXPECT_DOUBLE_EQ(m.GetDouble("hoverSpeed"), 3.5);
    const CPLJSONArray items = m.GetArray("items");
    EXPECT_EQ(items[4].GetInteger("command"), 203);
    EXPECT_DOUBLE_EQ(items[4].GetArray("params")[4].ToDouble(), 1.0);
    const CPLJSONObject land = items[items.Size() - 1];
    EXPECT_EQ(land.GetInteger("command"), 21);
    EXPECT_DOUBLE_EQ(land.GetArray("params")[4].ToDouble(), 49.010741);
    EXPECT_TRUE(land.GetObj("AMSLAltAboveTerrain").IsValid());
}

TEST(QgcPlan, GeofenceAndHomeComeBackOnImport) {
    const std::string dir = test::scratchDir("plan_fence");
    std::mt19937 rng(35);
    ExportContext ctx = demoContext(rng);
    ASSERT_TRUE(writeQgcPlan(ctx, 0, dir + "/r.plan").ok());
    auto r = readQgcPlan(dir + "/r.plan");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->noFlyZones.size(), 2u);
    EXPECT_EQ(r->noFlyZones[0].polygon.outer, ctx.mission.noFlyZones[0].polygon.outer);
    ASSERT_TRUE(r->home.has_value());
    EXPECT_EQ(*r->home, *ctx.mission.home);
}
