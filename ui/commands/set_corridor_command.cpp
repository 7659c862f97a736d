#include "ui/commands/set_corridor_command.h"

namespace pf::ui {

SetCorridorCommand::SetCorridorCommand(MissionDocument* doc,
                                       std::optional<mission::Corridor> corridor,
                                       const QString& text, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_doc(doc), m_old(doc->mission().corridor),
      m_new(std::move(corridor)), m_oldArea(doc->mission().area) {}

void SetCorridorCommand::redo() {
    m_doc->setCorridor(m_new);
}

void SetCorridorCommand::undo() {
    m_doc->setCorridor(m_old);
    if (!m_old)
        m_doc->setArea(m_oldArea);
}

} // namespace pf::ui
