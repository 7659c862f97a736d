// MoveShapeCommand: move the whole area or a no-fly zone by a drag on the map.
#pragma once

#include "ui/commands/shape_edit_command.h"

#include <QPointF>

namespace pf::ui {

class MoveShapeCommand : public ShapeEditCommand {
public:
    // `sceneDelta` is the drag in map-scene metres (Web Mercator), so the shape keeps its on-screen form.
    MoveShapeCommand(MissionDocument* doc, ShapeRef ref, QPointF sceneDelta, QUndoCommand* parent = nullptr);
};

} // namespace pf::ui
