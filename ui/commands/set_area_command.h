// SetAreaCommand: replace the area of interest (drawn, imported or deleted).
#pragma once

#include "ui/commands/shape_edit_command.h"

namespace pf::ui {

class SetAreaCommand : public ShapeEditCommand {
public:
    SetAreaCommand(MissionDocument* doc, const geo::GeoPolygon& area, const QString& text,
                   QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
