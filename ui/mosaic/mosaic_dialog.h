// MosaicDialog: File > Build mosaic: choose the photos, the plan, the camera, the resolution and
// the output, then build the mosaic in the background with progress and cancel. Closing the dialog
// while it builds lets the build finish; the mosaic then appears on the map.
#pragma once

#include "core/io/catalog.h"
#include "core/mosaic/mosaic_types.h"

#include <QDialog>
#include <QFutureWatcher>

#include <functional>
#include <memory>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;

namespace pf {
class Progress;
}

namespace pf::ui {

class MosaicDialog : public QDialog {
    Q_OBJECT
public:
    // `currentPlan` gives the plan shown in the main window, if any, when the dialog needs it.
    MosaicDialog(const io::Catalog& catalog,
                 std::function<std::optional<mosaic::PlannedFlight>()> currentPlan,
                 QWidget* parent = nullptr);
    ~MosaicDialog() override;

    // Adds photo files, or every .jpg/.jpeg of a directory (not recursive). Returns the number
    // added.
    int addPhotos(const QStringList& paths);
    void clearPhotos();
    QStringList photos() const;
    void setOutputPath(const QString& path);
    QString outputPath() const;
    // The plan to match against: the main window's current plan, a plan.geojson (or its directory),
    // or none.
    void useCurrentPlan();
    void usePlanFile(const QString& path);
    void useNoPlan();
    void setGsdCm(double cm); // 0: automatic
    void setFeatherM(double m);
    void setCamera(const QString& name); // empty: from the photos' EXIF
    // Match the photos to one aircraft's photo points (and measure coverage over its part of the
    // area); empty: every aircraft of the plan.
    void setAircraft(const QString& name);

    // Starts building (false with the reason in the status line if the choices are incomplete).
    bool start();
    // Asks the running build to stop; it ends with a "cancelled" status.
    void cancel();
    bool isRunning() const { return m_running; }
    // Waits for the running build (tests, closing). False on timeout.
    bool waitForFinished(int timeoutMs);

    QString statusText() const;
    QString reportText() const;
    const std::optional<mosaic::MosaicReport>& lastReport() const { return m_report; }
    QPushButton* buildButton() const { return m_build; }
    QPushButton* cancelButton() const { return m_cancel; }
    QProgressBar* progressBar() const { return m_progress; }

signals:
    // A mosaic was written; the controller puts it on the map.
    void mosaicReady(const pf::mosaic::MosaicReport& report);
    void runningChanged(bool running);

private:
    struct Outcome;
    void browsePhotos();
    void browseFolder();
    void browseOutput();
    void browsePlan();
    void onPlanChoice();
    // The plan the choices point at (null if none or unreadable; `why` says why).
    std::optional<mosaic::PlannedFlight> chosenPlan(QString* why) const;
    void refreshAircraft();
    void onProgress(double fraction, const QString& stage);
    void onFinished();
    void setRunning(bool on);
    void updatePhotoCount();

    const io::Catalog& m_catalog;
    std::function<std::optional<mosaic::PlannedFlight>()> m_currentPlan;
    QListWidget* m_photoList;
    QLabel* m_photoCount;
    QComboBox* m_plan;
    QLineEdit* m_planFile;
    QPushButton* m_planBrowse;
    QComboBox* m_aircraft;
    QComboBox* m_camera;
    QDoubleSpinBox* m_gsd;
    QDoubleSpinBox* m_feather;
    QLineEdit* m_output;
    QProgressBar* m_progress;
    QLabel* m_status;
    QPlainTextEdit* m_reportView;
    QPushButton* m_build;
    QPushButton* m_cancel;
    QPushButton* m_close;
    QFutureWatcher<std::shared_ptr<Outcome>> m_watcher;
    std::shared_ptr<Progress> m_job;
    bool m_running = false;
    std::optional<mosaic::MosaicReport> m_report;
};

} // namespace pf::ui
