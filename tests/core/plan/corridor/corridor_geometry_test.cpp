// Corridor geometry: the ground within half the width of the line, lanes parallel to it round
// bends.
#include "core/geo/polygon_ops.h"
#include "core/plan/corridor/corridor_geometry.h"
#include "core/plan/corridor/corridor_lanes.h"
#include "corridor_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf::plan {
namespace {

using corridortest::bentLine;
using geo::Vec2;

double distanceToLine(const Polyline& line, const Vec2& p) {
    double best = 1e300;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec2 d = line[i + 1] - line[i];
        const double t = std::clamp((p - line[i]).dot(d) / d.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (line[i] + t * d - p).norm());
    }
    return best;
}

TEST(CorridorGeometry, GroundOfAStraightLineIsItsRectangle) {
    const auto g = corridorGround({Vec2(0, 0), Vec2(1000, 0)}, 80.0);
    ASSERT_EQ(g.size(), 1u);
    EXPECT_NEAR(geo::area(g), 80000.0, 1e-6);
    const auto b = geo::bounds(g);
    EXPECT_NEAR(b.min.x(), 0.0, 1e-9);
    EXPECT_NEAR(b.max.y(), 40.0, 1e-9);
}

// The ground of a bent line: 2hL, plus on the outside of each bend the circular sector h^2 theta /
// 2, less on the inside the kite the two straight parts share, h^2 tan(theta / 2).
TEST(CorridorGeometry, GroundOfABendIsSectorOutsideAndOverlapInside) {
    for (double deg : {10.0, 45.0, 90.0, 120.0}) {
        const Polyline line = bentLine(500.0, {deg, -deg});
        const double h = 40.0, th = deg * M_PI / 180.0;
        const double expected = 2 * h * 1500.0 + 2 * h * h * (0.5 * th - std::tan(0.5 * th));
        const auto g = corridorGround(line, 2 * h);
        ASSERT_EQ(g.size(), 1u) << deg;
        EXPECT_NEAR(geo::area(g), expected, 2e-4 * expected) << deg;
        // Every point of the ground within h of the line.
        for (const auto& p : g.front().outer)
            EXPECT_LE(distanceToLine(line, p), h + 1e-6) << deg;
    }
}

TEST(CorridorGeometry, CleanLineDropsRepeatsAndStraightVertices) {
    const Polyline l =
        cleanLine({Vec2(0, 0), Vec2(0, 0.001), Vec2(50, 0), Vec2(100, 0), Vec2(100, 80)});
    ASSERT_EQ(l.size(), 3u);
    EXPECT_EQ(l[1], Vec2(100, 0));
    EXPECT_NEAR(lineLength(l), 180.0, 1e-6);
}

TEST(CorridorGeometry, LanesAreEvenlySpreadAndFlushWithTheEdges) {
    EXPECT_EQ(laneCount(100.0, 25.0), 4);
    EXPECT_EQ(laneCount(100.1, 25.0), 5);
    EXPECT_EQ(laneCount(10.0, 25.0), 1);
    const auto o = laneOffsets(100.0, 30.0, laneCount(100.0, 30.0));
    ASSERT_EQ(o.size(), 4u);
    EXPECT_NEAR(o.front(), -35.0, 1e-9);
    EXPECT_NEAR(o.back(), 35.0, 1e-9);
    for (std::size_t i = 1; i < o.size(); ++i)
        EXPECT_LE(o[i] - o[i - 1], 30.0 + 1e-9);
}

// Inside a bend the lane meets at the mitre point; outside it follows the circle round the vertex
// with corners within the tolerance of it, and its straight parts keep their offset.
TEST(CorridorGeometry, OffsetLineMitresInsideAndFollowsTheCircleOutside) {
    const Polyline line{Vec2(0, 0), Vec2(200, 0),
                        Vec2(200, 200)}; // a left turn of 90 degrees at (200, 0)
    const OffsetLine inside = offsetLine(line, 30.0, 5.0);
    ASSERT_EQ(inside.points.size(), 3u);
    EXPECT_NEAR((inside.points[1] - Vec2(170, 30)).norm(), 0.0, 1e-9);
    const OffsetLine outside = offsetLine(line, -30.0, 2.0);
    ASSERT_GT(outside.points.size(), 3u); // several legs round the circle
    for (std::size_t i = 1; i + 1 < outside.points.size(); ++i) {
        const double r = (outside.points[i] - Vec2(200, 0)).norm();
        EXPECT_GE(r, 30.0 - 1e-9);
        EXPECT_LE(r, 32.0 + 1e-9);
    }
    EXPECT_NEAR((outside.points.front() - Vec2(0, -30)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((outside.points.back() - Vec2(230, 200)).norm(), 0.0, 1e-9);
    // Stations run from 0 to the length, never back.
    for (std::size_t i = 1; i < outside.stations.size(); ++i)
        EXPECT_GE(outside.stations[i], outside.stations[i - 1]);
    EXPECT_NEAR(outside.stations.back(), 400.0, 1e-9);
}

// A tight zigzag makes an inner lane's short straight part run backwards: it is dropped, and the
// lane never runs against the line.
TEST(CorridorGeometry, OffsetLineDropsPartsATightBendReverses) {
    const Polyline line{Vec2(0, 0), Vec2(300, 0), Vec2(310, 10), Vec2(310, 300)};
    const OffsetLine lane = offsetLine(line, 60.0, 5.0);
    ASSERT_GE(lane.points.size(), 2u);
    for (std::size_t i = 1; i < lane.points.size(); ++i) {
        const Vec2 d = lane.points[i] - lane.points[i - 1];
        // Along the first leg's direction or the last's, never back.
        EXPECT_GT(std::max(d.x(), d.y()), -1e-6);
    }
}

// Photos at the trigger distance along a straight lane, centred as plan::stripPhotos centres them.
TEST(CorridorLanes, StraightLaneHasTheStripRule) {
    OffsetLine lane;
    lane.points = {Vec2(0, 0), Vec2(100, 0)};
    lane.stations = {0, 100};
    const auto p = lanePhotos(lane, 15.0, 20.0);
    ASSERT_EQ(p.size(), 7u); // ceil(100 / 15)
    EXPECT_NEAR(p.front().pos.x(), 50.0 - 45.0, 1e-9);
    for (std::size_t i = 1; i < p.size(); ++i)
        EXPECT_NEAR((p[i].pos - p[i - 1].pos).norm(), 15.0, 1e-9);
    EXPECT_NEAR(p.front().headingDeg, 90.0, 1e-9);
}

// Round the outside of a bend the photos lie closer on the lane: the strip's outer edge, half a
// strip further out, keeps the trigger distance. Along one straight leg of the lane the strip is a
// rectangle and the trigger distance holds; what the corners add goes to the measure.
TEST(CorridorLanes, OutsideOfABendHasCloserPhotos) {
    const Polyline line{Vec2(0, 0), Vec2(300, 0), Vec2(300, 300)}; // a left turn round (300, 0)
    const double spacing = 15.0, strip = 20.0, r = 40.0;
    const OffsetLine outer = offsetLine(line, -r, 1.0);
    const auto p = lanePhotos(outer, spacing, strip);
    // Photos within the bend's quarter (x > 300, y < 0): at least one per trigger distance of the
    // strip's outer edge, a quarter circle of radius r + strip / 2.
    int inBend = 0;
    for (const auto& q : p)
        inBend += q.pos.x() > 300.0 && q.pos.y() < 0.0;
    EXPECT_GE(inBend, static_cast<int>(std::floor((r + 0.5 * strip) * 0.5 * M_PI / spacing)));
    for (std::size_t i = 1; i < p.size(); ++i)
        EXPECT_LE((p[i].pos - p[i - 1].pos).norm(), spacing + 1e-9);
    // Headings turn with the lane, never back.
    for (std::size_t i = 1; i < p.size(); ++i)
        EXPECT_LE(p[i].headingDeg, p[i - 1].headingDeg + 1e-9);
    // Inside the same bend the lane is shorter and its photos keep the trigger distance: fewer
    // photos.
    const auto q = lanePhotos(offsetLine(line, r, 1.0), spacing, strip);
    EXPECT_LT(q.size() + 4, p.size());
}

TEST(CorridorLanes, BlockedIntervalsAlongALane) {
    const Polyline lane{Vec2(0, 0), Vec2(100, 0), Vec2(100, 100)};
    const geo::MultiPolygon zones{
        geo::Polygon{{Vec2(20, -5), Vec2(30, -5), Vec2(30, 5), Vec2(20, 5)}, {}},
        geo::Polygon{{Vec2(90, 40), Vec2(110, 40), Vec2(110, 50), Vec2(90, 50)}, {}}};
    const auto iv = blockedIntervals(lane, zones);
    ASSERT_EQ(iv.size(), 2u);
    EXPECT_NEAR(iv[0].first, 20.0, 1e-9);
    EXPECT_NEAR(iv[0].second, 30.0, 1e-9);
    EXPECT_NEAR(iv[1].first, 140.0, 1e-9);
    EXPECT_NEAR(iv[1].second, 150.0, 1e-9);
}

// A lane cut by a zone: two runs, the photos of the cut stretch at its ends, none inside it.
TEST(CorridorLanes, RunsAroundABlockedStretch) {
    OffsetLine lane;
    lane.points = {Vec2(0, 0), Vec2(200, 0)};
    lane.stations = {0, 200};
    const std::vector<Interval> blocked{{80.0, 120.0}};
    const auto runs = laneRuns(lane, 3, lanePhotos(lane, 10.0, 20.0), blocked);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].lane, 3);
    EXPECT_NEAR(runs[0].points.back().pos.x(), 80.0, 1e-9);
    EXPECT_NEAR(runs[1].points.front().pos.x(), 120.0, 1e-9);
    for (const auto& r : runs)
        for (const auto& p : r.points)
            EXPECT_FALSE(p.pos.x() > 80.0 + 1e-9 && p.pos.x() < 120.0 - 1e-9);
}

} // namespace
} // namespace pf::plan
