#include "ui/commands/set_planner_options_command.h"

namespace pf::ui {

SetPlannerOptionsCommand::SetPlannerOptionsCommand(MissionDocument* doc,
                                                   mission::PlannerOptions options,
                                                   const QString& text, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_doc(doc), m_old(doc->mission().options),
      m_new(std::move(options)) {}

void SetPlannerOptionsCommand::redo() {
    m_doc->setOptions(m_new);
}

void SetPlannerOptionsCommand::undo() {
    m_doc->setOptions(m_old);
}

} // namespace pf::ui
