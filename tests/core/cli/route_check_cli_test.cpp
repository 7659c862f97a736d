// `photoflight-cli convert` and `plan` refuse routes the route check finds errors in (exit 2, each
// problem on stderr, nothing written) unless --force.
#include "core/io/waypoint_formats.h"

#include "tests/core/io/formats_test_util.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace pf;

namespace {

std::string cli() { return PF_CLI_PATH; }
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

} // namespace

TEST(RouteCheckCli, ConvertRefusesARouteAcrossTheGeofenceUnlessForced) {
    const std::string dir = test::scratchDir("route_check_convert");
    std::mt19937 rng(51);
    // A random route over the demo site crosses its no-fly zones, which the .plan keeps as its geofence.
    const auto ctx = io::makeExportContext(test::demoMission(), {test::randomRoute(rng, "Alpha")});
    ASSERT_TRUE(io::exportRoute(ctx, 0, io::WaypointFormat::QgcPlan, dir + "/src.plan").ok());
    const std::string out = dir + "/out.waypoints";
    const auto refused = test::run(cli() + " convert '" + dir + "/src.plan' '" + out + "'");
    EXPECT_EQ(refused.status, 2) << refused.output;
    EXPECT_TRUE(has(refused.output, "photoflight-cli: error: " + dir + "/src.plan: route 1, waypoint "))
        << refused.output;
    EXPECT_TRUE(has(refused.output, "crosses no-fly zone Geofence")) << refused.output;
    EXPECT_TRUE(has(refused.output, "not written; --force writes it anyway")) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(out));

    const auto forced = test::run(cli() + " convert '" + dir + "/src.plan' '" + out + "' --force");
    EXPECT_EQ(forced.status, 0) << forced.output;
    EXPECT_TRUE(has(forced.output, "photoflight-cli: warning: ")) << forced.output;
    EXPECT_TRUE(std::filesystem::exists(out));

    // The limits can be given: a ceiling below the route's altitudes, a margin.
    const auto low = test::run(cli() + " convert '" + dir + "/src.plan' '" + dir + "/low.plan' --max-altitude 10 --force");
    EXPECT_TRUE(has(low.output, "is above the aircraft's maximum of 10.0 m")) << low.output;
    const auto bad = test::run(cli() + " convert '" + dir + "/src.plan' '" + dir + "/x.plan' --safety-margin -1");
    EXPECT_EQ(bad.status, 2);
    EXPECT_TRUE(has(bad.output, "--safety-margin: must be zero or a positive number of metres")) << bad.output;
}

TEST(RouteCheckCli, ConvertWritesACleanRouteWithoutAWord) {
    const std::string dir = test::scratchDir("route_check_clean");
    const auto r = test::run(cli() + " convert '" + std::string(PF_TEST_DATA_DIR) + "/formats/mission_planner.waypoints' '" +
                             dir + "/edited.plan'");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_FALSE(has(r.output, "warning")) << r.output;
}

TEST(RouteCheckCli, PlanRefusesRoutesWithErrorsUnlessForced) {
    // The crane lies outside the area, between home and the area: planning ignores it, so the legs
    // from and back home cross it; the route check does not ignore it.
    const std::string mission = std::string(PF_TEST_DATA_DIR) + "/cli/zone_outside_area.json";
    const std::string dir = test::scratchDir("route_check_plan");
    const auto refused = test::run(cli() + " plan '" + mission + "' --format plan --out '" + dir + "/out'");
    EXPECT_EQ(refused.status, 2) << refused.output;
    EXPECT_TRUE(has(refused.output, "photoflight-cli: error: Test copter, take-off: the leg from home to waypoint 1 "
                                    "crosses no-fly zone Crane"))
        << refused.output;
    EXPECT_TRUE(has(refused.output, "back home crosses no-fly zone Crane")) << refused.output;
    EXPECT_TRUE(has(refused.output, "nothing written; --force writes them anyway")) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out/plan.geojson"));

    const auto forced = test::run(cli() + " plan '" + mission + "' --format plan --out '" + dir + "/out' --force");
    EXPECT_EQ(forced.status, 0) << forced.output;
    EXPECT_TRUE(has(forced.output, "photoflight-cli: warning: Test copter, take-off: ")) << forced.output;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/mission-Test_copter.plan"));
}

// --planner lawnmower, the yardstick flying straight over the zones, says on stderr which zones its
// routes cross; its crossings are refused unless forced, as any route's.
TEST(RouteCheckCli, TheLawnmowerNamesTheZonesItCrosses) {
    const std::string dir = test::scratchDir("route_check_lawnmower");
    const std::string demo = std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json";
    const auto r = test::run(cli() + " plan '" + demo +
                             "' --planner lawnmower --format plan --out '" + dir + "'");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_TRUE(
        has(r.output,
            "photoflight-cli: warning: the lawnmower planner flies straight over no-fly zones "
            "Warehouse and Radio mast: it ignores no-fly zones by design"))
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir + "/mission-Falcon_8.plan"));
    // The planners that keep out of the zones say nothing of the kind.
    const auto sweep = test::run(cli() + " plan '" + demo + "' --planner sweep");
    EXPECT_EQ(sweep.status, 0) << sweep.output;
    EXPECT_FALSE(has(sweep.output, "flies straight over")) << sweep.output;
}
