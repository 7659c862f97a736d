// ExportDialog: choose formats, aircraft, folder and autopilot options, then write the waypoint
// files.
#pragma once

#include "ui/planning/route_export.h"

#include <QDialog>
#include <QPointer>

#include <map>

class QCheckBox;
class QComboBox;
class QLabel;
class QDoubleSpinBox;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QVBoxLayout;

namespace pf::ui {

class MissionDocument;
class PlanController;

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    ExportDialog(MissionDocument* doc, PlanController* planner, const QString& folder,
                 QWidget* parent = nullptr);

    // What the controls ask for.
    ExportRequest request() const;
    // Writes the files and lists them (or the error) in the dialog; returns the paths written.
    // Never writes silently what the user would not expect: an outdated plan asks first (default:
    // wait for the new plan, then export), routes with errors are listed and need a confirmation.
    QStringList runExport();
    // Waiting for the new plan before exporting.
    bool isWaiting() const { return m_waiting; }
    // The banner above the controls ("Outdated plan: …", route problems); empty when hidden.
    QString bannerText() const;
    QPushButton* exportButton() const { return m_exportButton; }
    // The window listing what the last export wrote (summary line, warnings, notes, files); empty
    // when it is closed or nothing was written.
    QString resultText() const;

signals:
    // After an export that ran (the files written, or the error), e.g. one that waited for a plan.
    void exported(const QStringList& written);

private:
    // ---- what is confirmed before writing (plan state, route check)
    bool confirmCurrentPlan();
    bool confirmRouteErrors(const QStringList& problems);
    void onPlanStateChanged();
    void refreshBanner();
    void rebuildRouteBoxes();
    void report(const QStringList& written, const QString& error, const QStringList& notes,
                const QStringList& warnings);
    void showWritten(const QStringList& written, const QStringList& notes,
                     const QStringList& warnings);

    MissionDocument* m_doc;
    PlanController* m_planner;
    QLabel* m_banner;
    QVBoxLayout* m_routeLayout;
    QPushButton* m_exportButton;
    bool m_waiting = false;
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
    QDoubleSpinBox* m_landingHeading; // a plane's; the minimum: unset
    QPlainTextEdit* m_report;
    QPointer<QDialog> m_result;
};

} // namespace pf::ui
