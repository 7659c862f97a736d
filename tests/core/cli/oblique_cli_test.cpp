// photoflight-cli with oblique photos: --camera-tilt with a double grid plans both passes covered by
// the tilted footprints and writes the gimbal's pitch into the mission files; a tilt out of range,
// a plane or a corridor is refused by name (exit 2).
#include "tests/core/cli/cli_test_util.h"

#include <cpl_json.h>

#include <filesystem>

namespace {

using namespace pf::cli::test;

std::string demo() { return "'" + std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json'"; }

TEST(CliOblique, DoubleGridWithTiltedCamerasPlansAndPitchesTheGimbal) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "pf_cli_oblique";
    std::filesystem::remove_all(dir);
    const CliRun r = cli("plan " + demo() + " --double-grid --camera-tilt 30 --quiet --format plan,waypoints --out '" +
                         dir.string() + "'");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "no-fly violations 0")) << r.out;
    EXPECT_TRUE(has(r.out, "coverage per pass of the double grid: 100.00 %, 100.00 %")) << r.out;
    // DO_MOUNT_CONTROL (205), param 1 the pitch: -90 + 30.
    const std::string wpl = slurp((dir / "mission-Falcon_8.waypoints").string());
    EXPECT_TRUE(has(wpl, "\t205\t-60\t0\t0\t0\t")) << wpl.substr(0, 400);
    CPLJSONDocument plan;
    ASSERT_TRUE(plan.Load((dir / "mission-Falcon_8.plan").string()));
    int mounts = 0;
    for (const auto& item : plan.GetRoot().GetObj("mission").GetArray("items"))
        if (item.GetInteger("command") == 205) {
            EXPECT_DOUBLE_EQ(item.GetArray("params")[0].ToDouble(), -60.0);
            ++mounts;
        }
    EXPECT_EQ(mounts, 1);
}

// validate gives the tilted footprint and how far ahead of the aircraft it is centred.
TEST(CliOblique, ValidateShowsTheTiltedFootprint) {
    const CliRun r = cli("validate " + demo() + " --camera-tilt 30");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "(across x along the track, the tilted camera's), centred ")) << r.out;
    EXPECT_TRUE(has(r.out, " m ahead of the aircraft")) << r.out;
    const CliRun nadir = cli("validate " + demo());
    EXPECT_TRUE(has(nadir.out, "(long side across the track)")) << nadir.out;
}

TEST(CliOblique, BadTiltsPlanesAndCorridorsAreRefusedByName) {
    expectBadInput("plan " + demo() + " --camera-tilt 60 --quiet",
                   "--camera-tilt: must be between 0 (straight down) and 45 degrees forward");
    expectBadInput("plan " + demo() + " --camera-tilt 20 --aircraft 'senseFly eBee X' --gsd 3 --quiet",
                   "flies as a plane, whose camera looks straight down");
    expectBadInput("plan --corridor '" + std::string(PF_TEST_DATA_DIR) +
                       "/corridor/river.gpx' --width 60 --camera-tilt 20 --quiet",
                   "a camera tilt is for area surveys");
}

} // namespace
