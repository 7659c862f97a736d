// The planned mission's messages worded once for the CLI and the desktop application: the covered
// share that never reads 100 beside unseen ground, the unseen ground in one unit, the share of each
// aircraft's part.
#include "core/mission/plan_messages.h"

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::mission;

namespace {

geo::Polygon square(double x0, double y0, double size) {
    return geo::Polygon{{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}}, {}};
}

} // namespace

TEST(PlanMessages, CoveredShareNeverReadsOneHundredBesideUnseenGround) {
    EXPECT_EQ(coveragePercentText(1.0, 0.0), "100.0");
    EXPECT_EQ(coveragePercentText(0.98912, 1500.0), "98.9");
    // 9 m² unseen of about 1 km²: 99.9991 % with the decimals it takes not to read 100.
    EXPECT_EQ(coveragePercentText(0.999991, 9.0), "99.999");
    EXPECT_EQ(coveragePercentText(0.99991, 9.0), "99.99");
    // Beyond three decimals it says so rather than round up.
    EXPECT_EQ(coveragePercentText(0.9999999, 0.01), "< 100");
}

TEST(PlanMessages, UnseenGroundIsSaidOnceInSquareMetres) {
    MissionPlan plan;
    EXPECT_EQ(uncoveredMessage(plan), "");
    plan.coverageRatio = 0.989;
    plan.uncoveredAreaM2 = 1012.4;
    plan.uncoveredPatchCount = 2;
    EXPECT_EQ(uncoveredMessage(plan),
              "1,012 m² of the area (1.1 %) is seen by no photo, in 2 patch(es)");
    plan.coverageRatio = 0.99999;
    plan.uncoveredAreaM2 = 9.4;
    plan.uncoveredPatchCount = 1;
    EXPECT_EQ(uncoveredMessage(plan),
              "9.4 m² of the area (0.001 %) is seen by no photo, in 1 patch(es)");
}

// Each aircraft's Cover % is the share of its part (less the zones) that the photos see; patches
// the plan does not list are not given to an aircraft.
TEST(PlanMessages, EachAircraftsShareOfItsPart) {
    MissionPlan plan;
    plan.aircraft.resize(2);
    plan.aircraft[0].subarea = {square(0, 0, 100)};
    plan.aircraft[1].subarea = {square(100, 0, 100)};
    EXPECT_FALSE(aircraftCoverage(plan, 0)); // no coverage check yet
    plan.coverageRatio = 0.995;
    plan.uncoveredAreaM2 = 130.0;
    plan.uncovered.push_back({{square(10, 10, 10)}, 100.0}); // in the first part
    plan.uncovered.push_back({{square(97.5, 50, 5)}, 25.0}); // across the border: half in each part
    attributeUncovered(plan, {square(150, 50, 20)});         // a 20 x 20 m zone in the second part
    EXPECT_NEAR(plan.aircraft[0].admissibleAreaM2, 10000.0, 1e-6);
    EXPECT_NEAR(plan.aircraft[1].admissibleAreaM2, 9600.0, 1e-6);
    EXPECT_NEAR(plan.aircraft[0].uncoveredAreaM2, 112.5, 1e-6);
    EXPECT_NEAR(plan.aircraft[1].uncoveredAreaM2, 12.5, 1e-6);
    ASSERT_TRUE(aircraftCoverage(plan, 0));
    EXPECT_NEAR(*aircraftCoverage(plan, 0), 1.0 - 112.5 / 10000.0, 1e-9);
    EXPECT_NEAR(*aircraftCoverage(plan, 1), 1.0 - 12.5 / 9600.0, 1e-9);
    EXPECT_FALSE(aircraftCoverage(plan, 2));
    // 5 m² of the 130 m² lie in patches the plan does not list.
    EXPECT_NEAR(unattributedUncoveredM2(plan), 5.0, 1e-9);
}
