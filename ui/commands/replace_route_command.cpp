#include "ui/commands/replace_route_command.h"

#include <QCoreApplication>

namespace pf::ui {

ReplaceRouteCommand::ReplaceRouteCommand(MissionDocument* doc, int routeIndex, route::Route route,
                                         QUndoCommand* parent)
    : RouteEditCommand(doc, routeIndex,
                       QCoreApplication::translate("Commands", "Load route of %1")
                           .arg(QString::fromStdString(route.aircraft)),
                       parent) {
    m_new = std::move(route);
}

} // namespace pf::ui
