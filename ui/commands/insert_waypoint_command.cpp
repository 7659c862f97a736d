#include "ui/commands/insert_waypoint_command.h"

#include <QCoreApplication>

#include <algorithm>

namespace pf::ui {

InsertWaypointCommand::InsertWaypointCommand(MissionDocument* doc, int routeIndex, int at,
                                             route::Waypoint waypoint, QUndoCommand* parent)
    : RouteEditCommand(doc, routeIndex, QCoreApplication::translate("Commands", "Insert waypoint"),
                       parent) {
    const int i = std::clamp(at, 0, int(m_new.waypoints.size()));
    m_new.waypoints.insert(m_new.waypoints.begin() + i, waypoint);
}

} // namespace pf::ui
