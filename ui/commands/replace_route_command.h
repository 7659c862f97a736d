// ReplaceRouteCommand: put a whole route in place (an imported waypoint file); routeIndex == count
// appends.
#pragma once

#include "ui/commands/route_edit_command.h"

namespace pf::ui {

class ReplaceRouteCommand : public RouteEditCommand {
public:
    ReplaceRouteCommand(MissionDocument* doc, int routeIndex, route::Route route,
                        QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
