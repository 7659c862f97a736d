#include "ui/commands/remove_aircraft_command.h"

#include <QCoreApplication>

namespace pf::ui {

RemoveAircraftCommand::RemoveAircraftCommand(MissionDocument* doc, int index, QUndoCommand* parent)
    : QUndoCommand(parent), m_doc(doc), m_index(index), m_aircraft(doc->mission().aircraft.at(std::size_t(index))) {
    setText(QCoreApplication::translate("Commands", "Remove aircraft %1").arg(QString::fromStdString(m_aircraft.name)));
}

void RemoveAircraftCommand::redo() { m_doc->removeAircraft(m_index); }

void RemoveAircraftCommand::undo() { m_doc->insertAircraft(m_index, m_aircraft); }

} // namespace pf::ui
