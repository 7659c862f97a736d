// planMission(): the planning facade, from a Mission to per-aircraft cell paths, waypoints and routes.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/types.h"
#include "core/grid/grid.h"
#include "core/mission/mission.h"
#include "core/plan/cell_path.h"
#include "core/plan/metrics.h"
#include "core/result.h"
#include "core/route/waypoint.h"
#include "core/sensor/camera.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::mission {

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
};

struct PlanTotals {
    int aircraft = 0;
    int cells = 0;
    int visitable = 0;
    int photos = 0;
    double pathLengthM = 0.0;
    double distanceM = 0.0;
    int turns = 0;
    double turnAngleDeg = 0.0;
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
// every waypoint, landing) with the properties aircraft, kind "path", and one Point per photo with
// aircraft, seq (1-based, per aircraft), alt_m and heading_deg (clockwise from north).
std::string planToGeoJson(const MissionPlan& plan);
// The metrics as JSON: {"aircraft": [{"name", ...metrics}], "total": {...}, "warnings": [...]}.
std::string planMetricsJson(const MissionPlan& plan, const std::string& plannerName);

// Plans the mission. With several aircraft the area must be partitioned between them first; until that
// stage is available only the first aircraft is planned (over the whole area) and a warning says so.
Result<MissionPlan> planMission(const Mission& m);

} // namespace pf::mission
