// SetPlannerOptionsCommand: change the mission's planning options (planner, grid angle, margins).
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

namespace pf::ui {

class SetPlannerOptionsCommand : public QUndoCommand {
public:
    SetPlannerOptionsCommand(MissionDocument* doc, mission::PlannerOptions options,
                             const QString& text, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    MissionDocument* m_doc;
    mission::PlannerOptions m_old;
    mission::PlannerOptions m_new;
};

} // namespace pf::ui
