// Lanes shortened to the ground only they photograph: by hand on a zone that cuts a lane, and on
// generated areas, where the overlap the operator set (the effective footprints) must survive.
#include "core/plan/sweep/lane_trim.h"

#include "core/plan/lanes/lane.h"
#include "tests/core/plan/sweep_test_util.h"

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::plan;
using namespace pf::plan::sweeptest;
using geo::Vec2;

namespace {

CellLane laneAt(double y, double x0, double x1, double photo) {
    CellLane l;
    l.y = y;
    l.stripA = l.flyA = Vec2(x0, y);
    l.stripB = l.flyB = Vec2(x1, y);
    l.span = laneSpan(l.stripA, l.stripB, photo, l.flyA, l.flyB);
    return l;
}

} // namespace

// A 200 x 60 m area, a zone of 20 x 16 m in its middle (no margin) whose foot lies at 24, lanes 20 m
// apart at 10, 30 (cut by the zone into two pieces) and 50, and one more at 18 across the whole width,
// as a cut under the zone asks for: the lanes beside it see all of its band but the ground under the
// zone's foot (20-24, where the pieces do not fly), so it is shortened to that stretch; the others are
// needed end to end and stay.
TEST(LaneTrim, ShortensALaneUnderAZoneToThePartTheOthersLeave) {
    const geo::MultiPolygon area{rect(0, 0, 200, 60)};
    const std::vector<geo::Polygon> zones{rect(90, 24, 110, 40)};
    const geo::MultiPolygon grown{zones[0]};
    const SweepGround ground(area, zones, grown);
    Decomposition d;
    SweepLaneParams p;
    p.trackSpacingM = 20;
    p.photoSpacingM = 10;
    p.reachAlongM = 5;
    std::vector<std::vector<CellLane>> lanes{{laneAt(10, 0, 200, 10), laneAt(18, 0, 200, 10), laneAt(50, 0, 200, 10)},
                                             {laneAt(30, 0, 90, 10)},
                                             {laneAt(30, 110, 200, 10)}};
    const LaneTrimStats st = trimCoveredLanes(d, lanes, p, ground);
    EXPECT_EQ(st.dropped, 0);
    EXPECT_EQ(st.shortened, 1);
    ASSERT_EQ(lanes[0].size(), 3u);
    const CellLane& cut = lanes[0][1];
    EXPECT_DOUBLE_EQ(cut.y, 18);
    const double a = std::min(cut.stripA.x(), cut.stripB.x()), b = std::max(cut.stripA.x(), cut.stripB.x());
    // The ground under the zone's foot, x 90-110: whole trigger distances come off either end, so
    // that the four photos left (85, 95, 105, 115) stay where they were.
    EXPECT_NEAR(a, 80.0, 1e-6);
    EXPECT_NEAR(b, 120.0, 1e-6);
    EXPECT_EQ(cut.span.photos, 4);
    EXPECT_NEAR(cut.span.first.x(), 85.0, 1e-6);
    EXPECT_NEAR(cut.span.last.x(), 115.0, 1e-6);
    for (std::size_t j : {0u, 2u}) {
        EXPECT_DOUBLE_EQ(lanes[0][j].stripA.x(), 0.0);
        EXPECT_DOUBLE_EQ(lanes[0][j].stripB.x(), 200.0);
    }
    EXPECT_DOUBLE_EQ(lanes[1][0].stripB.x(), 90.0);
    EXPECT_DOUBLE_EQ(lanes[2][0].stripA.x(), 110.0);
}

// Two lanes on the same line: one of them is not needed at all and goes; never both.
TEST(LaneTrim, OfTwoLanesOnOneLineOneStays) {
    const geo::MultiPolygon area{rect(0, 0, 100, 20)};
    const std::vector<geo::Polygon> zones;
    const geo::MultiPolygon grown;
    const SweepGround ground(area, zones, grown);
    Decomposition d;
    SweepLaneParams p;
    p.trackSpacingM = 20;
    p.photoSpacingM = 10;
    std::vector<std::vector<CellLane>> lanes{{laneAt(10, 0, 100, 10)}, {laneAt(10, 0, 100, 10)}};
    const LaneTrimStats st = trimCoveredLanes(d, lanes, p, ground);
    EXPECT_EQ(st.dropped, 1);
    EXPECT_EQ(lanes[0].size() + lanes[1].size(), 1u);
}

// On generated areas with zones, in one direction with and without trimming: the effective
// footprints (the overlap the operator set) and the real ones cover no less ground, no lane takes
// more photos, and the set as a whole takes fewer. The photo counts compare like with like only
// when both runs fly the same lane variant: with the placed shared lines (one more variant per
// direction) the two runs may choose different ones (T-304-z11: 464 photos trimmed, 460 not, on
// other lines), and the trimmed lanes can make another variant fly sooner (concave-305-z16: 40 lane
// segments and 320 photos in 1170 s trimmed, 36 segments and 312 photos in 1199 s not), so the
// counts are compared without the placed lines where both runs fly the same number of lane
// segments, and the coverage always.
TEST(LaneTrim, KeepsTheOverlapOnGeneratedAreas) {
    const Camera cam;
    Camera effective;
    effective.realAcross = cam.track();
    effective.realAlong = cam.photo();
    for (bool placed : {false, true}) {
        int before = 0, after = 0, compared = 0;
        // Twelve areas without the placed lines, so that enough of them fly the same segments
        // both ways; eight with them.
        for (unsigned seed = 1; seed <= (placed ? 8u : 12u); ++seed) {
            const Area a = generateArea(seed + 300, 6 + static_cast<int>(seed % 3) * 5);
            const std::string what = a.name + (placed ? " (placed lines)" : "");
            SweepOptions o = options(cam);
            o.anglesDeg = {seed * 20.0};
            o.placedLines = placed;
            o.trimLanes = false;
            auto plain = planSweep(a.region, a.zones, o);
            o.trimLanes = true;
            auto trimmed = planSweep(a.region, a.zones, o);
            ASSERT_TRUE(plain.ok() && trimmed.ok()) << what;
            before += photoCount(*plain);
            after += photoCount(*trimmed);
            if (!placed && trimmed->stats.laneSegments == plain->stats.laneSegments) {
                EXPECT_LE(photoCount(*trimmed), photoCount(*plain) + 2) << what;
                ++compared;
            }
            EXPECT_GE(coverage(a, *trimmed, effective), coverage(a, *plain, effective) - 0.001) << what;
            EXPECT_GE(coverage(a, *trimmed, cam), coverage(a, *plain, cam) - 0.001) << what;
        }
        if (!placed) {
            EXPECT_LT(after, before);
            EXPECT_GE(compared, 8);
        }
    }
}
