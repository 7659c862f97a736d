// SetCorridorCommand: draw, replace, widen or delete the corridor (and with it the area, its
// ground).
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

#include <optional>

namespace pf::ui {

class SetCorridorCommand : public QUndoCommand {
public:
    // nullopt deletes the corridor. Undo brings back what was there: a corridor, or an area.
    SetCorridorCommand(MissionDocument* doc, std::optional<mission::Corridor> corridor,
                       const QString& text, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    MissionDocument* m_doc;
    std::optional<mission::Corridor> m_old, m_new;
    geo::GeoPolygon m_oldArea; // the area of an area mission the corridor replaced
};

} // namespace pf::ui
