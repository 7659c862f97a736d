// ShapeEditCommand: the shared mechanics of commands that replace one polygon of the mission.
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

namespace pf::ui {

// A vertex of a shape: ring 0 is the outer ring, ring k > 0 is hole k - 1.
struct VertexRef {
    int ring = 0;
    int index = 0;
};

// geo::GeoRing of `poly` addressed by `ring` (0 outer, k hole k - 1).
geo::GeoRing& ringOf(geo::GeoPolygon& poly, int ring);

// Subclasses compute the new polygon in their constructor; the old one is captured here.
class ShapeEditCommand : public QUndoCommand {
public:
    ShapeEditCommand(MissionDocument* doc, ShapeRef ref, const QString& text, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

protected:
    MissionDocument* m_doc;
    ShapeRef m_ref;
    geo::GeoPolygon m_old;
    geo::GeoPolygon m_new;
};

} // namespace pf::ui
