// The one flight-time model: every choice the planners make by time and every time shown uses it.
#pragma once

#include "core/geo/types.h"

#include <vector>

namespace pf::plan {

// Horizontal acceleration assumed when the catalog or the mission gives none: ArduCopter's default
// waypoint acceleration (WPNAV_ACCEL, 250 cm/s^2), on the cautious side of PX4's (MPC_ACC_HOR, 3 m/s^2).
constexpr double kDefaultAccelerationMps2 = 2.5;

// A heading change of at most this many degrees is a straight line, not a turn: not counted in
// FlightTime::turns and costing nothing (a lane's photo points lie on one line up to rounding).
constexpr double kTurnThresholdDeg = 1.0;

// ---- The multirotor's corners -------------------------------------------------------------------
// Autopilots fly through a waypoint unless told to stop there: ArduCopter (4.1 and later, S-curve
// navigation) blends the braking of one leg into the next whenever the next navigation command is a
// waypoint and the current one has no delay (ModeAuto::set_next_wp: "do not add next wp if current
// command has a delay meaning the vehicle will stop at the destination"); PX4 sets the next
// setpoint, and so flies through, only for a waypoint without hold time (MissionBlock: "vehicle
// will be paused on current waypoint, don't set next item" otherwise). So every corner is a choice
// the exports make, and the model counts what they choose (isStopCorner, one rule for both):
//  - a corner turning by more than kStopCornerDeg is a stop: the aircraft brakes to rest on the
//    waypoint, holds kStopHoldS, turns on the spot and accelerates again (a lane's U-turn, whose
//    two corners turn 90 degrees each; the photo at a lane's end is taken on the lane, not in a
//    curve). Exports: NAV_WAYPOINT param1 (hold) = kStopHoldS; Litchi a "stay" action of that time,
//    curve size 0; DJI WPML waypointTurnMode toPointAndStopWithDiscontinuityCurvature (plus a hover
//    of the hold time to match this model).
//  - a shallower corner is flown through on a curve that leaves the legs kCornerCutM before the
//    waypoint (PX4 computes its corner speed from exactly this geometry, its acceptance radius
//    being the distance: TrajMath computeMaxSpeedInWaypoint, v = sqrt(a d tan(alpha / 2)) with
//    alpha the angle between the legs; ArduCopter's WPNAV_RADIUS default is 2 m). Exports: hold 0,
//    NAV_WAYPOINT param2 (acceptance radius, used by PX4) = kCornerCutM; Litchi curve size
//    kCornerCutM; WPML toPointAndPassWithContinuityCurvature.
// The hold exists because ArduCopter keeps the delay in whole seconds: 1 s is the shortest delay
// that makes it stop.
constexpr double kStopCornerDeg = 60.0;
constexpr double kStopHoldS = 1.0;
constexpr double kCornerCutM = 2.0;

// How the aircraft flies a path.
enum class FlightDynamics {
    Multirotor, // stops at sharp corners, slows in shallow ones (see above)
    FixedWing,  // a plane, or a VTOL aircraft in cruise: every metre at the cruise speed
};

// The time model. Multirotor: paper 004's completion time T = S / V + sum(theta) / omega, with what
// a multirotor loses at corners. It flies straight legs at the cruise speed V; at a stop corner it
// brakes from V to rest over V^2 / (2a), which takes V / a where cruising would take V / (2a),
// holds, rotates at omega and speeds up again: V / a + hold + theta / omega more than flying
// through. At a fly-through corner it slows to the corner speed v_c and speeds up again: (V -
// v_c)^2 / (a V) more (braking V -> v_c over (V^2 - v_c^2) / (2a) takes (V - v_c) / a, cruising it
// (V^2 - v_c^2) / (2aV)); v_c is the speed on the corner's circle, tangent to both legs kCornerCutM
// from the waypoint (radius r = d / tan(theta / 2) for a heading change theta), at lateral
// acceleration a and yaw rate omega: v_c = min(V, sqrt(a r), omega r); the yaw turns during the
// curve. The flight starts and ends at rest: one V / a more. Photos are taken on the fly
// (photoDwellS 0) unless the aircraft hovers for each one. The turn angle is the change of
// direction between consecutive legs (a U-turn is 180 degrees). FixedWing: the flown path already
// holds the arcs (route/turns.h samples them): time = length / V; a leg that climbs or descends
// flies its 3D length at V, or takes dz / climb (or sink) rate when that is longer (the plane
// cannot climb faster, so it flies the leg slower over the ground). A vertex costs nothing, there
// is no stop, and the flight has no rest-to-rest cost (take-off and landing are the exports'
// items). (Members in the order aggregate initialisers elsewhere rely on: speed, turn rate,
// acceleration first.)
struct FlightTimeModel {
    double speedMps = 10.0;     // V, > 0
    double turnRateDegS = 90.0; // omega, > 0 (multirotor)
    double accelerationMps2 =
        kDefaultAccelerationMps2;    // a, > 0; infinite: no braking cost (multirotor)
    double photoDwellS = 0.0;        // per photo point (the caller counts them)
    double stopHoldS = kStopHoldS;   // the hold at each stop corner (multirotor)
    double cornerCutM = kCornerCutM; // where a fly-through corner's curve begins
    FlightDynamics dynamics = FlightDynamics::Multirotor;
    double climbRateMps = 5.0; // fixed-wing: vertical speed climbing, > 0
    double sinkRateMps = 5.0;  // fixed-wing: vertical speed descending, > 0
    bool fixedWing() const { return dynamics == FlightDynamics::FixedWing; }
    // V / a: the time one stop and restart costs over flying through, hold and rotation aside (0
    // for a fixed-wing). The start and end at rest cost this once per flight.
    double stopCostS() const;
};

struct FlightTime {
    double totalS = 0.0; // straightS + cornerS + turnS + stopS (+ dwell, when the caller adds it)
    double straightS = 0.0;    // S / V (a fixed-wing: with the climbs and descents)
    double cornerS = 0.0;      // slowing down in the corners flown through
    double turnS = 0.0;        // rotating at the stop corners: sum of their theta / omega
    double stopS = 0.0;        // stops x (V / a + hold) + V / a for a flight with at least one leg
    double lengthM = 0.0;      // S
    double turnAngleDeg = 0.0; // all heading changes
    int turns = 0; // heading changes above kTurnThresholdDeg (a fixed-wing: each run of them, one
                   // arc sampled as many vertices, counts once)
    int stops = 0;             // stop corners (isStopCorner)
};

// The direction change at b of the legs a->b and b->c, in degrees [0, 180]; 0 when a leg is empty.
double turnAngleDeg(const geo::Vec2& a, const geo::Vec2& b, const geo::Vec2& c);

// Whether a multirotor stops at a corner turning by `thetaDeg` (above kStopCornerDeg); never for a
// fixed-wing. The one rule the model and every export share.
bool isStopCorner(double thetaDeg, const FlightTimeModel& model);
// The speed a multirotor keeps through a corner of `thetaDeg` (0 at a stop corner, V up to
// kTurnThresholdDeg, where the legs are one straight line); a fixed-wing keeps its cruise speed.
double cornerSpeedMps(double thetaDeg, const FlightTimeModel& model);
// The time one vertex of a flight costs beyond flying its legs at V: a stop corner theta / omega +
// V / a + hold, a fly-through corner (V - v_c)^2 / (a V), nothing up to kTurnThresholdDeg; 0 for a
// fixed-wing.
double turnCostS(double thetaDeg, const FlightTimeModel& model);

// Time to fly the polyline (a multirotor from rest to rest; legs of zero length are skipped when
// finding corners).
FlightTime flightTime(const std::vector<geo::Vec2>& polyline, const FlightTimeModel& model);
// The same for a flight that climbs and descends (terrain following): `altitudesM[i]` is the
// altitude at polyline[i]. A multirotor flies each leg's 3D length sqrt(d^2 + dz^2) at the cruise
// speed (its climb rate is rarely the limit at survey slopes); a fixed-wing takes the longer of
// that and dz / its climb or sink rate. Corners are the changes of horizontal direction as above.
// Without altitudes (an empty or short vector) it is the 2D time.
FlightTime flightTime(const std::vector<geo::Vec2>& polyline, const std::vector<double>& altitudesM,
                      const FlightTimeModel& model);

// Incremental form for planners that build a route leg by leg: add points in flight order.
class FlightTimeAccumulator {
public:
    explicit FlightTimeAccumulator(const FlightTimeModel& model) : m_model(model) {}
    void add(const geo::Vec2& p);
    // A point at an altitude: the leg to it climbs or descends.
    void add(const geo::Vec2& p, double altitudeM);
    FlightTime result() const;

private:
    FlightTimeModel m_model;
    FlightTime m_t;
    int m_points = 0;
    geo::Vec2 m_last{0, 0};
    double m_lastZ = 0.0;
    geo::Vec2 m_prevDir{0, 0}; // unit direction of the last non-empty leg, zero before it
    bool m_turning = false;    // the last vertex turned by more than kTurnThresholdDeg
};

} // namespace pf::plan
