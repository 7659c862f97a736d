#include "core/geo/no_fly_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pf::geo;

// The safety tests skip far zones and stop early; they must answer exactly as the clearances say.
TEST(NoFlyField, SafetyTestsAgreeWithTheClearances) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> pos(0, 300), r(5, 30);
    std::vector<Polygon> zones;
    for (int k = 0; k < 10; ++k) {
        const Vec2 c(pos(rng), pos(rng));
        Polygon z;
        const int n = 3 + k % 6;
        for (int i = 0; i < n; ++i)
            z.outer.push_back(c + r(rng) * Vec2(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n)));
        if (k == 3) // a zone with a courtyard
            z.holes.push_back({c + Vec2(-2, -2), c + Vec2(-2, 2), c + Vec2(2, 2), c + Vec2(2, -2)});
        zones.push_back(z);
    }
    for (double margin : {0.0, 5.0, 12.0}) {
        const NoFlyField f(zones, margin);
        for (int k = 0; k < 3000; ++k) {
            const Vec2 a(pos(rng), pos(rng));
            const Vec2 b = k % 3 ? Vec2(pos(rng), pos(rng)) : a + Vec2(r(rng), r(rng));
            ASSERT_EQ(f.pointIsSafe(a), f.isSafeClearance(f.clearance(a))) << margin << " at " << a.transpose();
            ASSERT_EQ(f.segmentIsSafe(a, b), f.isSafeClearance(f.clearance(a, b)))
                << margin << " from " << a.transpose() << " to " << b.transpose();
        }
    }
}

// The segment test skips an edge whose ends lie beyond the margin on one side of the segment's line;
// near that limit (segments tangent to the margin, passing a zone's corner, ending beside a zone, of
// zero length, far from the origin) it must still answer as the clearance says.
TEST(NoFlyField, SegmentTestAgreesWithTheClearanceAtTheMargin) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0, 1), ang(0, 2 * M_PI);
    for (const Vec2& origin : {Vec2(0, 0), Vec2(3.0e6, -2.0e6)}) {
        std::vector<Polygon> zones;
        Polygon square;
        square.outer = {Vec2(0, 0), Vec2(20, 0), Vec2(20, 20), Vec2(0, 20)};
        Polygon round;
        for (int i = 0; i < 24; ++i)
            round.outer.push_back(Vec2(60, 10) + 12.0 * Vec2(std::cos(M_PI * i / 12), std::sin(M_PI * i / 12)));
        for (Polygon* z : {&square, &round}) {
            for (auto& p : z->outer)
                p += origin;
            zones.push_back(*z);
        }
        for (double margin : {0.0, 5.0}) {
            const NoFlyField f(zones, margin);
            const double need = std::max(0.0, f.minClearance());
            for (int k = 0; k < 20000; ++k) {
                // A point at the margin's distance (give or take up to 1 mm, or exactly) from a
                // random vertex or edge point, and a segment through it in a random direction, or
                // along the edge.
                const Polygon& z = zones[static_cast<std::size_t>(k % 2)];
                const std::size_t i = static_cast<std::size_t>(k) % z.outer.size();
                const Vec2 c = z.outer[i], d = z.outer[(i + 1) % z.outer.size()];
                const Vec2 e = (d - c).normalized(), n(e.y(), -e.x()); // n: outward for a CCW ring
                // (Exactly on a zone's boundary, margin 0, the two differ by design: not asked.)
                const double off = k % 5 == 0 && margin > 0 ? 0.0 : (unit(rng) - 0.5) * (k % 3 ? 2e-3 : 2e-7);
                const Vec2 at = c + unit(rng) * (d - c) + (need + off) * n;
                const double dir = k % 4 == 0 ? std::atan2(e.y(), e.x()) : ang(rng);
                const double len = k % 7 == 0 ? 0.0 : 60.0 * unit(rng);
                const Vec2 a = at - len * unit(rng) * Vec2(std::cos(dir), std::sin(dir));
                const Vec2 b = a + len * Vec2(std::cos(dir), std::sin(dir));
                ASSERT_EQ(f.segmentIsSafe(a, b), f.isSafeClearance(f.clearance(a, b)))
                    << margin << " from " << (a - origin).transpose() << " to " << (b - origin).transpose();
            }
        }
    }
}

// Zones already grown by their margin (the grid's buffered zones): safe means not inside; the
// boundary counts as outside, for points to a micrometre and for segments that run along it.
TEST(NoFlyField, GrownZonesCountTheirBoundaryAsOutside) {
    Polygon square;
    square.outer = {Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(0, 10)};
    Polygon courtyard = square;
    for (auto& p : courtyard.outer)
        p += Vec2(30, 0);
    courtyard.holes.push_back({Vec2(33, 3), Vec2(33, 7), Vec2(37, 7), Vec2(37, 3)});
    const NoFlyField f = NoFlyField::ofGrownZones({square, courtyard});
    EXPECT_EQ(f.marginM(), 0.0);
    EXPECT_FALSE(f.pointIsSafe(Vec2(5, 5)));
    EXPECT_FALSE(f.pointIsSafe(Vec2(5, 9.99)));
    EXPECT_TRUE(f.pointIsSafe(Vec2(5, 10)));         // on the boundary
    EXPECT_TRUE(f.pointIsSafe(Vec2(5, 10 - 5e-7)));  // within a micrometre of it
    EXPECT_FALSE(f.pointIsSafe(Vec2(5, 10 - 2e-6))); // deeper
    EXPECT_TRUE(f.pointIsSafe(Vec2(10, 10)));        // a corner
    EXPECT_TRUE(f.pointIsSafe(Vec2(35, 5)));         // in the courtyard
    EXPECT_TRUE(f.pointIsSafe(Vec2(20, 5)));
    EXPECT_TRUE(f.segmentIsSafe(Vec2(-5, 10), Vec2(15, 10))); // along an edge
    EXPECT_TRUE(f.segmentIsSafe(Vec2(0, 20), Vec2(20, 0)));   // touching a corner
    EXPECT_FALSE(f.segmentIsSafe(Vec2(-5, 5), Vec2(15, 5)));  // across
    EXPECT_FALSE(f.segmentIsSafe(Vec2(5, 5), Vec2(5, 6)));    // wholly inside
    EXPECT_FALSE(f.segmentIsSafe(Vec2(20, 5), Vec2(35, 5)));  // into the courtyard through the zone
    EXPECT_TRUE(f.segmentIsSafe(Vec2(34, 4), Vec2(36, 6)));   // within the courtyard
}
