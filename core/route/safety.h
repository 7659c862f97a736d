// Flight safety of a route: no waypoint or leg inside a no-fly zone's margin (shortest detours), and
// optionally every waypoint kept inside the area without losing the part of the area it covers.
#pragma once

#include "core/geo/no_fly_field.h"
#include "core/geo/types.h"
#include "core/result.h"
#include "core/route/waypoint.h"

#include <string>
#include <vector>

namespace pf::route {

// The no-fly model (exact clearances, shortest safe paths) lives in geo/no_fly_field.h.
using geo::NoFlyField;
using geo::SafePathFinder;

// Heading in degrees clockwise from north, [0, 360), of the direction from a to b.
double headingDeg(const geo::Vec2& a, const geo::Vec2& b);

struct SafetyReport {
    int waypointsMoved = 0;    // waypoints pushed out of a no-fly margin (their photo may lose coverage)
    int detours = 0;           // legs replaced by a detour
    int detourWaypoints = 0;   // Transit waypoints added by the detours
    double addedLengthM = 0.0; // extra distance flown because of the detours
    int keptInside = 0;        // waypoints moved fully inside the area (keepInsideArea)
    int leftOutside = 0;       // waypoints moved only part of the way: further would open a gap
    std::vector<std::string> warnings;
};

// Moves any waypoint inside a margin to the nearest safe point and replaces every leg crossing a
// margin by the shortest safe detour (Transit waypoints, heading along the direction of travel).
// The safety net of the route: photoWaypoints already places every photo outside the margins, so on a
// planned route it moves nothing and only flies the jumps around the zones; it stays to catch a
// waypoint that a later stage may have moved. Errors: no safe way between two waypoints.
Result<std::vector<LocalWaypoint>> enforceNoFly(const std::vector<LocalWaypoint>& waypoints,
                                                const SafePathFinder& finder, SafetyReport* report = nullptr);

// The photo geometry keepInsideArea needs to protect coverage.
struct PhotoSides {
    double effectiveAcrossM = 0.0; // the part of the ground each photo is responsible for
    double effectiveAlongM = 0.0;
    double realAcrossM = 0.0;      // what the photo actually sees
    double realAlongM = 0.0;
};

// Paper 001, sections VI-VII: keeps waypoints inside the area shrunk by `marginM`. Each Photo
// waypoint outside is projected towards the nearest point of the shrunk area, but only as far as its
// REAL footprint still contains the admissible part of the ground it was responsible for (its
// effective footprint at the original position, within `admissible`), so no gap opens; it may stop
// part way (counted in leftOutside, with a warning). The check is per photo rather than per cell
// because a cell usually gets several photos along the track, none of which sees the whole cell
// alone; their responsibilities together tile it, so keeping each one keeps the cell covered.
// Run plan::checkCoverage afterwards to report what, if anything, is left uncovered.
// Turn waypoints move fully; Transit waypoints
// are left alone. A moved point must also stay safe from the no-fly zones of `finder`.
// Errors: the area shrunk by the margin is empty, sides not positive.
Result<std::vector<LocalWaypoint>> keepInsideArea(const std::vector<LocalWaypoint>& waypoints,
                                                  const geo::MultiPolygon& area, const geo::MultiPolygon& admissible,
                                                  const PhotoSides& sides, double marginM,
                                                  const SafePathFinder& finder, SafetyReport* report = nullptr);

} // namespace pf::route
