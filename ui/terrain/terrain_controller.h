// TerrainController: terrain following in the desktop application, behind File > Terrain model: the
// DEM chosen for the mission (undoable), following on or off, the minimum clearance, and the Terrain
// profile dock (ground, aircraft and clearance along the selected route, with its warnings).
#pragma once

#include <QObject>
#include <QString>

class QComboBox;
class QDockWidget;
class QLabel;
class QMainWindow;
class QMenu;
class QAction;

namespace pf::ui {

class MissionDocument;
class PlanController;
class TerrainProfileWidget;

class TerrainController : public QObject {
    Q_OBJECT
public:
    // `interactive` false: no dialog is shown (tests, --screenshot); errors go to lastError().
    TerrainController(QMainWindow* window, MissionDocument* doc, PlanController* planner, bool interactive);

    QMenu* menu() const { return m_menu; }
    QDockWidget* dock() const { return m_dock; }
    TerrainProfileWidget* profileWidget() const { return m_profile; }
    QLabel* summaryLabel() const { return m_summary; }
    QComboBox* aircraftBox() const { return m_aircraft; }

    // Checks that GDAL reads `path` as a terrain model, then makes it the mission's DEM with terrain
    // following on (one undoable edit). False, with the reason in lastError(), when it cannot be read.
    bool useDem(const QString& path);
    void setFollow(bool on);
    void setMinClearance(double metres);
    void removeDem();
    QString lastError() const { return m_error; }

private:
    void refresh();
    void chooseDem();
    void askClearance();

    QMainWindow* m_window;
    MissionDocument* m_doc;
    PlanController* m_planner;
    bool m_interactive;
    QString m_error;
    QMenu* m_menu = nullptr;
    QAction* m_followAct = nullptr;
    QAction* m_clearanceAct = nullptr;
    QAction* m_removeAct = nullptr;
    QDockWidget* m_dock = nullptr;
    QComboBox* m_aircraft = nullptr;
    QLabel* m_summary = nullptr;
    TerrainProfileWidget* m_profile = nullptr;
};

} // namespace pf::ui
