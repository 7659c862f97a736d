// The automatic choice against every planner it chooses from, on the demo's two aircraft and on
// fleets over sample and generated areas: it never finishes later than the mission planned with one
// planner throughout.
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mission/planner_kinds.h"

#include <cpl_json.h>
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace pf::mission {
namespace {

TEST(AutoChoice, NeverFinishesLaterThanAPlannerItChoseFrom) {
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    ASSERT_TRUE(m.ok()) << m.error().message;
    ASSERT_GE(m->aircraft.size(), 2u);
    m->options.planner = PlannerKind::Auto;
    auto chosen = planMission(*m);
    ASSERT_TRUE(chosen.ok()) << chosen.error().message;
    EXPECT_EQ(chosen->noFlyViolations, 0);
    for (PlannerKind k : {PlannerKind::Sweep, PlannerKind::Stride, PlannerKind::Raster}) {
        Mission one = *m;
        one.options.planner = k;
        auto alone = planMission(one);
        ASSERT_TRUE(alone.ok()) << alone.error().message;
        EXPECT_LE(chosen->makespanS, alone->makespanS + 0.5) << plannerKindInfo(k).id;
    }
    EXPECT_FALSE(chosen->plannerChoice.empty());
}

// The whole mission planned with each planner alone runs on worker threads beside the automatic
// choice: the plan is the same, waypoint for waypoint, however the threads were scheduled.
TEST(AutoChoice, FleetPlanIsTheSameEveryTime) {
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    ASSERT_TRUE(m.ok()) << m.error().message;
    m->options.planner = PlannerKind::Auto;
    auto first = planMission(*m);
    ASSERT_TRUE(first.ok()) << first.error().message;
    for (int run = 0; run < 2; ++run) {
        auto again = planMission(*m);
        ASSERT_TRUE(again.ok()) << again.error().message;
        EXPECT_EQ(again->plannerChoice, first->plannerChoice);
        ASSERT_EQ(again->aircraft.size(), first->aircraft.size());
        for (std::size_t k = 0; k < first->aircraft.size(); ++k) {
            const auto& a = first->aircraft[k].localWaypoints;
            const auto& b = again->aircraft[k].localWaypoints;
            ASSERT_EQ(a.size(), b.size()) << "aircraft " << k;
            for (std::size_t i = 0; i < a.size(); ++i)
                ASSERT_EQ(a[i].pos, b[i].pos) << "aircraft " << k << " waypoint " << i;
        }
    }
}

// The CLI's plan of an area file with the given aircraft and planner; the makespan, coverage and
// margin breaches from its metrics.json.
struct CliPlan {
    double makespanS = 0, coverage = 0;
    int violations = -1;
};

CliPlan planWithCli(const std::string& area, const std::string& aircraft, const std::string& planner,
                    const std::filesystem::path& dir) {
    std::filesystem::remove_all(dir);
    const std::string cmd = std::string(PF_CLI_PATH) + " plan '" + area + "' " + aircraft + " --planner " + planner +
                            " --quiet --out '" + dir.string() + "' > /dev/null 2>&1";
    const int rc = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(rc) && WEXITSTATUS(rc) == 0) << cmd;
    CliPlan out;
    CPLJSONDocument metrics;
    if (!metrics.Load((dir / "metrics.json").string()))
        return out;
    const CPLJSONObject total = metrics.GetRoot().GetObj("total");
    out.makespanS = total.GetDouble("makespan_s");
    out.coverage = total.GetDouble("coverage_ratio");
    out.violations = total.GetInteger("nofly_violations", -1);
    return out;
}

// Fleets where, before stride alone was among the whole-mission plans compared, the automatic
// choice finished up to 0.4 min after stride alone (its split, rebalanced on the chosen planners'
// times, came out worse than stride's own): a sample area with three aircraft and two generated
// areas with two. A planner alone that covers less or breaches a margin is not a rival.
TEST(AutoChoice, FleetsNeverFinishLaterThanAPlannerAlone) {
    const auto tmp = std::filesystem::temp_directory_path() / "pf_auto_choice_fleets";
    std::filesystem::remove_all(tmp);
    const std::string generate = std::string(PF_CLI_PATH) + " eval --generate 16 --seed 3 --out '" +
                                 (tmp / "areas").string() + "' > /dev/null 2>&1";
    ASSERT_EQ(std::system(generate.c_str()), 0);
    const std::string two = "--aircraft 'Falcon 8:70' --aircraft 'DJI Phantom 4 Pro:100'";
    const std::string three = two + " --aircraft 'DJI Phantom 4 RTK:90'";
    const std::vector<std::pair<std::string, std::string>> missions = {
        {std::string(PF_RESOURCES_DIR) + "/areas/a_concave.geojson", three},
        {(tmp / "areas" / "gen-s3-014-U.geojson").string(), two},
        {(tmp / "areas" / "gen-s3-016-rectangle.geojson").string(), two},
    };
    for (const auto& [area, aircraft] : missions) {
        SCOPED_TRACE(area + " " + aircraft);
        const CliPlan chosen = planWithCli(area, aircraft, "auto", tmp / "auto");
        ASSERT_GT(chosen.makespanS, 0);
        EXPECT_EQ(chosen.violations, 0);
        EXPECT_GE(chosen.coverage, 0.995);
        for (const char* k : {"stride", "sweep", "raster"}) {
            const CliPlan alone = planWithCli(area, aircraft, k, tmp / k);
            if (alone.coverage < chosen.coverage - 1e-4 || alone.violations > chosen.violations)
                continue;
            EXPECT_LE(chosen.makespanS, alone.makespanS + 0.5) << k;
        }
    }
    std::filesystem::remove_all(tmp);
}

} // namespace
} // namespace pf::mission
