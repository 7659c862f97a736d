// ExportDialog: choose formats, aircraft, folder and autopilot options, then write the waypoint
// files.
#pragma once

#include "ui/planning/route_export.h"

#include <QDialog>

#include <map>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QPlainTextEdit;

namespace pf::ui {

class MissionDocument;

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    ExportDialog(MissionDocument* doc, const QString& folder, QWidget* parent = nullptr);

    // What the controls ask for.
    ExportRequest request() const;
    // Writes the files and lists them (or the error) in the dialog; returns the paths written.
    QStringList runExport();

private:
    MissionDocument* m_doc;
    std::map<io::WaypointFormat, QCheckBox*> m_formats;
    std::vector<QCheckBox*> m_routes;
    QCheckBox* m_perAircraft;
    QCheckBox* m_combined;
    QLineEdit* m_folder;
    QLineEdit* m_stem;
    QComboBox* m_firmware;
    QComboBox* m_end;
    // MAVLink mission options (.plan, .waypoints): gimbal command, camera trigger, home elevation.
    QComboBox* m_gimbal;
    QComboBox* m_trigger;
    QDoubleSpinBox* m_homeElevation;
    QPlainTextEdit* m_report;
};

} // namespace pf::ui
