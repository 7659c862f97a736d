// ReverseRouteCommand: fly a route the other way round (headings turned by 180 degrees).
#pragma once

#include "ui/commands/route_edit_command.h"

namespace pf::ui {

class ReverseRouteCommand : public RouteEditCommand {
public:
    ReverseRouteCommand(MissionDocument* doc, int routeIndex, QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
