// A plane's survey route over given lanes: the order and direction of the lanes chosen so that the
// turns stay wide (the skip pattern where lanes lie closer than two turn radii), each lane entered
// after its run-in, and the lanes joined by curvature-bounded (Dubins) turns that keep the no-fly
// margins. The turns are sampled into waypoints, so that every export flies the arcs.
#pragma once

#include "core/geo/no_fly_field.h"
#include "core/plan/lanes/lane.h"
#include "core/route/turns.h"
#include "core/route/waypoint.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::route {

struct PlaneRouteOptions {
    double radiusM = 0.0;       // the minimum turn radius R, >= 0
    double runInM = 0.0;        // straight flight before a lane's first photo, >= 0
    double trackSpacingM = 0.0; // the lane spacing, > 0 (sets the skip patterns tried)
    // The planner's field of the no-fly zones with their margin (none: no zones).
    const geo::NoFlyField* field = nullptr;
    // Shortest safe paths round the zones at a larger margin (the field's plus about a turn
    // radius): a turn that no Dubins word flies safely follows one, turning at its corners.
    // Optional.
    const geo::SafePathFinder* detours = nullptr;
    std::optional<geo::Vec2> home, landing; // where the flight starts and ends (landing: home)
};

// A turn's arcs are sampled every kTurnStepDeg of heading (never closer than kMinTurnStepM), its
// straights only at their ends: the chord of a 20 degree step lies within 1.5 % of the radius inside
// the arc (34 cm at 22 m) and a turn of 180 degrees is 9 waypoints, so that a survey of a few dozen
// lanes stays within the mission items an autopilot holds (ArduPilot 650 on 16 KB boards, PX4 500 by
// default). The route checks and flies the sampled polyline itself.
constexpr double kTurnStepDeg = 20.0;
constexpr double kMinTurnStepM = 0.25;

// The points a Dubins path is flown through: its start, each arc's points every kTurnStepDeg (at
// most), each segment's end.
std::vector<Pose> turnPoints(const DubinsPath& path);

struct PlaneRoute {
    // In flight order: per lane its run-in point (Turn), its photos (Photo); between lanes the
    // turn's sampled points (Turn). Headings are the direction of flight.
    std::vector<LocalWaypoint> waypoints;
    std::vector<int> order;     // lanes in flight order (indices into the input)
    std::vector<bool> reversed; // per flown lane: flown from its last photo to its first
    int skipEvery = 0;          // the skip pattern flown (every k-th lane), 0 for another order
    double lengthM = 0.0;       // the flown length from the first run-in to the last photo
    int runInsShortened = 0;    // run-ins cut short where the full one would enter a margin
    int unsafeTurns = 0;        // turns for which no curvature-bounded path keeps the margins
    std::vector<std::string> warnings;
};

// The route over `lanes` (each flown from photos.front() to photos.back(), or the other way round):
// - lane order: the skip patterns (every k-th lane, then back over the next residue, for k from 1
// to
//   two turn radii over the spacing and one more) over the lanes sorted across the flight
//   direction, and greedy nearest-lane orders by turn length; each order's directions chosen
//   exactly (dynamic programming over the two directions of each lane); the shortest flight kept;
// - a turn is the shortest Dubins path from the end of one lane (heading along it) to the run-in
// point
//   of the next (heading along that) that keeps the field's margin, trying the six words by length;
//   where none does (a zone between the lanes), the turn follows the detour path round the zones,
//   a chain of Dubins paths through its corners (heading there along the bisector of its legs);
//   a turn that cannot be flown safely either way costs so much that an order avoiding it wins; if
//   none does, the shortest one is kept and counted in unsafeTurns with a warning (the route check
//   reports it);
// - a run-in whose straight would enter a margin is shortened to the part that keeps it (the first
//   photo then comes sooner after the turn) and counted.
// Lanes without photos are skipped. A radius of 0 gives straight legs between lanes.
PlaneRoute planPlaneRoute(const std::vector<plan::Lane>& lanes, const PlaneRouteOptions& options);

} // namespace pf::route
