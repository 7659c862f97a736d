#include "ui/commands/edit_waypoint_command.h"

#include <QCoreApplication>

namespace pf::ui {

EditWaypointCommand::EditWaypointCommand(MissionDocument* doc, int routeIndex, int waypoint,
                                         route::Waypoint updated, QUndoCommand* parent)
    : RouteEditCommand(
          doc, routeIndex,
          QCoreApplication::translate("Commands", "Edit waypoint %1").arg(waypoint + 1), parent) {
    if (waypoint >= 0 && waypoint < int(m_new.waypoints.size()))
        m_new.waypoints[std::size_t(waypoint)] = updated;
}

} // namespace pf::ui
