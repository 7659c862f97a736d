// plan.geojson: the planned mission as a compact GeoJSON FeatureCollection, written as a stream.
#pragma once

#include "core/mission/mission_plan.h"
#include "core/result.h"

#include <ostream>
#include <string>

namespace pf::mission {

struct PlanGeoJsonOptions {
    // Also one Polygon per photo (kind "footprint", aircraft, seq): its real ground footprint. Off by
    // default: it triples the file (about 250 more bytes per photo).
    bool footprints = false;
};

// Writes the plan as GeoJSON in WGS84, one feature per line, coordinates with 7 decimals (about 1 cm)
// and other numbers at fixed precision, without building a document in memory (about 190 bytes per
// photo). Features, in order:
// - per aircraft a LineString of the flown path (home, every waypoint, home between sorties, landing)
//   with kind "path", aircraft, alt_m, footprint_across_m and footprint_along_m (the REAL ground
//   footprint across and along the track, the same for all its photos), photos and sorties;
// - one Point per photo: kind "photo", aircraft, seq (1-based per aircraft), alt_m, heading_deg
//   (clockwise from north); the footprint is the path's;
// - with options.footprints, one Polygon per photo (kind "footprint", aircraft, seq);
// - per aircraft its subarea (kind "subarea", aircraft; MultiPolygon) and every uncovered patch listed
//   in the plan (kind "uncovered", area_m2).
// Returns false when the stream failed.
bool writePlanGeoJson(const MissionPlan& plan, std::ostream& out, const PlanGeoJsonOptions& options = {});

// The same into `path`, atomically (a temporary file beside it, renamed over it when complete).
Status writePlanGeoJsonFile(const MissionPlan& plan, const std::string& path, const PlanGeoJsonOptions& options = {});

// The plan as GeoJSON text (writePlanGeoJson, default options): for tests and small plans; files are
// written with writePlanGeoJsonFile, which streams.
std::string planToGeoJson(const MissionPlan& plan);

} // namespace pf::mission
