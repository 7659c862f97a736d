// MoveWaypointCommand: drag one waypoint of a route to a new position.
#pragma once

#include "ui/commands/route_edit_command.h"

namespace pf::ui {

class MoveWaypointCommand : public RouteEditCommand {
public:
    MoveWaypointCommand(MissionDocument* doc, int routeIndex, int waypoint, geo::LonLat to,
                        QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
