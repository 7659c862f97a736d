// EditAircraftCommand: change the settings of one aircraft (camera, altitude/GSD, overlap, speed, ...).
#pragma once

#include "ui/mission_document.h"

#include <QUndoCommand>

namespace pf::ui {

class EditAircraftCommand : public QUndoCommand {
public:
    // `field` names what changed ("altitude", "speed", ...); consecutive edits of the same field of the
    // same aircraft merge into one undo step, so spinning a box does not flood the history.
    EditAircraftCommand(MissionDocument* doc, int index, mission::AircraftConfig updated, const QString& field,
                        QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;
    int id() const override { return 0x41c; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    MissionDocument* m_doc;
    int m_index;
    QString m_field;
    mission::AircraftConfig m_old;
    mission::AircraftConfig m_new;
};

} // namespace pf::ui
