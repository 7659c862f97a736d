// RemoveWaypointsCommand: delete one or several waypoints of a route.
#pragma once

#include "ui/commands/route_edit_command.h"

#include <QList>

namespace pf::ui {

class RemoveWaypointsCommand : public RouteEditCommand {
public:
    RemoveWaypointsCommand(MissionDocument* doc, int routeIndex, QList<int> waypoints,
                           QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
