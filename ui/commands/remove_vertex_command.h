// RemoveVertexCommand: delete one vertex of the area or a no-fly zone.
#pragma once

#include "ui/commands/shape_edit_command.h"

namespace pf::ui {

class RemoveVertexCommand : public ShapeEditCommand {
public:
    RemoveVertexCommand(MissionDocument* doc, ShapeRef ref, VertexRef vertex, QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
