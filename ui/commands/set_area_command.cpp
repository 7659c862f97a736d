#include "ui/commands/set_area_command.h"

namespace pf::ui {

SetAreaCommand::SetAreaCommand(MissionDocument* doc, const geo::GeoPolygon& area, const QString& text,
                               QUndoCommand* parent)
    : ShapeEditCommand(doc, ShapeRef::area(), text, parent) {
    m_new = area;
}

} // namespace pf::ui
