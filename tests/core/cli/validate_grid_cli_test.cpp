// Tests of `photoflight-cli validate` and `photoflight-cli grid`: the real executable with arguments,
// checking exit codes (0 ok, 2 bad input, 1 internal), stdout and the messages on stderr.
#include "tests/core/cli/cli_test_util.h"

namespace {

using namespace pf::cli::test;

std::string data(const std::string& name) { return std::string("'") + PF_TEST_DATA_DIR + "/" + name + "'"; }

} // namespace

TEST(CliValidate, GoodMissionPrintsTheFigures) {
    const CliRun r = cli("validate " + data("cli/good_mission.json"));
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "Mission:          Good test mission")) << r.out;
    EXPECT_TRUE(has(r.out, "Area:             ")) << r.out;
    EXPECT_TRUE(has(r.out, " m² (")) << r.out;
    EXPECT_TRUE(has(r.out, "Admissible area:  ")) << r.out;
    EXPECT_TRUE(has(r.out, "  altitude        40.0 m")) << r.out;
    // GoPro Hero3 Medium at 40 m: 2 * 40 * tan(47.2 deg) = 86.4 m across, 2 * 40 * tan(27.5 deg) = 41.6 m.
    EXPECT_TRUE(has(r.out, "  footprint       86.4 x 41.6 m")) << r.out;
    EXPECT_TRUE(has(r.out, "  GSD             2.25 cm/px")) << r.out;
    EXPECT_TRUE(has(r.out, "  cell size       34.56 m")) << r.out;
    EXPECT_TRUE(has(r.out, " to photograph (")) << r.out;
    EXPECT_TRUE(has(r.out, "OK: 0 errors")) << r.out;
}

TEST(CliValidate, AreaFileWithFlags) {
    const CliRun r = cli("validate " + data("cli/area.geojson") + " --nofly " + data("cli/nofly_warehouse.geojson") +
                      " --hfov 94.4 --vfov 55 --altitude 40 --overlap 0.6 --safety-margin 3 --grid-angle 10");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "(area minus 1 no-fly zone)")) << r.out;
    EXPECT_TRUE(has(r.out, "Safety margin:    3.0 m")) << r.out;
    EXPECT_TRUE(has(r.out, "Grid angle:       10.0 deg")) << r.out;
    // Side overlap 0.6 -> 86.40 * 0.4 = 34.6 m; front 0.6 -> 41.65 * 0.4 = 16.7 m.
    EXPECT_TRUE(has(r.out, "  effective       34.6 x 16.7 m")) << r.out;
}

TEST(CliValidate, BadPolygonsNameTheProblemAndWhere) {
    expectBadInput("validate " + data("bad/area_self_intersecting.json"),
                   "the area intersects itself: edges 1-2 and 3-4 cross near 49.011000° N, 8.331000° E");
    expectBadInput("validate " + data("bad/area_bow_tie.geojson"),
                   "the area intersects itself: edges 1-2 and 3-4 cross near 49.011000° N, 8.331000° E");
    expectBadInput("validate " + data("bad/nofly_self_intersecting.json"),
                   "no-fly zone \"Yard\" intersects itself: edges 1-2 and 3-4 cross near 49.011750° N, 8.329500° E");
    expectBadInput("validate " + data("bad/area_two_vertices.json"),
                   "the area has 2 distinct vertices; a polygon needs at least 3");
    expectBadInput("validate " + data("bad/area_collinear.json"), "the area has zero area: all its vertices lie on one line");
    expectBadInput("validate " + data("bad/hole_outside.json"), "hole 1 of the area lies outside its outer ring");
    expectBadInput("validate " + data("bad/nofly_covers_area.json"),
                   "no-fly zone \"Everything\" covers the whole area: nothing admissible is left to photograph");
    expectBadInput("validate " + data("bad/area_two_polygons.geojson"),
                   "area_two_polygons.geojson holds 2 polygons, but the area must be a single polygon");
}

// An area file whose polygons carry the attribute role ("area", "nofly"), as the sample areas and
// the generated sets do, is an area with its no-fly zones; without the roles it stays an error.
TEST(CliValidate, AreaFileWithRolesBringsItsZones) {
    const CliRun r = cli(std::string("validate '") + PF_RESOURCES_DIR + "/areas/d_nofly.geojson'");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "(area minus 5 no-fly zones)")) << r.out;
    const CliRun extra = cli(std::string("validate '") + PF_RESOURCES_DIR + "/areas/d_nofly.geojson' --nofly " +
                             data("cli/nofly_warehouse.geojson"));
    EXPECT_EQ(extra.code, 0) << extra.err;
    EXPECT_TRUE(has(extra.out, "6 no-fly zones")) << extra.out;
}

TEST(CliValidate, CoordinatesOutOfRange) {
    // Swapped lon/lat: the mission reader or the validation names the coordinate.
    const CliRun r = cli("validate " + data("bad/area_out_of_range.json"));
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(has(r.err, "98.332465") || has(r.err, "98.3324653")) << r.err;
    EXPECT_TRUE(has(r.err, "out of range")) << r.err;
}

TEST(CliValidate, NoFlyZoneOutsideIsOnlyAWarning) {
    const CliRun r = cli("validate " + data("bad/nofly_outside.json"));
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "  warning: no-fly zone \"Far away\" lies entirely outside the area; it is ignored"))
        << r.out;
    EXPECT_TRUE(has(r.out, "OK: 0 errors, 1 warning")) << r.out;
    // Only errors are repeated on stderr: a warning is said once.
    EXPECT_FALSE(has(r.err, "Far away")) << r.err;
}

TEST(CliValidate, CellBudgetSaysWhatWouldFit) {
    expectBadInput(
        "validate " + data("bad/too_many_cells.json"),
        "Test copter: the area is too large for the cell budget: at 40.0 m (cell size 34.56 m) "
        "its grid would need ");
    const CliRun r = cli("validate " + data("bad/too_many_cells.json"));
    EXPECT_TRUE(has(r.err, "more than the budget of 20; an altitude of at least ")) << r.err;
    // The flag overrides the file's budget.
    EXPECT_EQ(cli("validate " + data("bad/too_many_cells.json") + " --max-cells 1000").code, 0);
}

TEST(CliValidate, FlagErrorsNameTheFlag) {
    const std::string good = "validate " + data("cli/good_mission.json");
    expectBadInput(good + " --altitude -5", "--altitude: must be greater than 0 m (got -5)");
    expectBadInput(good + " --altitude 0", "--altitude: must be greater than 0 m (got 0)");
    expectBadInput(good + " --gsd 0", "--gsd: must be greater than 0 cm/px (got 0)");
    expectBadInput(good + " --overlap 1.2", "--overlap: must be in [0, 1), e.g. 0.7 for 70 % (got 1.2)");
    expectBadInput(good + " --front 1", "--front: must be in [0, 1), e.g. 0.7 for 70 % (got 1)");
    expectBadInput(good + " --altitude 40 --gsd 2", "--gsd: give either --altitude or --gsd, not both");
    expectBadInput(good + " --altitude abc", "option --altitude: 'abc' is not a number");
    expectBadInput(good + " --hfov 60", "--hfov: needs --hfov and --vfov together");
    expectBadInput(good + " --hfov 200 --vfov 50", "--hfov: must be between 0 and 180 degrees, exclusive (got 200)");
    expectBadInput(good + " --planner spiral", "--planner: unknown planner 'spiral' (expected auto, sweep, stride, raster, wavefront or lawnmower)");
    expectBadInput(good + " --grid-angle sideways", "--grid-angle: 'sideways' is neither a number of degrees nor 'auto'");
    expectBadInput(good + " --safety-margin -1", "--safety-margin: must be 0 m or more (got -1)");
    expectBadInput(good + " --max-cells 0", "--max-cells: must be a whole number from 1 to 2147483647 (got 0)");
    expectBadInput(good + " --home 8.3", "--home: expected LON,LAT but got '8.3'");
    expectBadInput(good + " --camera 'No such camera'", "--camera: no camera named 'No such camera' in the catalog");
    expectBadInput(good + " --aircraft 'No such drone'", "--aircraft: no aircraft named 'No such drone' in the catalog");
    expectBadInput(good + " --wings 2", "unknown option --wings");
}

TEST(CliValidate, AltitudeAboveTheAircraftsMaximum) {
    expectBadInput("validate " + data("cli/good_mission.json") + " --altitude 500",
                   "Test copter: the flight altitude of 500.0 m is above its maximum of 120.0 m");
}

TEST(CliValidate, CatalogAircraftAndCamera) {
    const CliRun r = cli("validate " + data("cli/area.geojson") + " --aircraft 'Falcon 8:50' --aircraft 'Falcon 8'" +
                      " --camera 'GoPro Hero3 Medium' --altitude 30");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "Aircraft \"Falcon 8 #1\":\n  altitude        50.0 m")) << r.out;
    EXPECT_TRUE(has(r.out, "Aircraft \"Falcon 8 #2\":\n  altitude        30.0 m")) << r.out;
}

TEST(CliValidate, MissingOrBrokenFiles) {
    const CliRun none = cli("validate");
    EXPECT_EQ(none.code, 2);
    EXPECT_TRUE(has(none.err, "no mission or area file given")) << none.err;
    const CliRun missing = cli("validate /nonexistent/mission.json");
    EXPECT_EQ(missing.code, 2);
    EXPECT_TRUE(has(missing.err, "/nonexistent/mission.json")) << missing.err;
    const CliRun broken = cli("validate " + data("bad/not_json.json"));
    EXPECT_EQ(broken.code, 2);
    EXPECT_TRUE(has(broken.err, "not_json.json")) << broken.err;
}

TEST(CliValidate, HelpIsComplete) {
    const CliRun r = cli("validate --help");
    EXPECT_EQ(r.code, 0);
    for (const char* flag : {"--area", "--nofly", "--camera", "--hfov", "--vfov", "--altitude", "--gsd", "--overlap",
                             "--front", "--side", "--planner", "--grid-angle", "--home", "--aircraft",
                             "--safety-margin", "--max-cells", "Exit codes"})
        EXPECT_TRUE(has(r.out, flag)) << flag;
}

TEST(CliGrid, WritesTheGridAsGeoJson) {
    const std::string out = testing::TempDir() + "pf_cli_grid_test.geojson";
    std::remove(out.c_str());
    const CliRun r = cli("grid " + data("cli/good_mission.json") + " --grid-angle 15 --out '" + out + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "Wrote ")) << r.out;
    EXPECT_TRUE(has(r.out, "angle 15.0 deg")) << r.out;
    const std::string json = slurp(out);
    EXPECT_TRUE(has(json, "\"FeatureCollection\""));
    EXPECT_TRUE(has(json, "\"state\":\"free\""));
    EXPECT_TRUE(has(json, "\"contour\":true"));
    EXPECT_TRUE(has(json, "\"flight_lon\""));
    EXPECT_FALSE(has(json, "\"state\":\"outside\""));
    std::remove(out.c_str());
    const CliRun all = cli("grid " + data("cli/good_mission.json") + " --all-cells --out '" + out + "'");
    ASSERT_EQ(all.code, 0) << all.err;
    EXPECT_TRUE(has(slurp(out), "\"state\":\"outside\""));
    std::remove(out.c_str());
}

TEST(CliGrid, BadInput) {
    expectBadInput("grid " + data("cli/good_mission.json"), "--out is missing");
    expectBadInput("grid " + data("cli/good_mission.json") + " --index 3 --out /tmp/x.geojson",
                   "--index: must be a whole number from 1 to 1");
    const CliRun r = cli("grid " + data("bad/area_self_intersecting.json") + " --out /tmp/never-written.geojson");
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(has(r.err, "the area intersects itself")) << r.err;
    expectBadInput("grid " + data("cli/good_mission.json") + " --out /nonexistent-dir/grid.geojson",
                   "/nonexistent-dir/grid.geojson: cannot write the grid");
    const CliRun help = cli("grid --help");
    EXPECT_EQ(help.code, 0);
    EXPECT_TRUE(has(help.out, "--out FILE")) << help.out;
    EXPECT_TRUE(has(help.out, "unflyable")) << help.out;
}

TEST(CliDemo, DemoMissionValidatesAndGrids) {
    const std::string demo = std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json";
    if (!std::ifstream(demo))
        GTEST_SKIP() << "no demo mission at " << demo;
    const CliRun r = cli("validate '" + demo + "'");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "Rheinhafen training ground")) << r.out;
    EXPECT_TRUE(has(r.out, "(area minus 2 no-fly zones)")) << r.out;
    EXPECT_TRUE(has(r.out, "No-fly zones:     Warehouse, Radio mast")) << r.out;
    EXPECT_TRUE(has(r.out, "OK: 0 errors")) << r.out;
    // About 9 ha.
    const auto at = r.out.find("Area:             ");
    ASSERT_NE(at, std::string::npos);
    std::string digits;
    for (char c : r.out.substr(at + 18, 12))
        if (c >= '0' && c <= '9')
            digits += c;
        else if (c != ',')
            break;
    const double m2 = std::stod(digits);
    EXPECT_GT(m2, 80000);
    EXPECT_LT(m2, 100000);

    const std::string out = testing::TempDir() + "pf_cli_demo_grid.geojson";
    const CliRun g = cli("grid '" + demo + "' --index 2 --grid-angle 30 --out '" + out + "'");
    EXPECT_EQ(g.code, 0) << g.err;
    EXPECT_TRUE(has(g.out, "angle 30.0 deg")) << g.out;
    EXPECT_TRUE(has(slurp(out), "\"state\":\"shifted\"") || has(slurp(out), "\"state\":\"unflyable\""));
    std::remove(out.c_str());
}
