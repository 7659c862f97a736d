// InsertWaypointCommand: add a waypoint to a route (on a leg, or by the table's Insert).
#pragma once

#include "ui/commands/route_edit_command.h"

namespace pf::ui {

class InsertWaypointCommand : public RouteEditCommand {
public:
    InsertWaypointCommand(MissionDocument* doc, int routeIndex, int at, route::Waypoint waypoint,
                          QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
