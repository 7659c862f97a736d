// MainWindow: the application's main window: map, tools, docks, menus, documents and base maps.
#pragma once

#include "core/io/catalog.h"
#include "ui/mission_files.h"

#include <QMainWindow>

#include <map>
#include <memory>

class QAction;
class QActionGroup;
class QDockWidget;
class QGraphicsScene;
class QLabel;
class QMenu;

namespace pf::ui {

class AbstractTool;
class AircraftPanel;
class Autosave;
class GroundStation;
class MapView;
class MissionDocument;
class MissionLayer;
class MissionPanel;
class MosaicController;
class TerrainController;
class PlanController;
class PlanLayer;
class PlanProgressWidget;
class PlanningToolBar;
class ProblemsPanel;
class StatisticsPanel;
class WaypointPanel;
class TileLayer;
class TileSource;

enum class ToolId { Pan, Select, DrawArea, DrawNoFly, DrawCircle, DrawCorridor, Home, Waypoints };

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // `interactive` false: no dialog is ever shown (tests, --screenshot); errors go to the status bar.
    explicit MainWindow(QWidget* parent = nullptr, bool interactive = true);
    ~MainWindow() override;

    MissionDocument* document() const { return m_doc; }
    MapView* mapView() const { return m_view; }
    TileLayer* tileLayer() const { return m_tiles; }
    MissionLayer* missionLayer() const { return m_layer; }
    AircraftPanel* aircraftPanel() const { return m_aircraft; }
    GroundStation* groundStation() const { return m_ground; }
    Autosave* autosave() const { return m_autosave.get(); }
    PlanController* planController() const { return m_planner; }
    PlanProgressWidget* planProgress() const { return m_progress; }
    PlanLayer* planLayer() const { return m_planLayer; }
    WaypointPanel* waypointPanel() const { return m_waypoints; }
    StatisticsPanel* statisticsPanel() const { return m_statistics; }
    ProblemsPanel* problemsList() const { return m_problemList; }
    MosaicController* mosaicController() const { return m_mosaic; }
    TerrainController* terrainController() const { return m_terrain; }
    // The bar saying a new plan waits because routes were edited by hand.
    bool planNoticeVisible() const;
    AbstractTool* tool(ToolId id) const;
    void setTool(ToolId id);

    // File work is MissionFiles' (see there); these forward to it.
    void startup(const QString& missionPath);
    bool openMission(const QString& path, QString* error = nullptr);
    bool openDemoMission(QString* error = nullptr);
    bool saveMission(const QString& path, QString* error = nullptr);
    void newMission();

    using ImportRole = pf::ui::ImportRole;
    int importAreas(const QString& path, ImportRole role = ImportRole::Ask, QString* error = nullptr);

    // "demo", "osm" or a raster file path.
    bool setBaseMap(const QString& id, QString* error = nullptr);
    QString baseMapId() const { return m_baseMapId; }

    // Plan button / F5 (see PlanningToolBar::planNow).
    void planNow();
    // The new plan that waited for the user replaces the edited routes.
    void replaceEditedPaths();
    int openWaypointFile(const QString& path, int assignTo = -1, QString* error = nullptr);
    void showExportDialog();

    void zoomToMission();
    // Repaints until every visible tile is drawn from its own zoom level (or the timeout passes).
    bool waitForMap(int timeoutMs);
    // The status bar's message, else the current tool's hint or message.
    QString statusText() const;

protected:
    void closeEvent(QCloseEvent* e) override;

private:
    // The menus and tool bars (main_window_actions.cpp): a builder per menu, in menu bar order.
    struct BarActions;
    void buildActions();
    void buildUndoRedoActions(BarActions& bar);
    void buildFileMenu(BarActions& bar);
    void buildEditMenu(BarActions& bar);
    void buildToolsMenu();
    void buildViewMenu(BarActions& bar);
    void buildBaseMapMenu();
    void buildGroundStationMenu(BarActions& bar);
    void buildToolBars(const BarActions& bar);
    void buildDocks();
    // A dock (object name `name`) holding `widget`, added to `area`.
    QDockWidget* addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area);
    void updateTitle();
    void showError(const QString& title, const QString& message);
    void openDropped(const QStringList& paths);
    void onViewChanged();
    void buildPlanning();
    void showHint(const QString& text);

    bool m_interactive;
    MissionDocument* m_doc;
    QGraphicsScene* m_scene;
    MapView* m_view;
    TileLayer* m_tiles;
    MissionLayer* m_layer;
    GroundStation* m_ground;
    std::unique_ptr<Autosave> m_autosave;
    MissionFiles* m_files = nullptr;
    io::Catalog m_catalog;
    AircraftPanel* m_aircraft = nullptr;
    MissionPanel* m_missionPanel = nullptr;
    std::map<ToolId, AbstractTool*> m_tools;
    std::map<ToolId, QAction*> m_toolActions;
    QActionGroup* m_baseMapGroup = nullptr;
    std::map<QString, QAction*> m_baseMapActions;
    QString m_baseMapId;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QLabel* m_coords;
    QLabel* m_hint = nullptr;
    QAction* m_afterImport = nullptr;
    QLabel* m_scale;
    QLabel* m_mapLabel;
    QLabel* m_problems;
    PlanController* m_planner = nullptr;
    // Per aircraft the last sortie uploaded and verified (1-based), until the routes change: the
    // upload dialog offers the next battery first.
    std::map<QString, int> m_sortiesSent;
    PlanLayer* m_planLayer = nullptr;
    WaypointPanel* m_waypoints = nullptr;
    StatisticsPanel* m_statistics = nullptr;
    ProblemsPanel* m_problemList = nullptr;
    PlanningToolBar* m_planning = nullptr;
    PlanProgressWidget* m_progress = nullptr;
    MosaicController* m_mosaic = nullptr;
    TerrainController* m_terrain = nullptr;
};

} // namespace pf::ui
