#include "core/plan/flight_time.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace pf;
using namespace pf::plan;
using geo::Vec2;

namespace {
FlightTimeModel model(double v, double w, double a) {
    FlightTimeModel m;
    m.speedMps = v;
    m.turnRateDegS = w;
    m.accelerationMps2 = a;
    return m;
}
} // namespace

// By hand: a 100 m leg, a right angle, 50 m, a U-turn, 50 m back. V 10 m/s, omega 60 deg/s, a 2 m/s^2:
// S / V = 20 s, turns 270 deg / 60 = 4.5 s, stops (2 turns + rest to rest) x V / a = 3 x 5 s = 15 s.
TEST(FlightTime, HandComputedSmallPath) {
    const std::vector<Vec2> p{Vec2(0, 0), Vec2(100, 0), Vec2(100, 50), Vec2(100, 0)};
    const FlightTime t = flightTime(p, model(10, 60, 2));
    EXPECT_DOUBLE_EQ(t.lengthM, 200.0);
    EXPECT_EQ(t.turns, 2);
    EXPECT_NEAR(t.turnAngleDeg, 270.0, 1e-9);
    EXPECT_NEAR(t.straightS, 20.0, 1e-12);
    EXPECT_NEAR(t.turnS, 4.5, 1e-9);
    EXPECT_NEAR(t.stopS, 15.0, 1e-12);
    EXPECT_NEAR(t.totalS, 39.5, 1e-9);
}

// Points on one straight line are flown through: no turn, no stop but the one from rest to rest; a
// repeated point does not break the line.
TEST(FlightTime, CollinearPointsAndRepeatsAreNotTurns) {
    const std::vector<Vec2> p{Vec2(0, 0), Vec2(10, 0), Vec2(10, 0), Vec2(20, 1e-6), Vec2(30, 0)};
    const FlightTime t = flightTime(p, model(10, 60, 2));
    EXPECT_EQ(t.turns, 0);
    EXPECT_NEAR(t.stopS, 5.0, 1e-12);
    EXPECT_NEAR(t.totalS, 3.0 + t.turnAngleDeg / 60 + 5.0, 1e-9);
}

// A heading change above the threshold is a turn with its stop; one below it is flown through.
TEST(FlightTime, ThresholdSeparatesKinksFromTurns) {
    const double small = (kTurnThresholdDeg / 2) * M_PI / 180, big = (kTurnThresholdDeg * 2) * M_PI / 180;
    const auto path = [](double a) {
        return std::vector<Vec2>{Vec2(0, 0), Vec2(100, 0), Vec2(100 + 100 * std::cos(a), 100 * std::sin(a))};
    };
    EXPECT_EQ(flightTime(path(small), model(10, 60, 2)).turns, 0);
    EXPECT_EQ(flightTime(path(big), model(10, 60, 2)).turns, 1);
    EXPECT_NEAR(turnCostS(90, model(10, 60, 2)), 1.5 + 5.0, 1e-12);
    EXPECT_NEAR(turnCostS(kTurnThresholdDeg / 2, model(10, 60, 2)), kTurnThresholdDeg / 2 / 60, 1e-12);
}

// Paper 004's model is the special case without stops (infinite acceleration); an empty or one-point
// flight takes no time.
TEST(FlightTime, PaperModelWithoutStopsAndDegenerateFlights) {
    const auto inf = std::numeric_limits<double>::infinity();
    const FlightTime t = flightTime({Vec2(0, 0), Vec2(100, 0), Vec2(100, 100)}, model(10, 90, inf));
    EXPECT_NEAR(t.totalS, 10 + 10 + 1, 1e-9);
    EXPECT_EQ(flightTime({}, model(10, 90, 2)).totalS, 0.0);
    EXPECT_EQ(flightTime({Vec2(3, 4)}, model(10, 90, 2)).totalS, 0.0);
    EXPECT_EQ(flightTime({Vec2(3, 4), Vec2(3, 4)}, model(10, 90, 2)).totalS, 0.0);
}

// The accumulator and the polyline function agree.
TEST(FlightTime, AccumulatorMatchesPolyline) {
    const std::vector<Vec2> p{Vec2(0, 0), Vec2(50, 0), Vec2(50, 30), Vec2(0, 30), Vec2(0, 60), Vec2(80, 75)};
    FlightTimeAccumulator acc(model(8, 45, 3));
    for (const auto& q : p)
        acc.add(q);
    EXPECT_NEAR(acc.result().totalS, flightTime(p, model(8, 45, 3)).totalS, 1e-12);
    EXPECT_EQ(acc.result().turns, 4);
}
