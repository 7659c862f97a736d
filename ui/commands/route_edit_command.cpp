#include "ui/commands/route_edit_command.h"

namespace pf::ui {

RouteEditCommand::RouteEditCommand(MissionDocument* doc, int routeIndex, const QString& text,
                                   QUndoCommand* parent)
    : QUndoCommand(text, parent), m_doc(doc), m_index(routeIndex),
      m_generation(doc->routeGeneration()) {
    if (routeIndex >= 0 && routeIndex < int(doc->routes().size())) {
        m_old = doc->routes()[std::size_t(routeIndex)];
        m_new = m_old->route;
    }
}

void RouteEditCommand::redo() {
    if (m_doc->routeGeneration() != m_generation) {
        setObsolete(true);
        return;
    }
    m_doc->setRoute(m_index, MissionDocument::PlannedRoute{m_new, true});
}

void RouteEditCommand::undo() {
    if (m_doc->routeGeneration() != m_generation) {
        setObsolete(true);
        return;
    }
    m_doc->setRoute(m_index, m_old);
}

} // namespace pf::ui
