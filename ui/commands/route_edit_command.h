// RouteEditCommand: the shared mechanics of commands that change one planned route by hand.
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

#include <optional>

namespace pf::ui {

// Subclasses compute the new route in their constructor from `m_new` (a copy of the current one);
// redo() stores it marked as edited, undo() restores the old route and its mark. A command recorded
// against routes that a new plan has since replaced becomes obsolete rather than bringing back a
// route of the old plan.
class RouteEditCommand : public QUndoCommand {
public:
    RouteEditCommand(MissionDocument* doc, int routeIndex, const QString& text,
                     QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

protected:
    MissionDocument* m_doc;
    int m_index;
    int m_generation;
    std::optional<MissionDocument::PlannedRoute> m_old; // nullopt: the command appends a route
    route::Route m_new;
};

} // namespace pf::ui
