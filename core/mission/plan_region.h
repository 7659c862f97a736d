// Planning one aircraft over its region: the planner kinds (grid planners with their angle search, the
// sweep planner, the lawnmower yardstick, the automatic choice) and what their plans are compared on.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/types.h"
#include "core/mission/mission.h"
#include "core/mission/mission_plan.h"
#include "core/result.h"
#include "core/route/lane_spacing.h"
#include "core/route/waypoint.h"

#include <optional>
#include <vector>

namespace pf::mission {

// Plans ONE aircraft over `region` (local metres in `frame`, e.g. the subarea assigned
// to it), avoiding `noFly` (local metres, un-buffered; the options' safety margin is applied), with
// options.planner:
// - grid planners (stride, raster, wavefront): the take-off cell is the visitable cell nearest to
//   `home` and the landing cell the one nearest to `landing` (home if unset); without a home the
//   path starts at the grid's first cell. With no grid angle in the options, angles 0, 5, ..., 175
//   degrees and the directions of the region's longest edges are tried; the three whose cell paths
//   fly soonest (then fewer turns) are turned into lanes and the one whose route flies soonest is
//   kept;
// - sweep: plan::planSweep on the exact polygon (the mission's grid angle, if set, as its only lane
//   direction);
// - lawnmower: plan::planLawnmower, the Survey pattern over the region, straight over the zones;
// - auto: sweep, stride and raster are planned in full and the one whose route flies soonest (from
//   home over its survey waypoints and back, aloneRouteTimeS) is kept; plannerChoice says which and
//   why;
// - with options.doubleGrid, planDoubleGrid (core/mission/double_grid.h): two passes at 90 degrees.
// An aircraft flying as a plane (fixed-wing, VTOL) is planned only by the planners that serve planes
// (planner_kinds.h: the sweep, and auto among them): the sweep's lanes flown with Dubins turns
// (plane_region.h); another planner is refused with planeRoutingError.
// With `laneSpacing` (over terrain: terrain_stage.h's laneSpacing), every planner's photos are then
// spaced per lane (route::spaceLanes, before the automatic choice compares them; the lanes respaced
// and the photos that saved in AircraftPlan::terrain).
// The plan's route has the aircraft's name and speed but neither home nor waypoints: the caller
// converts those to WGS84 for the plan it keeps (routeWaypoints from the waypoints finally flown).
// Nothing here touches the frame's transformation, so regions can be planned on several threads.
// Errors name the aircraft and the problem.
Result<AircraftPlan> planRegion(const geo::MultiPolygon& region,
                                const std::vector<geo::Polygon>& noFly,
                                const AircraftConfig& aircraft, const PlannerOptions& options,
                                const std::optional<geo::Vec2>& home,
                                const std::optional<geo::Vec2>& landing = std::nullopt,
                                const route::LaneSpacingFn& laneSpacing = {});

// A plan made without a grid (sweep, lawnmower, corridor, a double grid): its metrics from its
// flown survey, the length and turns by the one model; no cells.
void routeMetrics(AircraftPlan& p, const plan::FlightTimeModel& model);

// The angles the automatic search tries for a region.
std::vector<double> candidateAngles(const geo::MultiPolygon& region);

// The survey part of a planned route: from the first photo to the last. The planner's own way from the
// take-off cell and back to the landing cell is replaced by the shortest safe transit later.
std::vector<route::LocalWaypoint> surveyPart(const std::vector<route::LocalWaypoint>& w);

// The route waypoints (WGS84, at `altitudeM`) of local waypoints, transformed in blocks of 65,536 with
// a cancel check between blocks (two million waypoints take 0.8 s); a cancelled job gets a partial
// list, which its caller drops.
std::vector<route::Waypoint> routeWaypoints(const std::vector<route::LocalWaypoint>& w, const geo::LocalFrame& frame,
                                            double altitudeM);

// The time of the route an aircraft would fly alone over its survey waypoints: from home along the
// straight line to the first one, through all, and straight back (to the landing point if any), by the
// one flight-time model. What planners and splits are compared on before the final plan.
double aloneRouteTimeS(const std::vector<route::LocalWaypoint>& survey, const AircraftConfig& a,
                       const std::optional<geo::Vec2>& home, const std::optional<geo::Vec2>& landing);

} // namespace pf::mission
