// Tests of the fleet plan's choice between splits: when another split is worth planning.
#include "core/mission/fleet_plan.h"

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::mission;

namespace {

geo::Polygon rect(double x0, double y0, double x1, double y1) {
    return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

// Two 100 m squares side by side (20,000 m2), sharing the line x = 100; the plan misses `patches`.
MissionPlan planMissing(const std::vector<geo::Polygon>& patches, double unlistedM2 = 0.0) {
    MissionPlan p;
    for (const auto& q : patches) {
        const double a = geo::area(q);
        p.uncovered.push_back({geo::MultiPolygon{q}, a});
        p.uncoveredAreaM2 += a;
    }
    p.uncoveredAreaM2 += unlistedM2;
    p.coverageRatio = 1.0 - p.uncoveredAreaM2 / 20000.0;
    return p;
}

const std::vector<geo::MultiPolygon> kRegions{{rect(0, 0, 100, 100)}, {rect(100, 0, 200, 100)}};

} // namespace

// The target 0.995 leaves 100 m2 of the 20,000 unseen; the ground within 5 m of both subareas (the
// band 95 < x < 105) is the split's to change.
TEST(FleetPlan, AnotherSplitIsWorthPlanningOnlyForGroundNearTheSharedBoundary) {
    const auto could = [](const MissionPlan& p) {
        return detail::otherSplitCouldReachTarget(p, kRegions, 5.0, 0.995);
    };
    // 150 m2 missed far from the shared boundary (as round a zone's margin): no split changes it.
    EXPECT_FALSE(could(planMissing({rect(10, 40, 25, 50)})));
    // 152 m2 missed on the shared boundary: another split may see it.
    EXPECT_TRUE(could(planMissing({rect(96, 40, 104, 59)})));
    // Just beyond the reach of the other subarea (6 m from the line) it is not the split's.
    EXPECT_FALSE(could(planMissing({rect(79, 40, 94, 50)})));
    // 50 m2 far and 152 m2 near: seeing the near ground would reach the target.
    EXPECT_TRUE(could(planMissing({rect(96, 40, 104, 59), rect(10, 40, 15, 50)})));
    // 150 m2 far and 152 m2 near: the far ground alone misses the target.
    EXPECT_FALSE(could(planMissing({rect(96, 40, 104, 59), rect(10, 40, 25, 50)})));
    // A margin ring the boundary crosses (800 m2, 100 of them within reach): only its crossing is
    // the split's.
    EXPECT_FALSE(could(planMissing({rect(60, 40, 140, 50)})));
    // Patches too small to be listed might lie anywhere: they count as the split's.
    EXPECT_TRUE(could(planMissing({rect(10, 40, 15, 50)}, 400.0)));
    // A plan on target needs nothing else.
    EXPECT_TRUE(could(planMissing({rect(10, 40, 13, 50)})));
}
