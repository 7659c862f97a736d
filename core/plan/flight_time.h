// The one flight-time model: every choice the planners make by time and every time shown uses it.
#pragma once

#include "core/geo/types.h"

#include <vector>

namespace pf::plan {

// Horizontal acceleration assumed when the catalog or the mission gives none: ArduCopter's default
// waypoint acceleration (WPNAV_ACCEL, 250 cm/s^2), on the cautious side of PX4's (MPC_ACC_HOR, 3 m/s^2).
constexpr double kDefaultAccelerationMps2 = 2.5;

// A heading change of at most this many degrees is flown through without slowing down (a lane's
// photo points lie on one straight line up to rounding); a larger one is a turn.
constexpr double kTurnThresholdDeg = 1.0;

// Paper 004's completion time T = S / V + sum(theta) / omega, extended with what a multirotor loses
// stopping and starting: it flies straight legs at the cruise speed V, stops at every turn, rotates
// there at omega and accelerates again at a. Braking from V to rest over V^2 / (2a) takes V / a, where
// cruising that distance would take V / (2a); the same again when it speeds up: each stop costs
// V / a more than flying through. The flight starts and ends at rest: one more V / a in all.
// Choices: the turn angle is the change of direction between consecutive legs (a U-turn is 180);
// heading changes up to kTurnThresholdDeg are not turns; photos are taken on the fly (photoDwellS 0)
// unless the aircraft is set to hover for each one.
struct FlightTimeModel {
    double speedMps = 10.0;                           // V, > 0
    double turnRateDegS = 90.0;                       // omega, > 0
    double accelerationMps2 = kDefaultAccelerationMps2; // a, > 0; infinite: no stop cost
    double photoDwellS = 0.0;                         // per photo point (the caller counts them)
    // V / a: the time one stop and restart costs over flying through.
    double stopCostS() const;
};

struct FlightTime {
    double totalS = 0.0;     // straightS + turnS + stopS (+ dwell, when the caller adds it)
    double straightS = 0.0;  // S / V
    double turnS = 0.0;      // sum(theta) / omega
    double stopS = 0.0;      // (turns + 1) * V / a for a flight with at least one leg
    double lengthM = 0.0;    // S
    double turnAngleDeg = 0.0;
    int turns = 0;           // heading changes above kTurnThresholdDeg
};

// The direction change at b of the legs a->b and b->c, in degrees [0, 180]; 0 when a leg is empty.
double turnAngleDeg(const geo::Vec2& a, const geo::Vec2& b, const geo::Vec2& c);

// Time to fly the polyline from rest to rest (legs of zero length are skipped when finding turns).
FlightTime flightTime(const std::vector<geo::Vec2>& polyline, const FlightTimeModel& model);
// The same for a flight that climbs and descends (terrain following): `altitudesM[i]` is the
// altitude at polyline[i]; each leg counts its 3D length sqrt(d^2 + dz^2) at the cruise speed (a
// multirotor's climb rate is rarely the limit at survey slopes), turns are the changes of horizontal
// direction as above. Without altitudes (an empty or short vector) it is the 2D time.
FlightTime flightTime(const std::vector<geo::Vec2>& polyline, const std::vector<double>& altitudesM,
                      const FlightTimeModel& model);

// The cost of one vertex of a flight: theta / omega plus a stop when theta is a turn.
double turnCostS(double thetaDeg, const FlightTimeModel& model);

// Incremental form for planners that build a route leg by leg: add points in flight order.
class FlightTimeAccumulator {
public:
    explicit FlightTimeAccumulator(const FlightTimeModel& model) : m_model(model) {}
    void add(const geo::Vec2& p);
    // A point at an altitude: the leg to it counts its 3D length.
    void add(const geo::Vec2& p, double altitudeM);
    FlightTime result() const;

private:
    FlightTimeModel m_model;
    FlightTime m_t;
    int m_points = 0;
    geo::Vec2 m_last{0, 0};
    double m_lastZ = 0.0;
    geo::Vec2 m_prevDir{0, 0}; // unit direction of the last non-empty leg, zero before it
};

} // namespace pf::plan
