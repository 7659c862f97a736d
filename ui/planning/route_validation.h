// The route check of (planned or hand-edited) routes as the map, the table and the Problems dock
// show it: the core's mission::checkRoute against the current mission, in Qt strings.
#pragma once

#include "core/mission/mission.h"
#include "core/mission/route_check.h"
#include "core/route/waypoint.h"

#include <QString>

#include <vector>

namespace pf::ui {

struct RouteIssues {
    // Per waypoint: empty when fine, else the reason in words ("inside no-fly zone Warehouse").
    std::vector<QString> waypoint;
    // Per leg i (waypoint i -> i + 1): empty when fine, else the reason.
    std::vector<QString> leg;
    QString fromHome; // the leg from take-off to the first waypoint
    QString toHome;   // the leg from the last waypoint back home
    mission::RouteCheck check; // the core's result (notes such as waypoints outside the area)
    int count() const { return check.count(); }
};

// Checks every waypoint and leg of `route` against the mission's no-fly zones grown by
// options.safetyMarginM and the altitude limits (mission::checkRoute, as export and the CLI do).
RouteIssues validateRoute(const mission::Mission& mission, const route::Route& route);

} // namespace pf::ui
