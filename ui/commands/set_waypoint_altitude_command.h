// SetWaypointAltitudeCommand: one altitude for the selected (or all) waypoints of a route.
#pragma once

#include "ui/commands/route_edit_command.h"

#include <QList>

namespace pf::ui {

class SetWaypointAltitudeCommand : public RouteEditCommand {
public:
    SetWaypointAltitudeCommand(MissionDocument* doc, int routeIndex, QList<int> waypoints,
                               double altitudeM, QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
