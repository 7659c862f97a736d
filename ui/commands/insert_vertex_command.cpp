#include "ui/commands/insert_vertex_command.h"

#include <QCoreApplication>

namespace pf::ui {

InsertVertexCommand::InsertVertexCommand(MissionDocument* doc, ShapeRef ref, VertexRef at, geo::LonLat position,
                                         QUndoCommand* parent)
    : ShapeEditCommand(doc, ref, QCoreApplication::translate("Commands", "Insert vertex"), parent) {
    auto& ring = ringOf(m_new, at.ring);
    ring.insert(ring.begin() + std::clamp<std::ptrdiff_t>(at.index, 0, std::ptrdiff_t(ring.size())), position);
}

} // namespace pf::ui
