// Smooth flight trajectories through a route's waypoints (paper 004), kept out of no-fly zones, and
// the flight time they take.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/types.h"
#include "core/result.h"
#include "core/route/waypoint.h"

#include <cstddef>
#include <vector>

namespace pf::route {

struct TrajectoryOptions {
    double spacingM = 1.0; // distance between consecutive samples along the trajectory (> 0)
    // Rounds of densifying a leg that cuts into a keep-out zone (each round doubles the knots
    // placed on the straight leg) before that leg is flown straight instead.
    int maxRefinements = 3;
};

struct TrajectorySample {
    geo::Vec2 pos{0, 0};    // local metres
    double yawDeg = 0.0;    // clockwise from north, [0, 360)
    double distanceM = 0.0; // along the trajectory from its start
};

struct Trajectory {
    std::vector<TrajectorySample> samples; // passes through every waypoint; first and last at rest
    // One entry per leg between consecutive input waypoints: true where the leg is flown straight
    // because the curve would have cut into a keep-out zone (legs of zero length count as
    // straight).
    std::vector<bool> straightLegs;
    // Legs whose straight line between the waypoints already enters a keep-out zone: the route
    // itself is unsafe there and no smoothing can fix it (the planner should never produce these).
    std::vector<std::size_t> unsafeLegs;
    double lengthM = 0.0;
    double headingChangeDeg = 0.0; // sum of the turns between consecutive waypoint headings
};

// A clamped cubic spline in x, y (local metres) and yaw over Lee's centripetal knots, at rest at
// both ends, sampled every `spacingM`. Yaw is unwrapped first, so a turn from 350 to 10 degrees
// goes through north, never back round through south. Where a sampled leg would enter `keepOut`
// (pass the no-fly zones already buffered by the safety margin), knots are added on that leg's
// straight line; if that is not enough the leg is flown straight, and the neighbouring curves
// join it tangentially. Consecutive waypoints at the same place are merged.
Result<Trajectory> buildTrajectory(const std::vector<LocalWaypoint>& waypoints,
                                   const geo::MultiPolygon& keepOut,
                                   const TrajectoryOptions& options = {});

// The same for a Route, converted to the local frame; the flight starts and ends at the route's
// home when it has one.
Result<Trajectory> buildTrajectory(const Route& route, const geo::LocalFrame& frame,
                                   const geo::MultiPolygon& keepOut,
                                   const TrajectoryOptions& options = {});

// No-fly zones in the local frame, grown by `marginM`: the keep-out set for buildTrajectory.
geo::MultiPolygon keepOutZones(const std::vector<geo::GeoPolygon>& noFlyZones,
                               const geo::LocalFrame& frame, double marginM);

// The trajectory's samples in WGS84 (for exports and the map).
std::vector<geo::LonLat> toGeo(const Trajectory& trajectory, const geo::LocalFrame& frame);

// Sum over consecutive headings of the smaller turn between them, in degrees.
double totalHeadingChangeDeg(const std::vector<double>& headingsDeg);

struct FlightEstimate {
    double lengthM = 0.0;
    double headingChangeDeg = 0.0;
    double timeS = 0.0; // lengthM / speed + headingChangeDeg / turn rate (paper 004)
};

// Errors when the speed or the turn rate is not positive.
Result<FlightEstimate> estimateFlight(const Trajectory& trajectory, double speedMps,
                                      double turnRateDegS);

} // namespace pf::route
