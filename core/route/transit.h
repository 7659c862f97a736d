// Safe transit between an aircraft's home and its survey: out to the first waypoint and back.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"
#include "core/route/safety.h"
#include "core/route/waypoint.h"

#include <optional>
#include <vector>

namespace pf::route {

struct TransitReport {
    double outboundM = 0.0; // home to the first survey waypoint, along the safe path
    double returnM = 0.0;   // last survey waypoint to the landing point
    int waypointsAdded = 0; // Transit waypoints inserted for detours
};

// The straight or detoured safe path from a to b, both ends included.
Result<std::vector<geo::Vec2>> safePolyline(const geo::Vec2& a, const geo::Vec2& b, const SafePathFinder& finder);

// `survey` with the Transit waypoints of the shortest safe paths from `home` to its first waypoint
// and from its last waypoint to `landing` (home when unset). Home and landing themselves are not
// added: the route carries them as its take-off and landing point. Errors: home or landing inside a
// no-fly margin, or no safe way out or back.
Result<std::vector<LocalWaypoint>> withTransit(const std::vector<LocalWaypoint>& survey, const geo::Vec2& home,
                                               const SafePathFinder& finder,
                                               const std::optional<geo::Vec2>& landing = std::nullopt,
                                               TransitReport* report = nullptr);

} // namespace pf::route
