// Tests of what `photoflight-cli plan --out` writes and says it wrote: every file it names exists and
// every file it made is named, also for an aircraft cut into sorties whose Litchi files are split
// into parts (the format takes at most 99 waypoints).
#include "tests/core/cli/cli_test_util.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace {

using namespace pf::cli::test;

TEST(CliPlanFiles, TheWroteListNamesExactlyTheFilesWritten) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "pf_cli_plan_files";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "out");
    // The demo with a 4-minute battery for the first aircraft: two sorties.
    std::string mission = slurp(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    const std::string from = "\"endurance_min\": 20.0";
    const auto at = mission.find(from);
    ASSERT_NE(at, std::string::npos);
    mission.replace(at, from.size(), "\"endurance_min\": 4.0");
    const auto missionPath = dir / "short_battery.json";
    std::ofstream(missionPath) << mission;

    const CliRun r = cli("plan '" + missionPath.string() + "' --format litchi,plan --out '" + (dir / "out").string() + "'");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    const auto wrote = r.out.find("Wrote ");
    ASSERT_NE(wrote, std::string::npos) << r.out;
    std::istringstream line(r.out.substr(wrote + 6, r.out.find('\n', wrote) - wrote - 6));
    std::set<std::string> listed;
    for (std::string p; line >> p;)
        listed.insert(std::filesystem::path(p).filename().string());
    std::set<std::string> onDisk;
    for (const auto& e : std::filesystem::directory_iterator(dir / "out"))
        onDisk.insert(e.path().filename().string());
    EXPECT_EQ(listed, onDisk);
    // The sorties are there, and a sortie over 99 waypoints in parts.
    EXPECT_TRUE(onDisk.count("mission-Falcon_8-sortie2.csv") || onDisk.count("mission-Falcon_8-sortie2-part1.csv"));
    EXPECT_TRUE(std::any_of(onDisk.begin(), onDisk.end(),
                            [](const std::string& f) { return f.find("-sortie1") != std::string::npos; }));
    // No vehicle file asks one battery for both sorties.
    for (const auto& f : onDisk)
        EXPECT_TRUE(f.rfind("mission-Falcon_8-sortie", 0) == 0 ||
                    f.rfind("mission-Falcon_8", 0) != 0)
            << f;
    EXPECT_NE(r.err.find("note: Falcon 8 needs 2 batteries: written as 2 flights, one per battery"),
              std::string::npos)
        << r.err;
}

// A flight of more mission items than the autopilot stores is written with a warning naming the
// aircraft, the count and the limit: the demo's Falcon 8 at 20 m is about 560 items, over PX4's 500
// but within ArduPilot's 650.
TEST(CliPlanFiles, AFlightOverTheAutopilotsItemLimitIsWarnedOf) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "pf_cli_plan_limit";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::string mission = slurp(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    const std::string from = "\"altitude_m\": 40.0";
    const auto at = mission.find(from);
    ASSERT_NE(at, std::string::npos);
    mission.replace(at, from.size(), "\"altitude_m\": 20.0");
    const auto missionPath = dir / "low.json";
    std::ofstream(missionPath) << mission;
    const std::string base =
        "plan '" + missionPath.string() + "' --format plan --out '" + (dir / "out").string() + "'";
    const CliRun px4 = cli(base + " --firmware px4");
    ASSERT_EQ(px4.code, 0) << px4.err;
    const std::string said = "warning: Falcon 8 (mission-Falcon_8.plan): ";
    const auto w = px4.err.find(said);
    ASSERT_NE(w, std::string::npos) << px4.err;
    const int items = std::atoi(px4.err.c_str() + w + said.size());
    EXPECT_GT(items, 500);
    EXPECT_LT(items, 650); // the test needs a flight between the two limits
    EXPECT_NE(px4.err.find(std::to_string(items) +
                           " mission items, more than an autopilot holds: PX4 500"),
              std::string::npos)
        << px4.err;
    EXPECT_EQ(px4.err.find("warning: Phantom 4 Pro ("), std::string::npos) << px4.err;
    const CliRun ardupilot = cli(base);
    ASSERT_EQ(ardupilot.code, 0) << ardupilot.err;
    EXPECT_EQ(ardupilot.err.find("mission items, more than"), std::string::npos) << ardupilot.err;
}

} // namespace

namespace {

// convert of a route that flies through home between sorties (a GeoJSON export keeps the whole
// route for editing) writes one vehicle file per battery, never one flying both.
TEST(CliPlanFiles, ConvertWritesAVehicleFilePerSortie) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "pf_cli_convert_sorties";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::string mission = slurp(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    const std::string from = "\"endurance_min\": 20.0";
    const auto at = mission.find(from);
    ASSERT_NE(at, std::string::npos);
    mission.replace(at, from.size(), "\"endurance_min\": 4.0");
    const auto missionPath = dir / "short_battery.json";
    std::ofstream(missionPath) << mission;
    const CliRun planned =
        cli("plan '" + missionPath.string() + "' --format geojson --out '" + dir.string() + "'");
    ASSERT_EQ(planned.code, 0) << planned.err;
    const CliRun r = cli("convert '" + (dir / "mission-Falcon_8.geojson").string() + "' '" +
                         (dir / "f.plan").string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "f-sortie1.plan"));
    EXPECT_TRUE(std::filesystem::exists(dir / "f-sortie2.plan"));
    EXPECT_FALSE(std::filesystem::exists(dir / "f.plan"));
    EXPECT_NE(r.err.find("note: Falcon 8 needs 2 batteries"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("f-sortie1.plan"), std::string::npos) << r.out;
    // Each holds one take-off and one return.
    for (const char* f : {"f-sortie1.plan", "f-sortie2.plan"}) {
        const std::string text = slurp((dir / f).string());
        std::size_t takeoffs = 0, returns = 0;
        for (auto p = text.find("\"command\":22,"); p != std::string::npos;
             p = text.find("\"command\":22,", p + 1))
            ++takeoffs;
        for (auto p = text.find("\"command\":20,"); p != std::string::npos;
             p = text.find("\"command\":20,", p + 1))
            ++returns;
        EXPECT_EQ(takeoffs, 1u) << f;
        EXPECT_EQ(returns, 1u) << f;
    }
}

} // namespace
