#include "ui/commands/add_aircraft_command.h"

#include <QCoreApplication>

namespace pf::ui {

AddAircraftCommand::AddAircraftCommand(MissionDocument* doc, mission::AircraftConfig aircraft, QUndoCommand* parent)
    : QUndoCommand(QCoreApplication::translate("Commands", "Add aircraft %1")
                       .arg(QString::fromStdString(aircraft.name)),
                   parent),
      m_doc(doc), m_aircraft(std::move(aircraft)), m_index(int(doc->mission().aircraft.size())) {}

void AddAircraftCommand::redo() { m_doc->insertAircraft(m_index, m_aircraft); }

void AddAircraftCommand::undo() { m_doc->removeAircraft(m_index); }

} // namespace pf::ui
