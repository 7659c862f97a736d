// AddNoFlyZoneCommand: add a no-fly zone (drawn or imported).
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

namespace pf::ui {

class AddNoFlyZoneCommand : public QUndoCommand {
public:
    // index < 0 appends.
    AddNoFlyZoneCommand(MissionDocument* doc, mission::NoFlyZone zone, int index = -1, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    MissionDocument* m_doc;
    mission::NoFlyZone m_zone;
    int m_index;
};

} // namespace pf::ui
