// The check of a route before it is flown or exported: waypoints and legs out of every no-fly
// zone's safety margin, altitudes between the minimum safe altitude and the aircraft's maximum.
#pragma once

#include "core/mission/mission.h"
#include "core/mission/mission_plan.h"
#include "core/route/waypoint.h"
#include "core/sensor/camera.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::mission {

// The lowest altitude above take-off a waypoint may have (m). Below it an aircraft flies at head
// height, inside ground effect and below most obstacles; a survey never needs it (5 m is allowed).
constexpr double kMinSafeAltitudeM = 2.0;

// What a route is checked against.
struct RouteLimits {
    std::vector<NoFlyZone> zones;
    double safetyMarginM = 5.0;
    std::optional<double> maxAltitudeM; // the aircraft's ceiling; unset: unknown, not checked
    double minAltitudeM = kMinSafeAltitudeM;
    geo::GeoPolygon area;                // optional: waypoints outside it are counted (a note)
    // The camera of the aircraft flying the route, when known: whether the photo of a waypoint
    // outside the area still sees part of it (its footprint at the waypoint's height above ground).
    std::optional<sensor::Camera> camera;
    std::optional<geo::LonLat> home;     // take-off: the leg to the first waypoint is checked
    std::optional<geo::LonLat> landing;  // the leg from the last waypoint; home when unset
    bool plane = false; // the aircraft flies as a plane: its turn waypoints are arcs, no photo
};

// Why waypoints lie outside the area: each group of RouteCheck::outside has one reason, true of
// every waypoint it lists.
enum class OutsideReason {
    CoversBoundary, // photo and turn waypoints whose photo still sees the area: lanes end where the
                    // photos cover the boundary, which may lie beyond it
    SeesNothing,    // photo and turn waypoints whose photo sees none of the area
    Unknown,        // photo and turn waypoints of an aircraft whose camera is not known
    Transit, // transit waypoints (no photo): to and from home, around zones, home between sorties
    PlaneTurn, // a plane's turn waypoints (the arcs between lanes and the run-ins, no photo): it
               // turns beyond the lane ends on arcs of at least its turn radius
};

// The waypoints outside the area for one reason.
struct OutsideGroup {
    OutsideReason reason = OutsideReason::CoversBoundary;
    std::vector<int> waypoints; // indices into the route, ascending
    int farthest = -1;          // the one farthest from the area
    double farthestM = 0.0;
    bool atHomeOnly =
        false; // Transit: every one lies at the route's home (where batteries are changed)
};

// The errors found, in words, per waypoint and per leg ("" where fine), and the notes.
struct RouteCheck {
    std::vector<std::string> waypoint; // per waypoint
    std::vector<std::string> leg;      // per leg i: waypoint i -> i + 1
    std::string fromHome;              // take-off -> first waypoint
    std::string toHome;                // last waypoint -> landing
    int noFly = 0;                     // waypoints and legs (home legs included) within a margin
    // Notes, not errors: the waypoints outside the area (all of them), and the same by reason, one
    // group per reason that has any, in the order of OutsideReason.
    int outsideArea = 0;
    std::vector<OutsideGroup> outside;
    const OutsideGroup* outsideGroup(OutsideReason reason) const;
    // The zones (indices into RouteLimits::zones, ascending) a waypoint or leg comes within the
    // margin of.
    std::vector<std::size_t> zonesEntered;

    int count() const; // number of errors
    bool ok() const { return count() == 0; }
    // Every error as one line naming the route and the waypoint (counted from 1, as the Waypoints
    // table and the exported files count): "Falcon 8, waypoint 12: inside no-fly zone Warehouse".
    std::vector<std::string> messages(const std::string& routeLabel) const;
};

RouteCheck checkRoute(const route::Route& route, const RouteLimits& limits);

// The limits of a route of mission `m`: its no-fly zones and margin, its area, the ceiling and the
// camera of the aircraft the route is named after (none when no aircraft has that name), the
// route's home (else the aircraft's, else the mission's) and the mission's landing point.
RouteLimits routeLimits(const Mission& m, const route::Route& route);

// Checks every route against its limits in `m`; the lines of RouteCheck::messages, route after route.
std::vector<std::string> routeErrors(const Mission& m, const std::vector<route::Route>& routes);
// The same for a planned mission as it is flown: an aircraft needing several batteries is checked
// sortie by sortie (each from home and back home), so the leg from one sortie's last waypoint to the
// next one's first, never flown, is not reported; lines name the aircraft and the sortie.
std::vector<std::string> planRouteErrors(const Mission& m, const MissionPlan& plan);

// The names of the mission's no-fly zones ("no-fly zone N" when unnamed) whose safety margin a
// planned route enters (the legs from and back home included), in the mission's order.
std::vector<std::string> zonesEntered(const Mission& m, const MissionPlan& plan);

} // namespace pf::mission
