// Double grids: the area surveyed twice, the second pass's lanes at 90 degrees to the first's, so
// that photogrammetry gets two independent views of every point (3D models of a collapsed or burnt
// building). Each pass is a complete survey: its photos are kept apart from the other pass's when
// photos are shared between aircraft and when the coverage is checked.
#pragma once

#include "core/fleet/photo_dedup.h"
#include "core/geo/types.h"
#include "core/mission/mission.h"
#include "core/mission/mission_plan.h"
#include "core/plan/coverage_check.h"
#include "core/result.h"
#include "core/route/lane_spacing.h"
#include "core/route/waypoint.h"

#include <optional>
#include <vector>

namespace pf::mission {

// planRegion for options.doubleGrid. The first pass is planned as a single grid would be (the
// options' planner, the automatic choice included); the second with straight lanes at 90 degrees to
// the lanes most of the first pass's photos lie on: the sweep planner at that angle (round the
// zones, as the first pass), or the lawnmower when the first pass is the lawnmower. The second pass
// is flown after the first, from whichever of its ends gets the flight home soonest; its waypoints
// carry pass 1. plannerChoice says both. Errors: either pass's.
Result<AircraftPlan>
planDoubleGrid(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
               const AircraftConfig& aircraft, const PlannerOptions& options,
               const std::optional<geo::Vec2>& home,
               const std::optional<geo::Vec2>& landing, const route::LaneSpacingFn& laneSpacing);

// The direction (degrees counter-clockwise from east, [0, 180)) of the lanes most photos of `w`
// lie on, by their headings; 0 without photos.
double dominantLaneAngleDeg(const std::vector<route::LocalWaypoint>& w);

// `w` flown the other way: the order reversed, photos and turns facing the other way, transits
// facing the next point.
std::vector<route::LocalWaypoint> reversedFlight(std::vector<route::LocalWaypoint> w);

// fleet::dropDuplicatePhotos pass by pass: a photo is left out only where other aircraft's photos
// of its own pass see its ground (each aircraft's survey holds its first pass, then its second).
Result<fleet::DedupReport> dropDuplicatePhotosPerPass(std::vector<fleet::AircraftPhotos>& fleet);

// The photos of each pass checked on their own against `admissible` (the same raster as a single
// check): passes[i] is the pass of photos[i] (and of outlines[i], when given). The report of the
// pass that sees less comes first; `perPass` gets each pass's covered share.
Result<plan::CoverageReport> checkPassCoverage(const geo::MultiPolygon& admissible,
                                               const std::vector<plan::PhotoFootprint>& photos,
                                               const std::vector<int>& passes,
                                               const std::vector<geo::Ring>* outlines,
                                               std::vector<double>& perPass);

} // namespace pf::mission
