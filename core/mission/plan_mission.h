// planMission(): the planning facade, from a Mission to per-aircraft cell paths, waypoints and routes.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/types.h"
#include "core/grid/grid.h"
#include "core/mission/mission.h"
#include "core/plan/cell_path.h"
#include "core/plan/flight_time.h"
#include "core/plan/metrics.h"
#include "core/result.h"
#include "core/route/waypoint.h"
#include "core/sensor/camera.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pf::terrain {
class HeightGrid;
}

namespace pf::mission {

// What terrain following (core/mission/terrain_stage.h) did to one aircraft's flight.
struct TerrainSummary {
    bool active = false;
    double heightAboveGroundM = 0.0;  // every waypoint this high above the ground under it
    double planningHeightM = 0.0;     // the lowest height above ground its camera sees: lanes and spacing
    double homeGroundM = 0.0;         // its take-off point's ground above sea level
    double lowestClearanceM = 0.0;    // along every leg, sampled every metre
    int waypointsInserted = 0;        // where the ground rises between two waypoints
    double gsdCm = 0.0;               // at every photo's centre
    double coarsestGsdCm = 0.0;       // at the farthest ground any photo sees (its edges)
};

// One battery's flight: a run of AircraftPlan::route.waypoints from home back to home.
struct SortieSummary {
    int firstWaypoint = 0; // index into route.waypoints (a Transit waypoint out, or the first survey one)
    int lastWaypoint = 0;  // inclusive
    int photos = 0;
    double lengthM = 0.0;  // home to home
    double timeS = 0.0;    // home to home
};

// A part of the admissible area that no photo sees.
struct UncoveredArea {
    geo::MultiPolygon shape; // local metres
    double areaM2 = 0.0;
};

// What one aircraft flies over its region.
struct AircraftPlan {
    std::string aircraft;
    double altitudeM = 0.0;
    double cellSizeM = 0.0;
    double gridAngleDeg = 0.0;    // the angle used (chosen by the search when the mission asks for auto)
    int anglesTried = 0;          // grids planned to choose the angle (1 for a fixed angle)
    sensor::EffectiveFootprint footprint;
    grid::Grid grid;
    plan::CellPath path;          // starts at the cell under the take-off point, ends at the landing cell
    std::vector<route::LocalWaypoint> localWaypoints; // photo, turn and transit waypoints, local metres
    route::Route route;           // the same in WGS84, with the home point and the cruise speed
    plan::PathMetrics metrics;    // photos included; planning time covers the angle search

    // Filled by planMission (planRegion leaves them empty or zero):
    geo::MultiPolygon subarea;    // the part of the area assigned to this aircraft, local metres
    std::vector<route::LocalWaypoint> surveyWaypoints; // first to last photo after dedup and safety
    std::vector<SortieSummary> sorties; // one per battery; route.waypoints holds them in order
    std::vector<route::Route> sortieRoutes; // each sortie as a flight of its own (home to home)
    double timeS = 0.0;           // whole flight, home to home over every sortie, transit included
    plan::FlightTime flight;      // the flown path (home, every waypoint, home between sorties, landing):
                                  // its length, turns and time by the one model (timeS adds the sorties)
    double flightDistanceM = 0.0; // the same as a distance
    int photosSaved = 0;          // photos left out because another aircraft already takes them
    int detours = 0;              // legs replaced by a detour around a no-fly margin
    int waypointsMoved = 0;       // waypoints pushed out of a no-fly margin
    int keptInside = 0;           // waypoints moved inside the area (options.keepInsideArea)
    TerrainSummary terrain;       // terrain following, when the mission asks for it
};

struct PlanTotals {
    int aircraft = 0;
    int cells = 0;
    int visitable = 0;
    int photos = 0;
    double pathLengthM = 0.0;
    double distanceM = 0.0;
    int turns = 0;               // of the planners' cell paths
    double turnAngleDeg = 0.0;
    int flightTurns = 0;         // of the flown routes (AircraftPlan::flight)
    int jumps = 0;
    int revisits = 0;
    double estimatedTimeS = 0.0; // the longest aircraft's time: they fly at the same time
    double planningMs = 0.0;
};

struct MissionPlan {
    std::optional<geo::LocalFrame> frame; // the mission's local planning frame
    std::vector<AircraftPlan> aircraft;
    PlanTotals totals;
    std::vector<std::string> warnings; // things the user must know (e.g. aircraft left unplanned)

    // Filled by planMission over all aircraft:
    double coverageRatio = 0.0;    // admissible area seen by the REAL footprints of all photos
    double uncoveredAreaM2 = 0.0;
    std::vector<UncoveredArea> uncovered; // the largest uncovered patches, largest first
    int noFlyViolations = 0;       // waypoints and legs (home to home) closer to a zone than the margin
    double makespanS = 0.0;        // the longest aircraft's timeS: they fly at the same time
    double idealS = 0.0;           // sum of the aircraft's timeS / number of aircraft
    int photosSaved = 0;           // photos left out across aircraft
    int altitudeConflicts = 0;     // pairs in the air together closer than altitudeSeparationM
    // The terrain the plan follows (heights in the local frame, above sea level), when it does.
    std::shared_ptr<const terrain::HeightGrid> terrain;
};

// Plans ONE aircraft over `region` (local metres in `frame`, e.g. the subarea assigned to it), avoiding
// `noFly` (local metres, un-buffered; the options' safety margin is applied). The take-off cell is the
// visitable cell nearest to `home` and the landing cell the one nearest to `landing` (home if unset);
// without a home the path starts at the grid's first cell. With no grid angle in the options, angles
// 0, 5, ..., 175 degrees and the directions of the region's longest edges are tried and the plan with
// the smallest estimated time is kept (then fewer turns). Errors name the aircraft and the problem.
Result<AircraftPlan> planRegion(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                                const AircraftConfig& aircraft, const PlannerOptions& options,
                                const geo::LocalFrame& frame, const std::optional<geo::Vec2>& home,
                                const std::optional<geo::Vec2>& landing = std::nullopt);

// The angles the automatic search tries for a region.
std::vector<double> candidateAngles(const geo::MultiPolygon& region);

// The plan as a GeoJSON FeatureCollection in WGS84: per aircraft a LineString of the flown path (home,
// every waypoint, landing) with the properties aircraft, kind "path", one Point per photo with
// aircraft, kind "photo", seq (1-based, per aircraft), alt_m, heading_deg (clockwise from north),
// footprint_across_m and footprint_along_m (the REAL ground footprint across and along the track), its
// subarea (Polygon or MultiPolygon, kind "subarea", aircraft) and every uncovered patch listed in the
// plan (kind "uncovered", area_m2).
std::string planToGeoJson(const MissionPlan& plan);
// The metrics as JSON: {"planner", "aircraft": [{"name", ...metrics, time_s, sorties, photos_saved}],
// "total": {..., coverage_ratio, nofly_violations, makespan_s}, "coverage_ratio", "nofly_violations",
// "warnings": [...]}.
std::string planMetricsJson(const MissionPlan& plan, const std::string& plannerName);

// Plans the mission end to end. One aircraft flies the whole admissible area; several share it through
// fleet::splitArea, balanced on the time of the route planRegion makes at a fixed grid angle (the
// mission's, or the one the search picks for the aircraft with the coarsest grid over the whole area),
// from home through the photo waypoints and back. The split is planned to the end and corrected with
// each aircraft's final/estimated time (up to 3 rounds), from the aircraft in the mission's order and,
// if that never came within 3 % of the ideal, reversed (the order places the subareas); of the splits
// tried (each planned at the fixed angle, without the coverage check), the one with the smallest
// makespan among those within 1.10 x the ideal (total time / aircraft), else overall, is kept (the next
// one if its photos miss the 0.995 coverage target or it breaches a no-fly margin) and planned with
// the mission's options. Per
// aircraft: planRegion over its subarea (grid angle: the mission's, or searched per subarea), photos
// another aircraft already takes are dropped, waypoints are kept inside the area if asked, out of every
// no-fly margin (detours), the flight gets its safe transit from and to its home (the aircraft's, else
// the mission's) and is cut into sorties that fit its endurance less options.batteryReserve. Finally
// altitudes are checked for separation (a warning per pair) and an independent check rasterises the
// real footprints of every photo (coverage ratio, uncovered patches) and counts margin breaches.
// Errors name the aircraft and the problem.
Result<MissionPlan> planMission(const Mission& m);

} // namespace pf::mission
