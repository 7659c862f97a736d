// The automatic choice against every planner it chooses from, on the demo's two aircraft: it never
// finishes later than the mission planned with one planner throughout.
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mission/planner_kinds.h"

#include <gtest/gtest.h>

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

} // namespace
} // namespace pf::mission
