#include "core/fleet/capability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace pf;
using namespace pf::fleet;

namespace {
// Without the stop at each turn (infinite acceleration) unless `accel` is given.
Capability make(const std::string& name, double across, double speed, double turn,
                double accel = std::numeric_limits<double>::infinity()) {
    Capability c;
    c.name = name;
    c.footprint.acrossM = across;
    c.footprint.alongM = across * 0.5;
    c.time.speedMps = speed;
    c.time.turnRateDegS = turn;
    c.time.accelerationMps2 = accel;
    return c;
}
} // namespace

TEST(Capability, AreaRateMatchesHandComputedValue) {
    // 20 m tracks spacing, 10 m/s, 90 deg/s, 100 m tracks: 2000 m^2 in 10 s + 2 s + 2 s.
    EXPECT_NEAR(areaRateM2PerS(make("a", 20, 10, 90), 100.0), 2000.0 / 14.0, 1e-12);
    EXPECT_EQ(areaRateM2PerS(make("a", 0, 10, 90), 100.0), 0.0);
}

TEST(Capability, AreaRateCountsTheStopsOfEachUTurn) {
    // As above, plus two stops of V / a = 10 / 2.5 = 4 s at the two corners of each U-turn.
    EXPECT_NEAR(areaRateM2PerS(make("a", 20, 10, 90, 2.5), 100.0), 2000.0 / 22.0, 1e-12);
}

TEST(Capability, TurnsDiscountFastNarrowAircraftOnSmallAreas) {
    // Same across x speed product; the fast one loses more to turns on short tracks.
    const auto wideSlow = make("wide", 40, 5, 45);
    const auto narrowFast = make("narrow", 10, 20, 45);
    EXPECT_GT(areaRateM2PerS(wideSlow, 50), areaRateM2PerS(narrowFast, 50));
    // On very long tracks the turns no longer matter: shares tend to across x speed.
    EXPECT_NEAR(areaRateM2PerS(wideSlow, 1e7) / areaRateM2PerS(narrowFast, 1e7), 1.0, 1e-3);
}

TEST(Capability, SharesSumToOneAndFollowTheRate) {
    auto s = capabilityShares({make("a", 20, 10, 90), make("b", 40, 10, 90)}, 10000.0);
    ASSERT_TRUE(s.ok());
    EXPECT_NEAR((*s)[0] + (*s)[1], 1.0, 1e-12);
    const double ra = areaRateM2PerS(make("a", 20, 10, 90), 100.0), rb = areaRateM2PerS(make("b", 40, 10, 90), 100.0);
    EXPECT_NEAR((*s)[1], rb / (ra + rb), 1e-12);
}

TEST(Capability, BadFiguresNameTheAircraft) {
    auto e = capabilityShares({make("Falcon", 20, 0, 90)}, 100.0);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().message, "Falcon has a cruise speed that is not positive.");
    auto f = capabilityShares({make("Kite", 0, 5, 90)}, 100.0);
    ASSERT_FALSE(f.ok());
    EXPECT_EQ(f.error().message,
              "Kite has no usable camera footprint (check altitude and overlap).");
    auto t = capabilityShares({make("Hex", 10, 5, 0)}, 100.0);
    ASSERT_FALSE(t.ok());
    EXPECT_EQ(t.error().message, "Hex has a turn rate that is not positive.");
    auto none = capabilityShares({}, 100.0);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().message, "No aircraft to share the area between.");
}

TEST(BaseCellSize, IsTheSmallestAircraftCellAndNeverLarger) {
    sensor::EffectiveFootprint a{24.0, 12.0, {}}, b{36.0, 40.0, {}};
    EXPECT_DOUBLE_EQ(aircraftCellSize(a), 24.0);
    EXPECT_DOUBLE_EQ(aircraftCellSize(b), 40.0);
    auto s = baseCellSize({aircraftCellSize(a), aircraftCellSize(b)}, 90'000.0);
    ASSERT_TRUE(s.ok());
    EXPECT_DOUBLE_EQ(*s, 24.0);
    for (double x : {24.0, 40.0, 17.5})
        EXPECT_LE(*baseCellSize({24.0, 40.0, x}, 90'000.0), x);
}

TEST(BaseCellSize, GrowsToStayWithinTheCellBudget) {
    auto s = baseCellSize({1.0, 5.0}, 1e6, 10'000);
    ASSERT_TRUE(s.ok());
    EXPECT_NEAR(*s, 10.0, 1e-12); // 1 km^2 in 10,000 cells of 10 m
    auto bad = baseCellSize({10.0, -1.0}, 100.0);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message, "An aircraft cell size is not a positive number of metres.");
    auto none = baseCellSize({}, 100.0);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().message, "No aircraft cell sizes to derive the base grid from.");
}
