#include "ui/commands/move_shape_command.h"

#include "ui/geo_adapter.h"

#include <QCoreApplication>

namespace pf::ui {

MoveShapeCommand::MoveShapeCommand(MissionDocument* doc, ShapeRef ref, QPointF sceneDelta,
                                   QUndoCommand* parent)
    : ShapeEditCommand(doc, ref,
                       ref.kind == ShapeRef::Kind::Area
                           ? QCoreApplication::translate("Commands", "Move area")
                       : ref.kind == ShapeRef::Kind::Corridor
                           ? QCoreApplication::translate("Commands", "Move corridor")
                           : QCoreApplication::translate("Commands", "Move no-fly zone"),
                       parent) {
    auto move = [&](geo::GeoRing& ring) {
        for (auto& p : ring) p = fromScene(toScene(p) + sceneDelta);
    };
    move(m_new.outer);
    for (auto& h : m_new.holes) move(h);
}

} // namespace pf::ui
