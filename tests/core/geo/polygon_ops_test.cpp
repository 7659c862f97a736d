#include "core/geo/polygon_ops.h"

#include "core/geo/even_odd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

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

// The slab index answers as insideEvenOdd does, bit for bit: staircases with hundreds of edges (as
// a subarea traced from grid cells), a hole, points on vertices' heights and far outside.
TEST(EvenOddIndex, AnswersAsInsideEvenOdd) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-5.0, 105.0);
    for (int shape = 0; shape < 6; ++shape) {
        Polygon poly;
        const int steps = 20 + 40 * shape;
        const double h = 100.0 / steps;
        for (int k = 0; k < steps; ++k) { // a staircase up the left side
            poly.outer.push_back(Vec2(3.0 * k * h / 10.0 + (k % 3), k * h));
            poly.outer.push_back(Vec2(3.0 * (k + 1) * h / 10.0 + (k % 3), k * h));
        }
        poly.outer.push_back(Vec2(100.0, 100.0));
        poly.outer.push_back(Vec2(100.0, 0.0));
        std::reverse(poly.outer.begin(), poly.outer.end());
        if (shape % 2 == 1)
            poly.holes.push_back({Vec2(60, 40), Vec2(60, 60), Vec2(80, 55), Vec2(75, 42)});
        const EvenOddIndex index(poly);
        int inside = 0, n = 0;
        for (int k = 0; k < 4000; ++k) {
            // Every fourth point at a vertex's height: an edge's end lies on the slab boundary
            // there.
            const double y = k % 4 == 0
                                 ? poly.outer[static_cast<std::size_t>(k) % poly.outer.size()].y()
                                 : u(rng);
            const Vec2 p(u(rng), y);
            const bool want = insideEvenOdd(poly, p);
            ASSERT_EQ(index.inside(p), want) << "shape " << shape << " point " << p.transpose();
            inside += want;
            ++n;
        }
        EXPECT_GT(inside, n / 5);
        EXPECT_LT(inside, n);
    }
    EXPECT_FALSE(EvenOddIndex().inside(Vec2(0, 0)));
}
