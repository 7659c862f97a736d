#include "ui/commands/remove_vertex_command.h"

#include <QCoreApplication>

namespace pf::ui {

RemoveVertexCommand::RemoveVertexCommand(MissionDocument* doc, ShapeRef ref, VertexRef vertex, QUndoCommand* parent)
    : ShapeEditCommand(doc, ref, QCoreApplication::translate("Commands", "Delete vertex"), parent) {
    auto& ring = ringOf(m_new, vertex.ring);
    ring.erase(ring.begin() + vertex.index);
}

} // namespace pf::ui
