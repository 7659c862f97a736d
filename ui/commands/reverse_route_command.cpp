#include "ui/commands/reverse_route_command.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace pf::ui {

ReverseRouteCommand::ReverseRouteCommand(MissionDocument* doc, int routeIndex, QUndoCommand* parent)
    : RouteEditCommand(doc, routeIndex, QCoreApplication::translate("Commands", "Reverse path"),
                       parent) {
    std::reverse(m_new.waypoints.begin(), m_new.waypoints.end());
    // The camera faces the direction of travel: flown backwards, every heading turns round.
    for (auto& w : m_new.waypoints)
        w.headingDeg = std::fmod(w.headingDeg + 180.0, 360.0);
}

} // namespace pf::ui
