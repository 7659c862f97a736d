// UploadDialog (Ground station > Connect and Upload): per aircraft a connection, a system id and
// the battery whose flight is sent (a mission is one sortie), the export options that shape the
// mission, then parallel uploads with each vehicle's progress, identity and answer.
#pragma once

#include "core/io/export_context.h"

#include <QDialog>

#include <map>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QDialogButtonBox;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSettings;
class QSpinBox;
class QStringList;
class QTableWidget;

namespace pf::ui {

class MissionDocument;
class UploadManager;

class UploadDialog : public QDialog {
    Q_OBJECT
public:
    // `sent` (optional, kept by the caller across dialogs) holds per aircraft the last sortie
    // uploaded and verified (1-based): the next one is offered first.
    explicit UploadDialog(MissionDocument* doc, QWidget* parent = nullptr,
                          std::map<QString, int>* sent = nullptr);

    // The row of an aircraft's route, for tests and scripted use.
    void setConnection(int row, const QString& connection, int systemId);
    // The battery whose flight the row sends (0-based), and how many the aircraft needs.
    void setSortie(int row, int sortie);
    int sortie(int row) const;
    int sortieCount(int row) const;
    // Starts the uploads of the ticked rows; false (and the reason shown) when nothing can start.
    bool startUpload();
    io::ExportOptions exportOptions() const;
    bool isRunning() const;
    QString rowResult(int row) const;

signals:
    void uploadsFinished(int succeeded, int failed);

private:
    struct Row {
        QCheckBox* use;
        QComboBox* sortie; // one item per battery
        QComboBox* connection;
        QSpinBox* systemId;
        QProgressBar* progress;
        QLabel* answer;
    };
    void buildTable();
    void addVehicleRow(int row, const route::Route& route, const io::ExportContext& ctx,
                       const QSettings& settings, const QStringList& ports);
    QGroupBox* buildOptions();
    QDialogButtonBox* buildButtons();
    void connectManager();
    void refreshRow(int job);
    void saveSettings() const;

    MissionDocument* m_doc;
    UploadManager* m_manager;
    QTableWidget* m_table;
    std::vector<Row> m_rows;
    std::vector<int> m_jobRow; // job index -> table row
    std::map<QString, int>* m_sent;
    QStringList m_warnings; // flights over an autopilot's item limit, shown with the status
    QComboBox* m_gimbal;
    QComboBox* m_trigger;
    QComboBox* m_end;
    QDoubleSpinBox* m_landingHeading; // a plane's; the minimum: unset
    QLabel* m_status;
    QPushButton* m_upload;
    QPushButton* m_cancel;
};

} // namespace pf::ui
