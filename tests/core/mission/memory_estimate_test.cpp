// Tests of the memory estimate and the refusal of plans that would not fit.
#include "core/geo/local_frame.h"
#include "core/mission/memory_estimate.h"
#include "core/mission/plan_mission.h"
#include "tests/sample_missions.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

using namespace pf;
using namespace pf::mission;

namespace {

Mission squareAt(double sideM, double altitudeM) {
    const geo::LocalFrame frame = *geo::LocalFrame::create({8.33, 49.01});
    Mission m;
    m.area = frame.toGeo(geo::Polygon{{{0, 0}, {sideM, 0}, {sideM, sideM}, {0, sideM}}, {}});
    m.home = frame.toGeo(geo::Vec2{-10, -10});
    AircraftConfig a = pf::test::bigSiteAircraft(altitudeM);
    m.aircraft.push_back(a);
    m.options.planner = PlannerKind::Stride;
    m.options.gridAngleDeg = 0.0;
    m.options.maxCells = 20'000'000;
    return m;
}

} // namespace

TEST(MemoryEstimate, GrowsWithTheAreaAndFallsWithTheAltitude) {
    const MemoryEstimate small = estimatePlanMemory(squareAt(500, 5));
    const MemoryEstimate big = estimatePlanMemory(squareAt(1000, 5));
    EXPECT_NEAR(big.cells / small.cells, 4.0, 0.1);
    EXPECT_NEAR(big.photos / small.photos, 4.0, 0.01);
    EXPECT_GT(big.bytes, small.bytes);
    // The 2.5 km site of the issue: about 1.1 million cells; measured 0.8 GB.
    const MemoryEstimate site = estimatePlanMemory(squareAt(2500, 5));
    EXPECT_NEAR(site.cells, 1.17e6, 0.05e6);
    EXPECT_GT(site.bytes, 0.6e9);
    EXPECT_LT(site.bytes, 1.2e9);
    // Four times the altitude: a sixteenth of the photos and cells.
    const MemoryEstimate high = estimatePlanMemory(squareAt(1000, 20));
    EXPECT_NEAR(high.photos / big.photos, 1.0 / 16.0, 0.002);
    EXPECT_LT(high.bytes, big.bytes);
}

TEST(MemoryEstimate, RefusesWhatDoesNotFitWithAdvice) {
    const Mission m = squareAt(5000, 5);
    EXPECT_TRUE(checkPlanMemory(m, std::size_t(64) << 30).ok());
    const Status s = checkPlanMemory(m, std::size_t(1) << 30);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::TooLarge);
    const std::string& msg = s.error().message;
    EXPECT_NE(msg.find("GB of memory"), std::string::npos) << msg;
    EXPECT_NE(msg.find("altitude of"), std::string::npos) << msg;
    // The altitude it names fits indeed.
    const auto at = msg.find("altitude of ");
    const double alt = std::stod(msg.substr(at + 12));
    EXPECT_GT(alt, 5.0);
    EXPECT_TRUE(checkPlanMemory(squareAt(5000, alt), std::size_t(1) << 30).ok()) << msg;
    // Comparing planners holds two plans: a budget for one is not enough for two.
    const double one = estimatePlanMemory(m).bytes;
    EXPECT_TRUE(checkPlanMemory(m, static_cast<std::size_t>(one * 1.01)).ok());
    EXPECT_FALSE(checkPlanMemory(m, static_cast<std::size_t>(one * 1.01), 2).ok());
}

// Under an address-space limit (ulimit -v) too small for the plan, planMission refuses up front,
// quickly, instead of failing on an allocation after minutes.
TEST(MemoryEstimate, PlanMissionRefusesUnderALowLimit) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        rlimit lim{};
        lim.rlim_cur = lim.rlim_max = rlim_t(1500) << 20; // 1.5 GB: the 5 km site needs about 3 GB
        setrlimit(RLIMIT_AS, &lim);
        auto plan = planMission(squareAt(5000, 5));
        _exit(!plan && plan.error().code == ErrorCode::TooLarge ? 0 : 1);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
}

namespace {

// The address space this process maps now (VmSize), in bytes.
double mappedBytesNow() {
    FILE* f = std::fopen("/proc/self/status", "r");
    if (!f)
        return 0.0;
    char line[256];
    double kb = 0.0;
    while (std::fgets(line, sizeof line, f))
        if (std::sscanf(line, "VmSize: %lf kB", &kb) == 1)
            break;
    std::fclose(f);
    return kb * 1024.0;
}

} // namespace

// Under ulimit -v the budget is what the plan may hold resident so that its mapping (which an
// address-space limit counts, 1.4 to 1.5 times the resident peak) still fits; 75 % of the limit
// left too little room for that (the 5 km site mapped 4.16 GB for 2.77 GB resident).
TEST(MemoryEstimate, BudgetUnderAnAddressSpaceLimitLeavesRoomForTheMapping) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        rlimit lim{};
        lim.rlim_cur = lim.rlim_max = rlim_t(4000) << 20;
        setrlimit(RLIMIT_AS, &lim);
        const double budget = static_cast<double>(memoryBudgetBytes());
        const bool mappingFits = addressSpaceBytes(budget) <= 0.96 * static_cast<double>(lim.rlim_cur);
        const bool notTooTight = addressSpaceBytes(budget) >= 0.9 * static_cast<double>(lim.rlim_cur);
        // The 5 km site: refused, and the message says the limit is what it runs into.
        const Status s = checkPlanMemory(squareAt(5000, 5), memoryBudgetBytes());
        const bool names = !s.ok() && s.error().message.find("ulimit -v allows") != std::string::npos;
        _exit(mappingFits && notTooTight && names ? 0 : 1);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
}

// The estimate is not below what planning really takes: under the tightest address-space limit the
// check accepts, the plan completes (no allocation fails and no late refusal).
TEST(MemoryEstimate, APlanAcceptedUnderTheTightestLimitCompletes) {
    Mission m = squareAt(790, 5); // about 110,000 cells and 200,000 photos
    m.noFlyZones.push_back({"mast", geo::LocalFrame::create({8.33, 49.01})->toGeo(
                                        geo::Polygon{{{300, 300}, {340, 300}, {340, 340}, {300, 340}}, {}})});
    const double need = estimatePlanMemory(m).bytes;
    // What this test process maps already beyond a fresh command's libraries comes on top.
    const double inherited = std::max(0.0, mappedBytesNow() - 150e6);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        rlimit lim{};
        lim.rlim_cur = lim.rlim_max = static_cast<rlim_t>((addressSpaceBytes(need) + inherited) / 0.95 + 1e6);
        setrlimit(RLIMIT_AS, &lim);
        if (!checkPlanMemory(m, memoryBudgetBytes()).ok())
            _exit(2); // the limit was meant to be just enough
        auto plan = planMission(m);
        _exit(plan && plan->totals.photos > 100000 ? 0 : 1);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
}
