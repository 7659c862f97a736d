// MoveVertexCommand: drag one vertex of the area or a no-fly zone to a new position.
#pragma once

#include "ui/commands/shape_edit_command.h"

namespace pf::ui {

class MoveVertexCommand : public ShapeEditCommand {
public:
    MoveVertexCommand(MissionDocument* doc, ShapeRef ref, VertexRef vertex, geo::LonLat to,
                      QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
