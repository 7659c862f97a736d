// Tests of terrain following on the command line: --dem, --terrain, --min-clearance on validate and
// plan, the demo terrain mission over the synthetic demo DEM, the files written, and the DEM's
// errors (exit code 2 with the message).
#include "tests/core/cli/cli_test_util.h"

#include <cpl_json.h>

#include <filesystem>
#include <fstream>

namespace {

using namespace pf::cli::test;

const std::string kTerrainDemo = std::string("'") + PF_RESOURCES_DIR + "/demo/demo_mission_terrain.json'";
const std::string kDemo = std::string("'") + PF_RESOURCES_DIR + "/demo/demo_mission.json'";

// The synthetic demo DEM the build generates (build/maps, beside build/app).
std::string demoDem() {
    return (std::filesystem::path(PF_CLI_PATH).parent_path().parent_path() / "maps" / "demo_dem.tif").string();
}

std::filesystem::path freshDir(const std::string& name) {
    const auto dir = std::filesystem::path(testing::TempDir()) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(CliTerrain, ValidateReadsTheDemoDemAndSaysWhatItDoes) {
    const CliRun r = cli("validate " + kTerrainDemo);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "Terrain:          following the terrain, minimum clearance 10.0 m")) << r.out;
    EXPECT_TRUE(has(r.out, "demo_dem.tif (GTiff")) << r.out;
    EXPECT_TRUE(has(r.out, "SYNTHETIC")) << r.out;
    EXPECT_TRUE(has(r.out, "EGM96 height")) << r.out;
    EXPECT_TRUE(has(r.out, "40.0 m above the ground under every photo")) << r.out;
}

TEST(CliTerrain, PlanWritesAltitudesAboveSeaLevelAndTheTerrainMetrics) {
    const auto dir = freshDir("pf_cli_terrain_plan");
    const CliRun r = cli("plan " + kTerrainDemo + " --planner stride --format plan,waypoints,kml --out '" +
                         dir.string() + "'");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "terrain: Falcon 8 40.0 m above the ground")) << r.out;
    CPLJSONDocument metrics;
    ASSERT_TRUE(metrics.Load((dir / "metrics.json").string()));
    const CPLJSONObject t = metrics.GetRoot().GetArray("aircraft")[0].GetObj("terrain");
    ASSERT_TRUE(t.IsValid());
    EXPECT_GE(t.GetDouble("lowest_clearance_m"), 10.0 - 0.05);
    EXPECT_EQ(t.GetDouble("height_above_ground_m"), 40.0);
    CPLJSONDocument plan;
    ASSERT_TRUE(plan.Load((dir / "mission-Falcon_8.plan").string())) << r.out;
    int amsl = 0;
    for (const auto& item : plan.GetRoot().GetObj("mission").GetArray("items"))
        amsl += item.GetInteger("command") == 16 && item.GetInteger("frame") == 0 && item.GetInteger("AltitudeMode") == 2;
    EXPECT_GT(amsl, 10);
    const double home = plan.GetRoot().GetObj("mission").GetArray("plannedHomePosition")[2].ToDouble();
    EXPECT_NEAR(home, t.GetDouble("home_ground_m"), 1e-6);

    // The terrain frame on request.
    const auto dir2 = freshDir("pf_cli_terrain_plan10");
    const CliRun r2 = cli("plan " + kTerrainDemo + " --planner stride --format waypoints --altitude-frame terrain --out '" +
                          dir2.string() + "'");
    ASSERT_EQ(r2.code, 0) << r2.err;
    const std::string wpl = slurp((dir2 / "mission-Falcon_8.waypoints").string());
    EXPECT_TRUE(has(wpl, "\t10\t16\t")) << wpl.substr(0, 400);
    EXPECT_TRUE(has(wpl, "\t40\t1\n")) << wpl.substr(0, 400);
}

TEST(CliTerrain, DemFlagsOnAFlatMission) {
    // --dem turns following on; --terrain off keeps the flat plan.
    const std::string dem = "'" + demoDem() + "'";
    const CliRun on = cli("validate " + kDemo + " --dem " + dem + " --min-clearance 12");
    ASSERT_EQ(on.code, 0) << on.err;
    EXPECT_TRUE(has(on.out, "following the terrain, minimum clearance 12.0 m")) << on.out;
    const CliRun off = cli("validate " + kDemo + " --dem " + dem + " --terrain off");
    ASSERT_EQ(off.code, 0) << off.err;
    EXPECT_TRUE(has(off.out, "Terrain:          off")) << off.out;
    expectBadInput("validate " + kDemo + " --terrain follow", "--terrain: follow needs a terrain model: give --dem FILE");
    expectBadInput("validate " + kDemo + " --dem " + dem + " --terrain up", "--terrain: expected follow or off");
    expectBadInput("validate " + kDemo + " --dem " + dem + " --min-clearance -3", "--min-clearance: must be 0 m or more");
    expectBadInput("plan " + kDemo + " --dem " + dem + " --min-clearance 50", "the minimum clearance of 50.0 m is more than");
    expectBadInput("plan " + kDemo + " --format plan --altitude-frame terrain --out /tmp/pf_x",
                   "altitudes above terrain need a route planned over a terrain model");
    expectBadInput("plan " + kDemo + " --format plan --altitude-frame sky --out /tmp/pf_x",
                   "--altitude-frame: expected auto, relative, amsl or terrain");
}

TEST(CliTerrain, DemErrorsExitWithTwo) {
    const auto dir = freshDir("pf_cli_terrain_bad");
    const std::string junk = (dir / "junk.tif").string();
    std::ofstream(junk) << "not a raster";
    expectBadInput("plan " + kDemo + " --dem '" + junk + "'", "junk.tif\" cannot be read");
    expectBadInput("validate " + kDemo + " --dem '" + (dir / "missing.tif").string() + "'", "missing.tif\" cannot be read");
    // A DEM of another place (the demo DEM moved 1 degree east): it does not cover the area.
    const std::string moved = (dir / "moved.vrt").string();
    const std::string dem = demoDem();
    const CliRun t = cli("--version"); // the binary exists
    ASSERT_EQ(t.code, 0);
    ASSERT_EQ(std::system(("gdal_translate -q -of VRT -a_ullr 9.3230 49.0160 9.3370 49.0085 '" + dem + "' '" + moved +
                           "' 2>/dev/null")
                              .c_str()),
              0);
    expectBadInput("validate " + kDemo + " --dem '" + moved + "' --home-elevation 110", "has no heights over the area");
    expectBadInput("plan " + kDemo + " --dem '" + moved + "'", "has no height at the take-off point");
    const CliRun mosaic = cli("mosaic x.jpg --out /tmp/pf_m.tif --dem '" + dem + "'");
    EXPECT_EQ(mosaic.code, 2);
    EXPECT_TRUE(has(mosaic.err, "the mosaic does not use terrain models")) << mosaic.err;
}

} // namespace
