// InsertVertexCommand: add a vertex on an edge of the area or a no-fly zone.
#pragma once

#include "ui/commands/shape_edit_command.h"

namespace pf::ui {

class InsertVertexCommand : public ShapeEditCommand {
public:
    // The new vertex becomes `at.index` of ring `at.ring` (inserted before the old vertex there).
    InsertVertexCommand(MissionDocument* doc, ShapeRef ref, VertexRef at, geo::LonLat position,
                        QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
