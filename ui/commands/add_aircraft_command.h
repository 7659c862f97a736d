// AddAircraftCommand: add an aircraft (from the catalog or custom) to the mission.
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

namespace pf::ui {

class AddAircraftCommand : public QUndoCommand {
public:
    AddAircraftCommand(MissionDocument* doc, mission::AircraftConfig aircraft, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    MissionDocument* m_doc;
    mission::AircraftConfig m_aircraft;
    int m_index;
};

} // namespace pf::ui
