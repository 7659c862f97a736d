#include "ui/commands/move_vertex_command.h"

#include <QCoreApplication>

namespace pf::ui {

MoveVertexCommand::MoveVertexCommand(MissionDocument* doc, ShapeRef ref, VertexRef vertex, geo::LonLat to,
                                     QUndoCommand* parent)
    : ShapeEditCommand(doc, ref, QCoreApplication::translate("Commands", "Move vertex"), parent) {
    ringOf(m_new, vertex.ring).at(std::size_t(vertex.index)) = to;
}

} // namespace pf::ui
