// Tests of what `photoflight-cli plan --out` writes and says it wrote: every file it names exists and
// every file it made is named, also for an aircraft cut into sorties whose Litchi files are split
// into parts (the format takes at most 99 waypoints).
#include "tests/core/cli/cli_test_util.h"

#include <algorithm>
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
}

} // namespace
