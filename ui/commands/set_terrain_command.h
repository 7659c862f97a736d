// SetTerrainCommand: change the mission's terrain following (DEM, follow or off, minimum clearance).
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

namespace pf::ui {

class SetTerrainCommand : public QUndoCommand {
public:
    SetTerrainCommand(MissionDocument* doc, mission::TerrainOptions terrain, const QString& text,
                      QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    MissionDocument* m_doc;
    mission::TerrainOptions m_old;
    mission::TerrainOptions m_new;
};

} // namespace pf::ui
