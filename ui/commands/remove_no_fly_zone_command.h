// RemoveNoFlyZoneCommand: delete a no-fly zone.
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

namespace pf::ui {

class RemoveNoFlyZoneCommand : public QUndoCommand {
public:
    RemoveNoFlyZoneCommand(MissionDocument* doc, int index, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    MissionDocument* m_doc;
    int m_index;
    mission::NoFlyZone m_zone;
};

} // namespace pf::ui
