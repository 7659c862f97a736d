#include "ui/commands/remove_waypoints_command.h"

#include <QCoreApplication>

#include <algorithm>

namespace pf::ui {

RemoveWaypointsCommand::RemoveWaypointsCommand(MissionDocument* doc, int routeIndex,
                                               QList<int> waypoints, QUndoCommand* parent)
    : RouteEditCommand(doc, routeIndex,
                       QCoreApplication::translate("Commands", "Delete %n waypoint(s)", nullptr,
                                                   waypoints.size()),
                       parent) {
    // From the back, so the indices still to remove stay valid.
    std::sort(waypoints.begin(), waypoints.end(), std::greater<int>());
    waypoints.erase(std::unique(waypoints.begin(), waypoints.end()), waypoints.end());
    for (int i : waypoints)
        if (i >= 0 && i < int(m_new.waypoints.size()))
            m_new.waypoints.erase(m_new.waypoints.begin() + i);
}

} // namespace pf::ui
