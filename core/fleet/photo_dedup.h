// Photos across aircraft (paper 001, section V.B): no second photo of ground another aircraft
// already photographs, without opening a gap.
#pragma once

#include "core/result.h"
#include "core/route/waypoint.h"

#include <vector>

namespace pf::fleet {

struct AircraftPhotos {
    std::vector<route::LocalWaypoint> waypoints; // survey waypoints in flight order (before transit)
    double effectiveAcrossM = 0.0; // the ground each photo is responsible for
    double effectiveAlongM = 0.0;
    double realAcrossM = 0.0;      // what each photo actually sees
    double realAlongM = 0.0;
};

struct DedupReport {
    std::vector<int> photosSaved; // per aircraft
    int totalSaved = 0;
};

// Drops a Photo waypoint only when its whole EFFECTIVE footprint lies inside the union of the REAL
// footprints of other aircraft's photos that are kept; those covering photos are then pinned (never
// dropped themselves), so every drop stays justified and no gap opens. Aircraft with the smallest
// effective footprint are examined first: their photos are the ones most often swallowed by a
// larger neighbour's. A dropped photo's waypoint is removed where the path runs straight through
// it, becomes a Turn waypoint where the path bends there, and waypoints left without a photo at
// either end of a route are trimmed. Errors: a footprint side not positive.
Result<DedupReport> dropDuplicatePhotos(std::vector<AircraftPhotos>& fleet);

} // namespace pf::fleet
