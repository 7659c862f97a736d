#include "ui/commands/move_waypoint_command.h"

#include <QCoreApplication>

namespace pf::ui {

MoveWaypointCommand::MoveWaypointCommand(MissionDocument* doc, int routeIndex, int waypoint,
                                         geo::LonLat to, QUndoCommand* parent)
    : RouteEditCommand(
          doc, routeIndex,
          QCoreApplication::translate("Commands", "Move waypoint %1").arg(waypoint + 1), parent) {
    if (waypoint >= 0 && waypoint < int(m_new.waypoints.size()))
        m_new.waypoints[std::size_t(waypoint)].position = to;
}

} // namespace pf::ui
