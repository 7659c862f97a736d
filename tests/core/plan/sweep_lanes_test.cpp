// The lanes of a sweep's cells: which lanes other lanes make redundant.
#include "core/plan/sweep_lanes.h"

#include "core/plan/coverage_check.h"
#include "core/plan/decomposition.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pf::plan;
using pf::geo::Vec2;

namespace {

struct Strip {
    pf::geo::MultiPolygon area{pf::geo::Polygon{{Vec2(0, 0), Vec2(300, 0), Vec2(300, 47), Vec2(0, 47)}, {}}};
    std::vector<pf::geo::Polygon> zones;
    pf::geo::MultiPolygon grown;
    SweepGround ground{area, zones, grown};
    double realAcross = 34.64, realAlong = 24.85;
    SweepLaneParams p;
    Strip() {
        p.trackSpacingM = 0.8 * realAcross;
        p.photoSpacingM = 0.8 * realAlong;
        p.marginRunCapM = 50.0;
        p.reachAlongM = 0.5 * realAlong;
        p.neighbourReachM = 0.5 * (realAcross - p.trackSpacingM);
    }
    std::vector<std::vector<CellLane>> lanes(const Decomposition& d, const std::vector<double>& heights) {
        const auto merged = mergeCells(d);
        return {cellLanes(d, merged.front(), heights, p, ground, [](const Vec2&, const Vec2&) { return true; })};
    }
};

double photographed(const Strip& s, const std::vector<std::vector<CellLane>>& lanes) {
    std::vector<PhotoFootprint> fps;
    for (const auto& cl : lanes)
        for (const auto& l : cl)
            for (const auto& ph : makeLane(l.stripA, l.stripB, s.p.photoSpacingM, l.flyA, l.flyB).photos)
                fps.push_back(PhotoFootprint{ph, 90.0, s.realAcross, s.realAlong});
    CoverageCheckOptions co;
    co.resolutionM = 0.5;
    auto c = checkCoverage(s.area, fps, co);
    return c.ok() ? c->coveredFraction : -1.0;
}

} // namespace

// Two long lanes 2 m apart, a third one spacing above: whatever the middle one photographs the other
// two see, however long it is (a cell's lane beside another cell's along a whole zone is such a lane).
// One of the pair goes; the rest still photograph all of the strip.
TEST(SweepLanes, LongLaneOthersSeeIsDropped) {
    Strip s;
    auto d = decompose(s.area, SweepFrame{0.0});
    ASSERT_TRUE(d.ok());
    auto lanes = s.lanes(*d, {10.0, 12.0, 37.0});
    ASSERT_EQ(lanes.front().size(), 3u);
    ASSERT_DOUBLE_EQ(photographed(s, lanes), 1.0);
    const int dropped = dropCoveredLanes(*d, lanes, {}, s.p, s.ground, s.realAcross, s.realAlong, INFINITY);
    EXPECT_EQ(dropped, 1);
    ASSERT_EQ(lanes.front().size(), 2u);
    EXPECT_GT(lanes.front()[1].y - lanes.front()[0].y, 20.0);
    EXPECT_DOUBLE_EQ(photographed(s, lanes), 1.0);
}

// Lanes a full spacing apart each see ground no other lane sees: none is dropped.
TEST(SweepLanes, LanesASpacingApartAreKept) {
    Strip s;
    auto d = decompose(s.area, SweepFrame{0.0});
    ASSERT_TRUE(d.ok());
    auto lanes = s.lanes(*d, {10.0, 37.0});
    EXPECT_EQ(dropCoveredLanes(*d, lanes, {}, s.p, s.ground, s.realAcross, s.realAlong, INFINITY), 0);
    EXPECT_EQ(lanes.front().size(), 2u);
}
