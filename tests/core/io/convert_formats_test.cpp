// photoflight-cli convert, run as a user would.
#include "core/io/waypoint_formats.h"

#include "tests/core/io/formats_test_util.h"

#include <gtest/gtest.h>

using namespace pf;

namespace {

std::string cli() {
    return PF_CLI_PATH;
}
std::string fixture(const std::string& name) {
    return std::string(PF_TEST_DATA_DIR) + "/formats/" + name;
}

} // namespace

TEST(ConvertCli, EditedWaypointsBackToPlan) {
    const std::string dir = test::scratchDir("convert");
    const auto r = test::run(cli() + " convert '" + fixture("mission_planner.waypoints") + "' '" +
                             dir + "/edited.plan'");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output, "wrote " + dir + "/edited.plan: 1 route, 3 waypoints\n");
    auto text = test::run("cat '" + dir + "/edited.plan'");
    EXPECT_TRUE(test::qgcPlanViolations(text.output).empty());
    auto plan = io::importWaypoints(dir + "/edited.plan");
    auto wpl = io::importWaypoints(fixture("mission_planner.waypoints"));
    ASSERT_TRUE(plan.ok() && wpl.ok());
    test::expectSameWaypoints(wpl->routes[0].waypoints, plan->routes[0].waypoints, true, "convert");
}

TEST(ConvertCli, EveryFormatToEveryOther) {
    const std::string dir = test::scratchDir("convert_all");
    std::mt19937 rng(51);
    const auto ctx = io::makeExportContext(test::demoMission(), {test::randomRoute(rng, "Alpha")});
    const char* exts[] = {".plan", ".waypoints", ".gpx", ".geojson", ".csv"};
    for (const char* from : exts) {
        const auto fmt = io::formatFromPath(std::string("x") + from);
        ASSERT_TRUE(io::exportRoute(ctx, 0, *fmt, dir + "/src" + from).ok());
        for (const char* to : exts) {
            const std::string out = dir + "/out_" + std::string(from + 1) + to;
            // The random route crosses the demo's no-fly zones (kept as the .plan's geofence): this
            // test is about the formats, so the route check's refusal is overridden.
            const auto r =
                test::run(cli() + " convert '" + dir + "/src" + from + "' '" + out + "' --force");
            ASSERT_EQ(r.status, 0) << from << " -> " << to << ": " << r.output;
            auto back = io::importWaypoints(out);
            ASSERT_TRUE(back.ok()) << back.error().message;
            const bool exact = std::string(from) == ".gpx" || std::string(from) == ".geojson";
            const bool exactOut = std::string(to) == ".gpx" || std::string(to) == ".geojson";
            test::expectSameWaypoints(ctx.routes[0].waypoints, back->routes[0].waypoints,
                                      exact && exactOut, std::string(from) + " -> " + to);
        }
    }
}

TEST(ConvertCli, BadInputExitsWithTwoAndNamesFileAndLine) {
    const std::string dir = test::scratchDir("convert_bad");
    const auto r = test::run(cli() + " convert '" + fixture("eleven_fields.waypoints") + "' '" +
                             dir + "/o.plan'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.output, "photoflight-cli: error: " + fixture("eleven_fields.waypoints") +
                            ": line 4: expected 12 tab-separated fields but found 11\n");
    const auto k = test::run(cli() + " convert '" + dir + "/o.kml' '" + dir + "/o.plan'");
    EXPECT_EQ(k.status, 2);
    const auto ext = test::run(cli() + " convert '" + fixture("mission_planner.waypoints") + "' '" +
                               dir + "/o.shp'");
    EXPECT_EQ(ext.status, 2);
    EXPECT_NE(ext.output.find("cannot tell the waypoint format from the extension \".shp\""),
              std::string::npos);
    const auto fw = test::run(cli() + " convert '" + fixture("mission_planner.waypoints") + "' '" +
                              dir + "/o.plan' --firmware inav");
    EXPECT_EQ(fw.status, 2);
    EXPECT_EQ(fw.output,
              "photoflight-cli: error: --firmware: expected ardupilot or px4 but got 'inav'\n");
}

TEST(ConvertCli, SeveralRoutesNeedAnAircraftForSingleVehicleFormats) {
    const std::string dir = test::scratchDir("convert_multi");
    std::mt19937 rng(52);
    const auto ctx = io::makeExportContext(
        test::demoMission(), {test::randomRoute(rng, "Alpha"), test::randomRoute(rng, "Bravo")});
    ASSERT_TRUE(io::exportCombined(ctx, io::WaypointFormat::Gpx, dir + "/all.gpx").ok());
    const auto r = test::run(cli() + " convert '" + dir + "/all.gpx' '" + dir + "/one.plan'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(
        r.output,
        "photoflight-cli: error: " + dir +
            "/all.gpx holds 2 routes (Alpha, Bravo) but a .plan file holds one; choose one with "
            "--aircraft NAME\n");
    const auto ok = test::run(cli() + " convert '" + dir + "/all.gpx' '" + dir +
                              "/one.plan' --aircraft Bravo --end land");
    ASSERT_EQ(ok.status, 0) << ok.output;
    auto back = io::importWaypoints(dir + "/one.plan");
    ASSERT_TRUE(back.ok());
    test::expectSameWaypoints(ctx.routes[1].waypoints, back->routes[0].waypoints, false, "bravo");
    const auto none =
        test::run(cli() + " convert '" + dir + "/all.gpx' '" + dir + "/x.plan' --aircraft Zulu");
    EXPECT_EQ(none.status, 2);
    EXPECT_EQ(none.output, "photoflight-cli: error: " + dir +
                               "/all.gpx: no route of aircraft 'Zulu' (the file has: "
                               "Alpha, Bravo)\n");
    const auto both =
        test::run(cli() + " convert '" + dir + "/all.gpx' '" + dir + "/both.geojson'");
    ASSERT_EQ(both.status, 0) << both.output;
    auto gj = io::importWaypoints(dir + "/both.geojson");
    ASSERT_TRUE(gj.ok());
    EXPECT_EQ(gj->routes.size(), 2u);
}
