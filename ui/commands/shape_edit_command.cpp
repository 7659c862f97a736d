#include "ui/commands/shape_edit_command.h"

namespace pf::ui {

geo::GeoRing& ringOf(geo::GeoPolygon& poly, int ring) {
    return ring == 0 ? poly.outer : poly.holes.at(std::size_t(ring - 1));
}

ShapeEditCommand::ShapeEditCommand(MissionDocument* doc, ShapeRef ref, const QString& text, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_doc(doc), m_ref(ref), m_old(doc->shape(ref)), m_new(m_old) {}

void ShapeEditCommand::redo() { m_doc->setShape(m_ref, m_new); }

void ShapeEditCommand::undo() { m_doc->setShape(m_ref, m_old); }

} // namespace pf::ui
