// photoflight-cli with corridors and double grids: --corridor FILE --width M plans lanes along the
// line and writes the usual files; bad corridor input exits 2 with a message naming the problem.
#include "tests/core/cli/cli_test_util.h"

#include <filesystem>

namespace {

using namespace pf::cli::test;

std::string corridorFile(const std::string& name) {
    return std::string(PF_TEST_DATA_DIR) + "/corridor/" + name;
}

TEST(CliCorridor, PlansLanesAlongTheLineAndWritesTheFiles) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "pf_cli_corridor";
    std::filesystem::remove_all(dir);
    const CliRun r = cli("plan --corridor '" + corridorFile("river.gpx") +
                         "' --width 80 --aircraft 'DJI Phantom 4 Pro:60' --home 8.3195,49.0095 "
                         "--format plan,kml --out '" +
                         dir.string() + "' --quiet");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "planner: corridor: ")) << r.out;
    EXPECT_TRUE(has(r.out, "lane(s) along the line")) << r.out;
    EXPECT_TRUE(has(r.out, "coverage 100.0 %") || has(r.out, "coverage 99.")) << r.out;
    EXPECT_TRUE(has(r.out, "no-fly violations 0")) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "plan.geojson"));
    EXPECT_TRUE(std::filesystem::exists(dir / "mission-DJI_Phantom_4_Pro.plan"));
    // validate shows the corridor beside its ground.
    const CliRun v = cli("validate --corridor '" + corridorFile("river.geojson") + "' --width 80");
    EXPECT_EQ(v.code, 0) << v.out << v.err;
    EXPECT_TRUE(has(v.out, "Corridor:         2.72 km x 80 m, 6 points (lanes along the line)")) << v.out;
}

TEST(CliCorridor, BadCorridorsAreRefusedWithTheReason) {
    expectBadInput("plan --corridor '" + corridorFile("river.geojson") + "'",
                   "--corridor: needs the corridor's full width: give --width M");
    expectBadInput("plan --corridor '" + corridorFile("river.geojson") + "' --width 0",
                   "--width: must be greater than 0 and at most 5000 m (got 0)");
    expectBadInput(
        "plan '" + std::string(PF_TEST_DATA_DIR) + "/cli/area.geojson' --width 50",
        "--width: is the width of a corridor: give its centre line with --corridor FILE");
    expectBadInput("plan --corridor '" + corridorFile("two_lines.geojson") + "' --width 50",
                   "holds 2 lines ('North bank', 'South bank'), but a corridor follows one");
    expectBadInput("plan --corridor '" + corridorFile("no_line.geojson") + "' --width 50",
                   "--corridor: " + corridorFile("no_line.geojson") + ": no line to import");
}

TEST(CliCorridor, DoubleGridSaysBothPassesCover) {
    const CliRun r = cli("plan '" + std::string(PF_TEST_DATA_DIR) +
                         "/cli/area.geojson' --double-grid --planner sweep --altitude 60 --home "
                         "8.3270554,49.010741 --quiet");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "coverage per pass of the double grid: ")) << r.out;
    EXPECT_TRUE(has(r.out, "planner: double grid: sweep")) << r.out;
}

} // namespace
