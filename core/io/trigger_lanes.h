// Lanes a camera can photograph by distance: found in a route's geometry, not in planner fields.
#pragma once

#include "core/route/waypoint.h"

#include <cstddef>
#include <vector>

namespace pf::io {

// Photo waypoints first..last (indices into the route) that lie on one straight line, `spacingM`
// apart, at one altitude and heading: a camera triggered every spacingM metres from `first` takes
// exactly these photos.
struct TriggerLane {
    std::size_t first = 0;
    std::size_t last = 0;
    double spacingM = 0.0;
    std::size_t photos() const { return last - first + 1; }
};

// Maximal runs of at least 3 consecutive photo waypoints, collinear within 5 cm, their spacings
// equal within 1 cm, altitudes within 1 cm and headings within 0.5 degrees. A last photo that is
// closer to its predecessor (moved out of a no-fly margin) is not part of the lane: it stays a
// photo of its own.
std::vector<TriggerLane> findTriggerLanes(const std::vector<route::Waypoint>& waypoints);

// Merges consecutive waypoints closer than `minDistanceM` (geodesic) into one: a photo wins over a
// turn or transit point (its position, heading and kind are kept), the higher altitude is kept.
// `merged` receives the number of waypoints removed.
std::vector<route::Waypoint> mergeCloseWaypoints(const std::vector<route::Waypoint>& waypoints,
                                                 double minDistanceM,
                                                 std::size_t* merged = nullptr);

} // namespace pf::io
