#include "ui/planning/route_validation.h"

namespace pf::ui {

RouteIssues validateRoute(const mission::Mission& mission, const route::Route& route) {
    RouteIssues out;
    out.check = mission::checkRoute(route, mission::routeLimits(mission, route));
    for (const auto& s : out.check.waypoint)
        out.waypoint.push_back(QString::fromStdString(s));
    for (const auto& s : out.check.leg)
        out.leg.push_back(QString::fromStdString(s));
    out.fromHome = QString::fromStdString(out.check.fromHome);
    out.toHome = QString::fromStdString(out.check.toHome);
    return out;
}

} // namespace pf::ui
