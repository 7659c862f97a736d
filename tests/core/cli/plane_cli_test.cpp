// `photoflight-cli plan --aircraft` with a catalog plane: the plan, its mission files (the take-off
// and landing of its kind, the .plan's vehicle type) and the planner's sentence; Litchi refused by
// name; a grid planner refused with the planners that can.
#include "tests/core/cli/cli_test_util.h"

#include <filesystem>

namespace {

using namespace pf::cli::test;

std::string area() { return "'" + std::string(PF_RESOURCES_DIR) + "/areas/d_nofly.geojson'"; }

TEST(CliPlane, CatalogPlanePlansAndWritesItsFiles) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "pf_cli_plane";
    std::filesystem::remove_all(dir);
    const CliRun r = cli("plan " + area() + " --aircraft 'senseFly eBee X' --gsd 2.5 --home 8.3240,49.0226 --quiet " +
                         "--format plan,waypoints,kml --out '" + dir.string() + "'");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "the only planner here that plans for a plane")) << r.out;
    EXPECT_TRUE(has(r.out, "no-fly violations 0")) << r.out;
    for (const char* f : {"plan.geojson", "metrics.json", "mission-senseFly_eBee_X.plan",
                          "mission-senseFly_eBee_X.waypoints", "mission-senseFly_eBee_X.kml"})
        EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
    const std::string plan = slurp((dir / "mission-senseFly_eBee_X.plan").string());
    EXPECT_TRUE(has(plan, "\"vehicleType\":1")) << plan.substr(0, 400);
    // QGC WPL 110: the take-off (22) first after home, DO_LAND_START (189) and NAV_LAND (21) at the end.
    const std::string wpl = slurp((dir / "mission-senseFly_eBee_X.waypoints").string());
    EXPECT_TRUE(has(wpl, "\n1\t0\t3\t22\t15\t")) << wpl.substr(0, 300);
    EXPECT_TRUE(has(wpl, "\t189\t"));
    EXPECT_TRUE(has(wpl.substr(wpl.rfind('\n', wpl.size() - 2)), "\t21\t"));
}

// --landing-heading sets the fixed-wing's landing direction (NAV_LAND's yaw, param 4); a value
// outside 0 to 360 degrees is refused by name.
TEST(CliPlane, LandingHeadingIsWrittenAndChecked) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "pf_cli_plane_landing";
    std::filesystem::remove_all(dir);
    const std::string base = "plan " + area() +
                             " --aircraft 'senseFly eBee X' --gsd 2.5 --home 8.3240,49.0226 --quiet "
                             "--format waypoints --out '" +
                             dir.string() + "'";
    const CliRun r = cli(base + " --landing-heading 270");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    const std::string wpl = slurp((dir / "mission-senseFly_eBee_X.waypoints").string());
    EXPECT_TRUE(has(wpl.substr(wpl.rfind('\n', wpl.size() - 2)), "\t21\t0\t0\t0\t270\t"))
        << wpl.substr(wpl.rfind('\n', wpl.size() - 2));
    expectBadInput(base + " --landing-heading 400",
                   "--landing-heading: expected degrees from north, from 0 to less than 360");
}

// A plane's file read back stays a plane's: converted to the other MAVLink format it keeps the
// vehicle type, the take-off and the landing sequence, and Litchi still refuses it.
TEST(CliPlane, ConvertKeepsAPlanesKind) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "pf_cli_plane_convert";
    std::filesystem::remove_all(dir);
    const CliRun r = cli("plan " + area() + " --aircraft 'senseFly eBee X' --gsd 2.5 --home 8.3240,49.0226 --quiet " +
                         "--format waypoints,plan --out '" + dir.string() + "'");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    const std::string wpl = (dir / "mission-senseFly_eBee_X.waypoints").string();
    const std::string plan = (dir / "back.plan").string();
    const CliRun c = cli("convert '" + wpl + "' '" + plan + "'");
    ASSERT_EQ(c.code, 0) << c.out << c.err;
    const std::string json = slurp(plan);
    EXPECT_TRUE(has(json, "\"vehicleType\":1")) << json.substr(0, 400);
    const std::string again = (dir / "again.waypoints").string();
    const CliRun d = cli("convert '" + plan + "' '" + again + "'");
    ASSERT_EQ(d.code, 0) << d.out << d.err;
    const std::string back = slurp(again);
    EXPECT_TRUE(has(back, "\n1\t0\t3\t22\t15\t")) << back.substr(0, 300); // NAV_TAKEOFF, pitch 15
    EXPECT_TRUE(has(back, "\t189\t"));                                     // DO_LAND_START
    expectBadInput("convert '" + plan + "' '" + (dir / "wing.csv").string() + "'",
                   "is a fixed-wing aircraft: Litchi missions are flown by DJI multirotors only");
}

TEST(CliPlane, LitchiAndGridPlannersRefuseAPlane) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "pf_cli_plane_refused";
    expectBadInput("plan " + area() + " --aircraft 'DeltaQuad Pro' --gsd 1.2 --format csv --out '" + dir.string() + "'",
                   "DeltaQuad Pro is a VTOL aircraft: Litchi missions are flown by DJI multirotors only");
    expectBadInput("plan " + area() + " --aircraft 'senseFly eBee X' --gsd 2.5 --planner raster",
                   "senseFly eBee X is a fixed-wing aircraft: the raster planner cannot plan for a "
                   "plane (a grid planner's path steps from cell to cell and turns on the spot, which a plane cannot "
                   "fly); choose auto or sweep");
}

} // namespace
