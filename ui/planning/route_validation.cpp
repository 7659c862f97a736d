#include "ui/planning/route_validation.h"

#include "core/geo/local_frame.h"
#include "core/route/safety.h"

#include <QCoreApplication>

namespace pf::ui {

int RouteIssues::count() const {
    int n = 0;
    for (const auto& s : waypoint)
        n += s.isEmpty() ? 0 : 1;
    for (const auto& s : leg)
        n += s.isEmpty() ? 0 : 1;
    return n;
}

RouteIssues validateRoute(const mission::Mission& mission, const route::Route& route) {
    RouteIssues out;
    const std::size_t n = route.waypoints.size();
    out.waypoint.resize(n);
    out.leg.resize(n > 0 ? n - 1 : 0);
    if (mission.noFlyZones.empty() || mission.area.outer.size() < 3)
        return out;
    auto frame = geo::LocalFrame::forArea(mission.area);
    if (!frame)
        return out;
    const double margin = mission.options.safetyMarginM;
    // One field per zone, so the reason can name the zone.
    std::vector<route::NoFlyField> fields;
    for (const auto& z : mission.noFlyZones)
        fields.emplace_back(std::vector<geo::Polygon>{frame->toLocal(z.polygon)}, margin);
    auto name = [&](std::size_t z) { return QString::fromStdString(mission.noFlyZones[z].name); };
    std::vector<geo::Vec2> local(n);
    for (std::size_t i = 0; i < n; ++i)
        local[i] = frame->toLocal(route.waypoints[i].position);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t z = 0; z < fields.size(); ++z) {
            const double c = fields[z].clearance(local[i]);
            if (c <= 0.0) {
                out.waypoint[i] =
                    QCoreApplication::translate("Validation", "inside no-fly zone %1").arg(name(z));
                break;
            }
            if (!fields[z].isSafeClearance(c)) {
                out.waypoint[i] = QCoreApplication::translate(
                                      "Validation", "%1 m from no-fly zone %2 (margin %3 m)")
                                      .arg(c, 0, 'f', 1)
                                      .arg(name(z))
                                      .arg(margin, 0, 'f', 1);
                break;
            }
        }
    }
    for (std::size_t i = 0; i + 1 < n; ++i) {
        for (std::size_t z = 0; z < fields.size(); ++z) {
            if (!fields[z].segmentIsSafe(local[i], local[i + 1])) {
                out.leg[i] = QCoreApplication::translate(
                                 "Validation", "leg to waypoint %1 crosses no-fly zone %2")
                                 .arg(i + 2)
                                 .arg(name(z));
                break;
            }
        }
    }
    return out;
}

} // namespace pf::ui
