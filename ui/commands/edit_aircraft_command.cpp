#include "ui/commands/edit_aircraft_command.h"

#include <QCoreApplication>

namespace pf::ui {

EditAircraftCommand::EditAircraftCommand(MissionDocument* doc, int index, mission::AircraftConfig updated,
                                         const QString& field, QUndoCommand* parent)
    : QUndoCommand(QCoreApplication::translate("Commands", "Change %1 of %2")
                       .arg(field, QString::fromStdString(updated.name)),
                   parent),
      m_doc(doc), m_index(index), m_field(field), m_old(doc->mission().aircraft.at(std::size_t(index))),
      m_new(std::move(updated)) {}

void EditAircraftCommand::redo() { m_doc->setAircraft(m_index, m_new); }

void EditAircraftCommand::undo() { m_doc->setAircraft(m_index, m_old); }

bool EditAircraftCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const EditAircraftCommand*>(other);
    if (o->m_doc != m_doc || o->m_index != m_index || o->m_field != m_field) return false;
    m_new = o->m_new;
    return true;
}

} // namespace pf::ui
