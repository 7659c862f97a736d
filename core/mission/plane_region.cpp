#include "core/mission/plane_region.h"

#include "core/geo/no_fly_field.h"
#include "core/route/photo_waypoints.h"
#include "core/route/plane_route.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pf::mission {

double planeLaneRoomM(double radiusM, double realAlongM) { return std::min(radiusM, 0.45 * realAlongM); }

AircraftPlan planeLanesPlan(const plan::SweepPlan& sweep, const std::vector<geo::Polygon>& noFly,
                            const AircraftConfig& cfg, double radiusM, double trackSpacingM,
                            const PlannerOptions& options, const std::optional<geo::Vec2>& home,
                            const std::optional<geo::Vec2>& landing) {
    const geo::NoFlyField field(noFly, options.safetyMarginM);
    // Detours round the zones at the margin plus most of a turn radius: turning at their corners on
    // arcs of that radius keeps the margin.
    const geo::SafePathFinder detours(geo::NoFlyField(noFly, options.safetyMarginM + 0.9 * radiusM));
    route::PlaneRouteOptions ro;
    ro.detours = noFly.empty() ? nullptr : &detours;
    ro.radiusM = radiusM;
    ro.runInM = cfg.plane.runInM;
    ro.trackSpacingM = trackSpacingM;
    ro.field = &field;
    ro.home = home;
    ro.landing = landing;
    const route::PlaneRoute r = route::planPlaneRoute(sweep.lanes, ro);
    AircraftPlan p;
    p.gridAngleDeg = sweep.stats.angleDeg;
    p.anglesTried = sweep.stats.directionsPlanned;
    p.localWaypoints = r.waypoints;
    route::dropNearDuplicates(p.localWaypoints, &field);
    p.warnings = sweep.warnings;
    p.warnings.insert(p.warnings.end(), r.warnings.begin(), r.warnings.end());
    if (options.keepInsideArea)
        p.warnings.push_back("a plane's turns run up to its turn radius (" +
                             std::to_string(static_cast<int>(std::lround(radiusM))) +
                             " m) past the area's edge: keep-inside holds for its lanes, not its turns");
    return p;
}

} // namespace pf::mission
