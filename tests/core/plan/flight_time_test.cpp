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

FlightTimeModel plane(double v, double climb, double sink) {
    FlightTimeModel m;
    m.dynamics = FlightDynamics::FixedWing;
    m.speedMps = v;
    m.climbRateMps = climb;
    m.sinkRateMps = sink;
    return m;
}

// 100 m east, then 100 m at `deg` degrees to the left of east.
std::vector<Vec2> corner(double deg) {
    const double a = deg * M_PI / 180;
    return {Vec2(0, 0), Vec2(100, 0), Vec2(100 + 100 * std::cos(a), 100 * std::sin(a))};
}
} // namespace

// By hand: a 100 m leg, a right angle, 50 m, a U-turn, 50 m back. V 10 m/s, omega 60 deg/s, a 2
// m/s^2, hold 1 s: both corners turn more than 60 degrees, so both are stops. S / V = 20 s,
// rotating at them 270 deg / 60 = 4.5 s, stops 2 x (V / a + hold) = 2 x 6 = 12 s plus rest to rest
// V / a = 5 s.
TEST(FlightTime, HandComputedStops) {
    const std::vector<Vec2> p{Vec2(0, 0), Vec2(100, 0), Vec2(100, 50), Vec2(100, 0)};
    const FlightTime t = flightTime(p, model(10, 60, 2));
    EXPECT_DOUBLE_EQ(t.lengthM, 200.0);
    EXPECT_EQ(t.turns, 2);
    EXPECT_EQ(t.stops, 2);
    EXPECT_NEAR(t.turnAngleDeg, 270.0, 1e-9);
    EXPECT_NEAR(t.straightS, 20.0, 1e-12);
    EXPECT_NEAR(t.turnS, 4.5, 1e-9);
    EXPECT_NEAR(t.cornerS, 0.0, 1e-12);
    EXPECT_NEAR(t.stopS, 17.0, 1e-12);
    EXPECT_NEAR(t.totalS, 41.5, 1e-9);
}

// By hand, a corner flown through: 30 degrees. The curve leaves the legs 2 m before the waypoint:
// radius r = 2 / tan 15 = 2 / (2 - sqrt 3) = 4 + 2 sqrt 3 = 7.4641 m. At a = 2 m/s^2 the lateral
// limit is sqrt(a r) = sqrt(14.9282) = 3.8637 m/s; the yaw at 60 deg/s allows (pi / 3) r = 7.8164
// m/s: v_c = 3.8637. Slowing from 10 m/s and back costs (10 - 3.8637)^2 / (2 x 10) = 1.8827 s. Path
// 200 m: 20 s, rest to rest 5 s.
TEST(FlightTime, HandComputedFlyThroughCorner) {
    const FlightTimeModel m = model(10, 60, 2);
    const double r = 4 + 2 * std::sqrt(3.0), vc = std::sqrt(2 * r);
    EXPECT_NEAR(r, 7.46410, 1e-5);
    EXPECT_NEAR(cornerSpeedMps(30, m), vc, 1e-12);
    EXPECT_NEAR(turnCostS(30, m), (10 - vc) * (10 - vc) / 20, 1e-12);
    EXPECT_NEAR(turnCostS(30, m), 1.88270, 1e-5);
    EXPECT_FALSE(isStopCorner(30, m));
    const FlightTime t = flightTime(corner(30), m);
    EXPECT_EQ(t.turns, 1);
    EXPECT_EQ(t.stops, 0);
    EXPECT_NEAR(t.cornerS, 1.88270, 1e-5);
    EXPECT_NEAR(t.turnS, 0.0, 1e-12);
    EXPECT_NEAR(t.stopS, 5.0, 1e-12);
    EXPECT_NEAR(t.totalS, 20 + 1.88270 + 5, 1e-5);
    // A slow yaw limits the corner speed instead: at 20 deg/s, (pi / 9) r = 2.6055 m/s, so (10 -
    // 2.6055)^2 / 20 = 2.7340 s.
    EXPECT_NEAR(cornerSpeedMps(30, model(10, 20, 2)), M_PI / 9 * r, 1e-12);
    EXPECT_NEAR(turnCostS(30, model(10, 20, 2)), 2.73396, 1e-5);
}

// The stop rule: up to kStopCornerDeg a corner is flown through, beyond it the aircraft stops; the
// cost grows with the angle on each side, and a shallow kink (below a few degrees at 10 m/s, where
// the corner speed reaches V) costs nothing.
TEST(FlightTime, StopRuleAndMonotoneCost) {
    const FlightTimeModel m = model(10, 60, 2);
    EXPECT_FALSE(isStopCorner(kStopCornerDeg, m));
    EXPECT_TRUE(isStopCorner(kStopCornerDeg + 0.1, m));
    EXPECT_EQ(cornerSpeedMps(kStopCornerDeg + 0.1, m), 0.0);
    EXPECT_NEAR(turnCostS(90, m), 1.5 + 5.0 + kStopHoldS, 1e-12); // theta / omega + V / a + hold
    EXPECT_EQ(turnCostS(0.5, m), 0.0);
    EXPECT_EQ(cornerSpeedMps(0.5, m), 10.0);
    double last = 0.0;
    for (double deg = 1; deg <= kStopCornerDeg; deg += 1) {
        EXPECT_GE(turnCostS(deg, m), last) << deg;
        last = turnCostS(deg, m);
    }
    EXPECT_LT(last, turnCostS(kStopCornerDeg + 0.1,
                              m)); // a stop costs more than any corner flown through
    // Heading changes below kTurnThresholdDeg are not counted as turns.
    EXPECT_EQ(flightTime(corner(kTurnThresholdDeg / 2), m).turns, 0);
    EXPECT_EQ(flightTime(corner(kTurnThresholdDeg * 2), m).turns, 1);
}

// Points on one straight line are flown through: no turn, no stop but the one from rest to rest; a
// repeated point does not break the line.
TEST(FlightTime, CollinearPointsAndRepeatsAreNotTurns) {
    const std::vector<Vec2> p{Vec2(0, 0), Vec2(10, 0), Vec2(10, 0), Vec2(20, 1e-6), Vec2(30, 0)};
    const FlightTime t = flightTime(p, model(10, 60, 2));
    EXPECT_EQ(t.turns, 0);
    EXPECT_EQ(t.stops, 0);
    EXPECT_NEAR(t.stopS, 5.0, 1e-12);
    EXPECT_NEAR(t.totalS, 3.0 + 5.0, 1e-9);
}

// Paper 004's model is the special case without braking (infinite acceleration) and without hold:
// S / V + theta / omega. An empty or one-point flight takes no time.
TEST(FlightTime, PaperModelWithoutStopsAndDegenerateFlights) {
    const auto inf = std::numeric_limits<double>::infinity();
    FlightTimeModel m = model(10, 90, inf);
    m.stopHoldS = 0.0;
    const FlightTime t = flightTime({Vec2(0, 0), Vec2(100, 0), Vec2(100, 100)}, m);
    EXPECT_NEAR(t.totalS, 10 + 10 + 1, 1e-9);
    EXPECT_NEAR(flightTime(corner(30), m).totalS, 20.0,
                1e-9); // a corner flown through costs nothing
    EXPECT_EQ(flightTime({}, model(10, 90, 2)).totalS, 0.0);
    EXPECT_EQ(flightTime({Vec2(3, 4)}, model(10, 90, 2)).totalS, 0.0);
    EXPECT_EQ(flightTime({Vec2(3, 4), Vec2(3, 4)}, model(10, 90, 2)).totalS, 0.0);
}

// A plane: length / V, corners free (its arcs are in the path), no stops. By hand at 20 m/s: the
// same U-turn path as above is 200 m = 10 s. A leg of 100 m climbing 50 m flies 111.80 m (5.59 s)
// but climbs at 2 m/s only: 25 s. A leg of 100 m descending 10 m at 5 m/s sink: its 100.50 m at
// V, 5.02 s, is the longer.
TEST(FlightTime, FixedWingByHand) {
    const FlightTimeModel m = plane(20, 2, 5);
    const std::vector<Vec2> p{Vec2(0, 0), Vec2(100, 0), Vec2(100, 50), Vec2(100, 0)};
    const FlightTime t = flightTime(p, m);
    EXPECT_NEAR(t.totalS, 10.0, 1e-12);
    EXPECT_EQ(t.stops, 0);
    EXPECT_EQ(t.stopS, 0.0);
    EXPECT_EQ(turnCostS(180, m), 0.0);
    EXPECT_FALSE(isStopCorner(180, m));
    EXPECT_EQ(cornerSpeedMps(120, m), 20.0);
    const FlightTime climb = flightTime({Vec2(0, 0), Vec2(100, 0)}, {0.0, 50.0}, m);
    EXPECT_NEAR(climb.totalS, 25.0, 1e-9);
    EXPECT_NEAR(climb.lengthM, std::hypot(100.0, 50.0), 1e-9);
    const FlightTime descent = flightTime({Vec2(0, 0), Vec2(100, 0)}, {50.0, 40.0}, m);
    EXPECT_NEAR(descent.totalS, std::hypot(100.0, 10.0) / 20.0, 1e-9);
    // A multirotor flies the climb's 3D length at V: 111.80 / 10 + rest to rest 5 s.
    EXPECT_NEAR(flightTime({Vec2(0, 0), Vec2(100, 0)}, {0.0, 50.0}, model(10, 60, 2)).totalS,
                std::hypot(100.0, 50.0) / 10.0 + 5.0, 1e-9);
}

// A plane's U-turn is one arc sampled as many vertices: one turn, two with a straight between two
// arcs; a multirotor flying the same polyline turns at each vertex.
TEST(FlightTime, APlanesArcIsOneTurn) {
    std::vector<Vec2> p{Vec2(0, 0), Vec2(100, 0)};
    for (int a = 20; a <= 180; a += 20) // a half circle of radius 20 m, to the left
        p.emplace_back(100 + 20 * std::sin(a * M_PI / 180), 20 - 20 * std::cos(a * M_PI / 180));
    p.emplace_back(50, 40); // the lane back: its photo waypoints are straight ahead
    p.emplace_back(0, 40);
    EXPECT_EQ(flightTime(p, plane(15, 5, 5)).turns, 1);
    EXPECT_EQ(flightTime(p, model(10, 60, 2)).turns, 10);
    p.emplace_back(-20, 60); // a second corner at the lane's end
    EXPECT_EQ(flightTime(p, plane(15, 5, 5)).turns, 2);
}

// The accumulator and the polyline function agree.
TEST(FlightTime, AccumulatorMatchesPolyline) {
    const std::vector<Vec2> p{Vec2(0, 0), Vec2(50, 0), Vec2(50, 30), Vec2(0, 30), Vec2(0, 60), Vec2(80, 75)};
    FlightTimeAccumulator acc(model(8, 45, 3));
    for (const auto& q : p)
        acc.add(q);
    EXPECT_NEAR(acc.result().totalS, flightTime(p, model(8, 45, 3)).totalS, 1e-12);
    EXPECT_EQ(acc.result().turns, 4);
    EXPECT_EQ(acc.result().stops, 4); // three right angles and a corner of 79 degrees
}
