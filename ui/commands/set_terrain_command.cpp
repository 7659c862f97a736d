#include "ui/commands/set_terrain_command.h"

namespace pf::ui {

SetTerrainCommand::SetTerrainCommand(MissionDocument* doc, mission::TerrainOptions terrain, const QString& text,
                                     QUndoCommand* parent)
    : QUndoCommand(text, parent), m_doc(doc), m_old(doc->mission().terrain), m_new(std::move(terrain)) {}

void SetTerrainCommand::redo() { m_doc->setTerrain(m_new); }

void SetTerrainCommand::undo() { m_doc->setTerrain(m_old); }

} // namespace pf::ui
