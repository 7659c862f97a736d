// Re-validation of (hand-edited) routes against the mission's no-fly zones and their safety margin.
#pragma once

#include "core/mission/mission.h"
#include "core/route/waypoint.h"

#include <QString>

#include <vector>

namespace pf::ui {

struct RouteIssues {
    // Per waypoint: empty when fine, else the reason in words ("inside the safety margin of
    // Warehouse").
    std::vector<QString> waypoint;
    // Per leg i (waypoint i -> i + 1): empty when fine, else the reason.
    std::vector<QString> leg;
    int count() const;
};

// Checks every waypoint and leg of `route` against the mission's no-fly zones grown by
// options.safetyMarginM (the same rule the planner keeps: core's route::NoFlyField).
RouteIssues validateRoute(const mission::Mission& mission, const route::Route& route);

} // namespace pf::ui
