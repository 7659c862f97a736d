// PlannedFlight: the photo points and the area of a plan, from plan.geojson (photoflight-cli plan
// --out DIR) or from a plan in memory, for matching photos to where they were meant to be taken.
#pragma once

#include "core/geo/types.h"
#include "core/mission/plan_mission.h"
#include "core/result.h"

#include <string>
#include <vector>

namespace pf::mosaic {

struct PlannedPhoto {
    std::string aircraft;
    int seq = 0; // 1-based, per aircraft, in flight order
    geo::LonLat position;
    double altitudeM = 0.0; // above the take-off point
    double headingDeg =
        0.0; // clockwise from north: where the aircraft (and the top of the image) points
    double footprintAcrossM =
        0.0; // the real ground footprint across the track (the image's long side)
    double footprintAlongM = 0.0; // along the track (the short side)
    // "Falcon 8 #12", for messages.
    std::string label() const { return aircraft + " #" + std::to_string(seq); }
};

struct PlannedFlight {
    std::string source; // the file read, for messages ("plan.geojson", "the current plan")
    std::vector<PlannedPhoto> photos;  // per aircraft in flight order, aircraft after aircraft
    std::vector<geo::GeoPolygon> area; // the area to photograph (the aircraft's subareas), WGS84
    std::vector<std::string>
        areaAircraft; // for each polygon of `area`, the aircraft it is assigned to
    // The aircraft of the plan, in order.
    std::vector<std::string> aircraft() const;
};

// Reads `path`: a plan.geojson file or a directory holding one. Errors name the file and what is
// wrong (no photo points, a photo without alt_m, ...).
Result<PlannedFlight> readPlannedFlight(const std::string& path);

// The same from a plan computed in this process (the desktop application's current plan).
PlannedFlight plannedFlightFromPlan(const mission::MissionPlan& plan);

} // namespace pf::mosaic
