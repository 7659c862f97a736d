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
