#include "ui/commands/set_waypoint_altitude_command.h"

#include <QCoreApplication>

namespace pf::ui {

SetWaypointAltitudeCommand::SetWaypointAltitudeCommand(MissionDocument* doc, int routeIndex,
                                                       QList<int> waypoints, double altitudeM,
                                                       QUndoCommand* parent)
    : RouteEditCommand(
          doc, routeIndex,
          QCoreApplication::translate("Commands", "Set altitude %1 m").arg(altitudeM, 0, 'f', 1),
          parent) {
    // An empty selection means every waypoint.
    if (waypoints.isEmpty())
        for (int i = 0; i < int(m_new.waypoints.size()); ++i)
            waypoints.append(i);
    for (int i : waypoints)
        if (i >= 0 && i < int(m_new.waypoints.size()))
            m_new.waypoints[std::size_t(i)].altitudeM = altitudeM;
}

} // namespace pf::ui
