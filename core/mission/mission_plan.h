// The planned mission as value types: per aircraft its grid, cell path, waypoints and route, and totals.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/types.h"
#include "core/grid/grid.h"
#include "core/mission/mission.h"
#include "core/plan/cell_path.h"
#include "core/plan/flight_time.h"
#include "core/plan/metrics.h"
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
    double planningHeightM = 0.0;     // the lowest height above ground its camera sees: lane placement
    int lanesRespaced = 0;            // lanes whose own lowest height above ground spaced their photos wider
    int photosSavedPerLane = 0;       // photos that saved against the spacing of planningHeightM
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
    PlannerKind planner = PlannerKind::Stride; // the planner that made this plan (never Auto)
    std::string plannerChoice;    // with the automatic choice: which planner, and the times compared
    std::vector<std::string> warnings; // the planner's own (e.g. ground no safe path reaches)
    double altitudeM = 0.0;
    double cellSizeM = 0.0;
    double gridAngleDeg = 0.0;    // the angle used (chosen by the search when the mission asks for auto)
    int anglesTried = 0;          // grids planned to choose the angle (1 for a fixed angle)
    sensor::EffectiveFootprint footprint;
    grid::Grid grid;              // grid planners only (empty for sweep and lawnmower)
    plan::CellPath path;          // grid planners: starts at the cell under the take-off point, ends at the
                                  // landing cell
    std::vector<route::LocalWaypoint> localWaypoints; // photo, turn and transit waypoints, local metres
    route::Route route;           // the same in WGS84, with the home point and the cruise speed
    plan::PathMetrics metrics;    // photos included; planning time covers the angle search

    // Filled by planMission (planRegion leaves them empty or zero):
    geo::MultiPolygon subarea;    // the part of the area assigned to this aircraft, local metres
    std::vector<route::LocalWaypoint> surveyWaypoints; // first to last photo after dedup and safety
    std::vector<SortieSummary> sorties; // one per battery; route.waypoints holds them in order, with a
                                        // Transit waypoint at home between two (outside every sortie)
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
    // The coverage check over its part (plan_messages.h: attributeUncovered): the part less the
    // zones, and the plan's listed uncovered patches within it.
    double admissibleAreaM2 = 0.0;
    double uncoveredAreaM2 = 0.0;
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
    std::vector<std::string>
        notes; // things worth knowing that ask for nothing (e.g. sorties needed)

    // Filled by planMission over all aircraft:
    double coverageRatio = 0.0; // admissible area seen by the REAL footprints of all photos (with a
                                // double grid: by each pass on its own, the lower of the two)
    std::vector<double> passCoverage; // a double grid: the share each pass sees on its own
    double uncoveredAreaM2 = 0.0;
    std::vector<UncoveredArea> uncovered; // the largest uncovered patches, largest first
    int uncoveredPatchCount = 0;          // all of them, listed or not
    int noFlyViolations = 0;       // waypoints and legs (home to home) closer to a zone than the margin
    double makespanS = 0.0;        // the longest aircraft's timeS: they fly at the same time
    double idealS = 0.0;           // sum of the aircraft's timeS / number of aircraft
    int photosSaved = 0;           // photos left out across aircraft
    int altitudeConflicts = 0;     // pairs in the air together closer than altitudeSeparationM
    // With the automatic planner choice: which planner made the plan, and the makespans compared.
    std::string plannerChoice;
    // The terrain the plan follows (heights in the local frame, above sea level), when it does.
    std::shared_ptr<const terrain::HeightGrid> terrain;
};

} // namespace pf::mission
