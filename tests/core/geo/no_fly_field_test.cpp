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
