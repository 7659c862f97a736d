#include "ui/commands/add_no_fly_zone_command.h"

#include <QCoreApplication>

namespace pf::ui {

AddNoFlyZoneCommand::AddNoFlyZoneCommand(MissionDocument* doc, mission::NoFlyZone zone, int index,
                                         QUndoCommand* parent)
    : QUndoCommand(QCoreApplication::translate("Commands", "Add no-fly zone"), parent), m_doc(doc),
      m_zone(std::move(zone)), m_index(index < 0 ? int(doc->mission().noFlyZones.size()) : index) {}

void AddNoFlyZoneCommand::redo() { m_doc->insertNoFlyZone(m_index, m_zone); }

void AddNoFlyZoneCommand::undo() { m_doc->removeNoFlyZone(m_index); }

} // namespace pf::ui
