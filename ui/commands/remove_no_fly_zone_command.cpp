#include "ui/commands/remove_no_fly_zone_command.h"

#include <QCoreApplication>

namespace pf::ui {

RemoveNoFlyZoneCommand::RemoveNoFlyZoneCommand(MissionDocument* doc, int index, QUndoCommand* parent)
    : QUndoCommand(QCoreApplication::translate("Commands", "Delete no-fly zone"), parent), m_doc(doc),
      m_index(index), m_zone(doc->mission().noFlyZones.at(std::size_t(index))) {}

void RemoveNoFlyZoneCommand::redo() { m_doc->removeNoFlyZone(m_index); }

void RemoveNoFlyZoneCommand::undo() { m_doc->insertNoFlyZone(m_index, m_zone); }

} // namespace pf::ui
