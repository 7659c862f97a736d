// EditWaypointCommand: replace one waypoint (a cell of the waypoint table: position, altitude,
// heading, action).
#pragma once

#include "ui/commands/route_edit_command.h"

namespace pf::ui {

class EditWaypointCommand : public RouteEditCommand {
public:
    EditWaypointCommand(MissionDocument* doc, int routeIndex, int waypoint, route::Waypoint updated,
                        QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
