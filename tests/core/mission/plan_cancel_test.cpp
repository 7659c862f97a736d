// Tests that a cancelled plan stops in every stage of the chain, well before the plan would have ended.
#include "core/geo/local_frame.h"
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/progress.h"
#include "tests/sample_missions.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <map>
#include <string>

using namespace pf;
using namespace pf::mission;

namespace {

using Clock = std::chrono::steady_clock;

// A 790 m square with 4 round zones, one aircraft at 5 m at a fixed grid angle: about 110,000 cells
// and 200,000 photos, a plan of a second or two.
Mission site() {
    const geo::LocalFrame frame = *geo::LocalFrame::create({8.33, 49.01});
    Mission m;
    const double side = 790;
    m.area = frame.toGeo(geo::Polygon{{{0, 0}, {side, 0}, {side, side}, {0, side}}, {}});
    for (int z = 0; z < 4; ++z) {
        const geo::Vec2 c(150 + 160 * z, 200 + 110 * z);
        geo::Polygon p;
        for (int k = 0; k < 16; ++k)
            p.outer.push_back(c + 16.0 * geo::Vec2(std::cos(k * M_PI / 8), std::sin(k * M_PI / 8)));
        m.noFlyZones.push_back({"zone " + std::to_string(z + 1), frame.toGeo(p)});
    }
    m.home = frame.toGeo(geo::Vec2{-30, -30});
    AircraftConfig a = pf::test::bigSiteAircraft(5.0);
    a.enduranceMin = 40;
    m.aircraft.push_back(a);
    m.options.planner = PlannerKind::Stride;
    m.options.gridAngleDeg = 0.0;
    return m;
}

} // namespace

// Cancelled as a stage begins, the plan returns Cancelled (never a partial plan) in less than half the
// time the whole plan still needed from there (pf_bench's CancelInStageStrideBig measures the latency
// at 10^6 cells).
TEST(PlanCancel, StopsInEveryStageWellBeforeThePlanWouldEnd) {
    const Mission m = site();
    std::map<std::string, Clock::time_point> began;
    Progress watch([&](double, const std::string& stage) { began.emplace(stage, Clock::now()); });
    auto full = planMission(m, &watch);
    const auto end = Clock::now();
    ASSERT_TRUE(full) << full.error().message;
    for (const std::string stage : {"cell path", "photo waypoints", "detours and sorties"}) {
        ASSERT_TRUE(began.count(stage)) << stage;
        const double rest = std::chrono::duration<double>(end - began[stage]).count();
        Clock::time_point cancelledAt;
        Progress* self = nullptr;
        Progress progress([&](double, const std::string& s) {
            if (s == stage && !self->cancelled()) {
                cancelledAt = Clock::now();
                self->cancel();
            }
        });
        self = &progress;
        auto plan = planMission(m, &progress);
        const double latency = std::chrono::duration<double>(Clock::now() - cancelledAt).count();
        ASSERT_TRUE(progress.cancelled()) << stage;
        ASSERT_FALSE(plan) << stage;
        EXPECT_EQ(plan.error().code, ErrorCode::Cancelled) << stage;
        EXPECT_LT(latency, 0.5 * rest) << stage << ": the plan needed " << rest << " s more";
    }
}

// The demo's two aircraft under the automatic choice: the whole mission is planned with each
// planner alone on worker threads beside the per-aircraft choice. Cancelled at its first report,
// the plan returns Cancelled, every worker stopped too, in a fraction of the whole plan's time.
TEST(PlanCancel, AutomaticFleetPlanStopsItsWorkerThreads) {
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    ASSERT_TRUE(m.ok()) << m.error().message;
    ASSERT_GE(m->aircraft.size(), 2u);
    m->options.planner = PlannerKind::Auto;
    const auto t0 = Clock::now();
    auto full = planMission(*m);
    const double whole = std::chrono::duration<double>(Clock::now() - t0).count();
    ASSERT_TRUE(full) << full.error().message;
    Progress* self = nullptr;
    Progress progress([&](double, const std::string&) { self->cancel(); });
    self = &progress;
    const auto t1 = Clock::now();
    auto plan = planMission(*m, &progress);
    const double took = std::chrono::duration<double>(Clock::now() - t1).count();
    ASSERT_TRUE(progress.cancelled());
    ASSERT_FALSE(plan);
    EXPECT_EQ(plan.error().code, ErrorCode::Cancelled);
    EXPECT_LT(took, 0.5 * whole) << "the whole plan took " << whole << " s";
}

// The demo at 3.5 m with one more zone spends most of its plan sharing the area between its two
// aircraft (estimates of each subarea's flight time, then a plan of each split tried). Cancelled as
// an estimate or a split's plan begins, the plan returns Cancelled at its next check: no stage
// reports after the cancel, and it returns within a fraction of a second, where the sharing had
// seconds to go.
TEST(PlanCancel, SharingTheAreaStopsAtItsNextCheck) {
    auto m = pf::test::lowDemoWithZone(PF_RESOURCES_DIR);
    ASSERT_TRUE(m.ok()) << m.error().message;
    for (const std::string stage :
         {"sharing the area: estimating flight times", "sharing the area: planning split 1"}) {
        Clock::time_point cancelledAt;
        int reportsAfter = 0;
        Progress* self = nullptr;
        Progress progress([&](double, const std::string& s) {
            if (self->cancelled())
                ++reportsAfter;
            else if (s == stage) {
                cancelledAt = Clock::now();
                self->cancel();
            }
        });
        self = &progress;
        auto plan = planMission(*m, &progress);
        const double latency = std::chrono::duration<double>(Clock::now() - cancelledAt).count();
        ASSERT_TRUE(progress.cancelled()) << stage;
        ASSERT_FALSE(plan) << stage;
        EXPECT_EQ(plan.error().code, ErrorCode::Cancelled) << stage;
        EXPECT_EQ(reportsAfter, 0) << stage;
        EXPECT_LT(latency, 0.5) << stage;
    }
}
