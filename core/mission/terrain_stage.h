// The terrain stage of planMission (issue 18): the DEM over the mission, the height the footprints
// are planned at, and terrain following applied to the planned flights.
#pragma once

#include "core/mission/mission.h"
#include "core/mission/plan_mission.h"
#include "core/mission/validation.h"
#include "core/plan/coverage_check.h"
#include "core/result.h"
#include "core/route/lane_spacing.h"
#include "core/terrain/dem.h"
#include "core/terrain/height_grid.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pf::mission {

// The terrain one mission is planned over.
struct MissionTerrain {
    std::shared_ptr<const terrain::HeightGrid> grid; // the area and a margin, local metres
    terrain::DemInfo info;
    std::optional<double> homeGroundM;   // the mission's take-off point (given, else from the DEM)
    std::vector<double> heightAboveGroundM; // per aircraft: its altitude (or its GSD's), above ground
    std::vector<double> planningHeightM;    // per aircraft: the lowest height above ground it sees
    // Per aircraft: at every node of `grid`, the largest rise of the ground within its camera's
    // footprint reach (terrain::riseWithin), for the lowest height above ground along each lane.
    std::vector<std::shared_ptr<const terrain::HeightGrid>> riseM;
    // Whether each lane's photos are spaced from that lane's own lowest height above ground
    // (laneSpacing); off, every lane keeps the area-wide spacing of planningHeightM.
    bool spacingPerLane = true;
};

// Where a DEM named in a mission is: the path itself if it exists, else (a bare name such as the
// demo's "demo_dem.tif") the maps folder of the data directory or of the build tree. The path
// unchanged when none holds it (opening it then says what is missing).
std::string locateDem(const std::string& path);
// The synthetic demo DEM generated at build time, "" when it is not found.
std::string demoDemPath();

// Reads the mission's DEM (m.terrain.demPath) over the area, every home and landing point, and a
// margin for the footprints, and works out each aircraft's heights. Errors (exit 2 on the command
// line): no DEM given, unreadable, not covering the area (which part) or a take-off point without a
// height given, all no-data; a minimum clearance above an aircraft's height; ground rising within a
// camera's view by more than 80 % of its height above ground (no height keeps the overlap).
Result<std::shared_ptr<const MissionTerrain>> loadMissionTerrain(const Mission& m, const LocalGeometry& geom);

// The mission as the planner plans it over terrain: each aircraft's altitude replaced by the lowest
// height above ground its camera sees over the area (its height above ground minus the largest rise
// of the ground within its footprint's half-diagonal of any point of the area), so that lanes and
// photo spacing keep the overlaps wherever the ground comes closer; `terrain.prepared` set to `t`.
// The planners then space each lane's photos by its own lowest height above ground (laneSpacing).
Mission planningMission(const Mission& m, std::shared_ptr<const MissionTerrain> t);

// The trigger distance of each lane of aircraft k of a mission planned over terrain (m.terrain.prepared
// set, m as planningMission made it): the effective footprint along the track at the lowest height
// above ground along the lane, its height above ground minus the largest rise of the ground within
// its footprint's half-diagonal of any point of the lane (the area-wide rule of planningMission,
// along one lane), so that the front overlap is kept over the whole lane. Empty (the planner's
// spacing kept) without terrain or with MissionTerrain::spacingPerLane off; 0 for a lane with no
// height left to plan at.
route::LaneSpacingFn laneSpacing(const Mission& m, std::size_t k);

// Whether planMission must first run the terrain stage: the mission follows the terrain and its DEM
// has not been read yet.
bool needsTerrainStage(const Mission& m);
// The terrain stage in front of a planner: reads the DEM over the mission (loadMissionTerrain) and
// plans planningMission(m) with `plan` (planMission itself: its automatic choice then compares
// planners over the same terrain). Errors: the DEM's, or the planner's.
Result<MissionPlan> planOverTerrain(const Mission& m,
                                    const std::function<Result<MissionPlan>(const Mission&)>& plan);

// Terrain following applied to every aircraft of a plan of planningMission(m) (m.terrain.prepared
// set): waypoints at
// their height above the ground, legs checked every metre and waypoints inserted where the ground
// rises (route::followTerrain), altitudes above take-off from the home's ground, sortie and flight
// times with the 3D length of each leg, the photos in `footprints` and each one's footprint on the
// terrain in `outlines` (parallel, for the coverage check), AircraftPlan::terrain filled. Warnings go
// to plan.warnings.
Status applyTerrain(MissionPlan& plan, const Mission& m, const geo::LocalFrame& frame,
                    const std::vector<std::optional<geo::Vec2>>& homes, const std::optional<geo::Vec2>& landing,
                    std::vector<plan::PhotoFootprint>& footprints, std::vector<geo::Ring>& outlines);

} // namespace pf::mission
