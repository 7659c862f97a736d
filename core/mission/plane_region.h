// A plane over the sweep's lanes: the stage of one aircraft's planning (plan_region) that turns the
// sweep planner's lanes into a route a fixed-wing or VTOL aircraft can fly.
#pragma once

#include "core/geo/types.h"
#include "core/mission/mission.h"
#include "core/mission/mission_plan.h"
#include "core/plan/sweep/sweep_planner.h"

#include <optional>
#include <vector>

namespace pf::mission {

// How much further from the no-fly zones a plane's lanes end than the margin: its turn begins at a
// lane's last photo and runs up to one turn radius on past it, so up to the radius; the ground in
// between is photographed from outside, as the ground in a margin is, which sees up to half a real
// footprint ahead, so at most 0.45 of the real footprint along the track (with a larger radius the
// turn goes away from the zone or round it: route::planPlaneRoute).
double planeLaneRoomM(double radiusM, double realAlongM);

// The plan of aircraft `cfg` (flying as a plane, minimum turn radius `radiusM`, lanes `trackSpacingM`
// apart) over the sweep's lanes: route::planPlaneRoute with the mission's no-fly margin and detours
// round the zones at the margin plus 0.9 of the radius, the waypoints (run-ins and turns as Turn
// waypoints, photos on the lanes), the sweep's warnings and the route's, and, with keep-inside, that
// it holds for the lanes only. The metrics are left to the caller (the one flight-time model).
AircraftPlan planeLanesPlan(const plan::SweepPlan& sweep, const std::vector<geo::Polygon>& noFly,
                            const AircraftConfig& cfg, double radiusM, double trackSpacingM,
                            const PlannerOptions& options, const std::optional<geo::Vec2>& home,
                            const std::optional<geo::Vec2>& landing);

} // namespace pf::mission
