// Photo spacing per lane: the photos of each straight lane of a flight spaced by the trigger
// distance that lane allows (over terrain: from the lowest height above ground along it).
#pragma once

#include "core/geo/types.h"
#include "core/route/waypoint.h"

#include <functional>
#include <utility>
#include <vector>

namespace pf::route {

// The lanes of a flight: maximal runs of consecutive Photo waypoints (inclusive index ranges) with
// one heading, on the straight line through the first of them along that heading (1 cm across it),
// advancing along it, each at most `maxGapM` after the previous one. A run of photos with a wider
// gap (the flight crosses ground it does not photograph: a hole, a zone, a bay of the area) is two
// lanes. Single photos are lanes of one.
std::vector<std::pair<int, int>> photoLanes(const std::vector<LocalWaypoint>& w, double maxGapM);

// The trigger distance (metres) a lane from photo a to photo b may have; 0 or less keeps its
// photos.
using LaneSpacingFn = std::function<double(const geo::Vec2& a, const geo::Vec2& b)>;

struct LaneSpacingReport {
    int lanes = 0;        // lanes of two photos or more
    int respaced = 0;     // lanes given fewer photos
    int photosBefore = 0; // of the lanes respaced
    int photosAfter = 0;
};

// The flight `w` (planned with the trigger distance `areaSpacingM` everywhere) with the photos of
// each lane (photoLanes, gaps up to areaSpacingM) spaced by the lane's own trigger distance d =
// spacing(first, last): the first and last photos stay where they are (the planner made them safe
// and they cover the lane's ends) and n = ceil(L / d) + 1 photos lie evenly between them (L their
// distance), so no two consecutive photos are more than d apart. A lane changes only when n is less
// than both the photos it has and ceil(L / areaSpacingM) + 1, what the area-wide trigger distance
// needs: a lane whose own trigger distance is the area's keeps its photos exactly, and a lane is
// never given more photos. The new photos keep the lane's heading and the cell of the old photo
// nearest to them; every waypoint that is not a photo of a respaced lane is unchanged. The photos
// lie on the straight legs the aircraft flew between the old ones, so the flown path is the same
// line.
std::vector<LocalWaypoint> spaceLanes(const std::vector<LocalWaypoint>& w, double areaSpacingM,
                                      const LaneSpacingFn& spacing,
                                      LaneSpacingReport* report = nullptr);

} // namespace pf::route
