// SetHomeCommand: set, move or clear the take-off/landing point.
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

namespace pf::ui {

class SetHomeCommand : public QUndoCommand {
public:
    SetHomeCommand(MissionDocument* doc, std::optional<geo::LonLat> home, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    MissionDocument* m_doc;
    std::optional<geo::LonLat> m_old;
    std::optional<geo::LonLat> m_new;
};

} // namespace pf::ui
