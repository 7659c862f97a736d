// RemoveAircraftCommand: remove an aircraft from the mission.
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

namespace pf::ui {

class RemoveAircraftCommand : public QUndoCommand {
public:
    RemoveAircraftCommand(MissionDocument* doc, int index, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    MissionDocument* m_doc;
    int m_index;
    mission::AircraftConfig m_aircraft;
};

} // namespace pf::ui
