#include "core/geo/polygon_ops.h"

#include <gtest/gtest.h>

using namespace pf::geo;

namespace {

Polygon square(double x0, double y0, double s) {
    return Polygon{{Vec2(x0, y0), Vec2(x0 + s, y0), Vec2(x0 + s, y0 + s), Vec2(x0, y0 + s)}, {}};
}

Polygon ring10() { // 10 x 10 square with a 2 x 2 hole in the middle
    Polygon p = square(0, 0, 10);
    p.holes.push_back(square(4, 4, 2).outer);
    return p;
}

} // namespace

TEST(PolygonOps, AreaSubtractsHoles) {
    EXPECT_DOUBLE_EQ(area(square(0, 0, 10)), 100.0);
    EXPECT_DOUBLE_EQ(area(ring10()), 96.0);
    EXPECT_DOUBLE_EQ(signedArea(square(0, 0, 2).outer), 4.0);
}

TEST(PolygonOps, ContainsRespectsHolesAndBoundary) {
    const Polygon p = ring10();
    EXPECT_TRUE(contains(p, Vec2(1, 1)));
    EXPECT_FALSE(contains(p, Vec2(5, 5)));   // in the hole
    EXPECT_TRUE(contains(p, Vec2(4, 5)));    // on the hole's edge
    EXPECT_TRUE(contains(p, Vec2(0, 5)));    // on the outer edge
    EXPECT_FALSE(contains(p, Vec2(-0.1, 5)));
}

TEST(PolygonOps, Distances) {
    const Polygon p = ring10();
    EXPECT_DOUBLE_EQ(distanceToBoundary(p, Vec2(1, 5)), 1.0);
    EXPECT_DOUBLE_EQ(distanceToBoundary(p, Vec2(5, 5)), 1.0); // to the hole's edge
    EXPECT_DOUBLE_EQ(distanceTo(p, Vec2(1, 5)), 0.0);
    EXPECT_DOUBLE_EQ(distanceTo(p, Vec2(13, 14)), 5.0);
}

TEST(PolygonOps, BufferGrowsBySafetyMargin) {
    const auto b = buffer(square(0, 0, 10), 2.0, 16);
    ASSERT_EQ(b.size(), 1u);
    // A square grown by r has area s^2 + 4 s r + pi r^2 (arcs approximated by segments).
    EXPECT_NEAR(area(b), 100 + 80 + 3.14159 * 4, 0.2);
    EXPECT_TRUE(contains(b, Vec2(-1.9, 5)));
    EXPECT_FALSE(contains(b, Vec2(-2.1, 5)));
}

TEST(PolygonOps, DifferenceCutsNoFlyZones) {
    const auto d = difference(square(0, 0, 10), MultiPolygon{square(2, 2, 2), square(6, 6, 2)});
    EXPECT_NEAR(area(d), 92.0, 1e-9);
    EXPECT_FALSE(contains(d, Vec2(3, 3)));
}

TEST(PolygonOps, SegmentCrossesInterior) {
    const MultiPolygon nf{square(4, 4, 2)};
    EXPECT_TRUE(segmentCrossesInterior(nf, Vec2(0, 5), Vec2(10, 5)));
    EXPECT_FALSE(segmentCrossesInterior(nf, Vec2(0, 3), Vec2(10, 3)));
    EXPECT_FALSE(segmentCrossesInterior(nf, Vec2(0, 4), Vec2(10, 4))); // grazing an edge
    EXPECT_TRUE(segmentCrossesInterior(nf, Vec2(5, 5), Vec2(5, 5.5))); // wholly inside
}

TEST(PolygonOps, ValidityReportsSelfIntersection) {
    Polygon bowtie{{Vec2(0, 0), Vec2(10, 10), Vec2(10, 0), Vec2(0, 10)}, {}};
    std::string why;
    EXPECT_FALSE(isValid(bowtie, &why));
    EXPECT_TRUE(isValid(square(0, 0, 1)));
}
