#include "ui/commands/set_home_command.h"

#include <QCoreApplication>

namespace pf::ui {

SetHomeCommand::SetHomeCommand(MissionDocument* doc, std::optional<geo::LonLat> home, QUndoCommand* parent)
    : QUndoCommand(home ? QCoreApplication::translate("Commands", "Set home point")
                        : QCoreApplication::translate("Commands", "Clear home point"),
                   parent),
      m_doc(doc), m_old(doc->mission().home), m_new(home) {}

void SetHomeCommand::redo() { m_doc->setHome(m_new); }

void SetHomeCommand::undo() { m_doc->setHome(m_old); }

} // namespace pf::ui
