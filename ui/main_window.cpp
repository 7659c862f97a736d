#include "ui/main_window.h"

#include "core/io/mission_file.h"
#include "ui/autosave.h"
#include "ui/dialogs/export_dialog.h"
#include "ui/geo_adapter.h"
#include "ui/ground_station.h"
#include "ui/map/base_maps.h"
#include "ui/map/hillshade_layer.h"
#include "ui/map/map_view.h"
#include "ui/map/mission_layer.h"
#include "ui/map/plan_layer.h"
#include "ui/map/tile_layer.h"
#include "ui/mission_document.h"
#include "ui/mission_files.h"
#include "ui/mosaic/mosaic_controller.h"
#include "ui/mosaic/mosaic_panel.h"
#include "ui/panels/aircraft_panel.h"
#include "ui/panels/mission_panel.h"
#include "ui/panels/problems_panel.h"
#include "ui/panels/statistics_panel.h"
#include "ui/panels/waypoint_panel.h"
#include "ui/planning/plan_controller.h"
#include "ui/planning/plan_notice.h"
#include "ui/planning/plan_progress_widget.h"
#include "ui/planning/planning_toolbar.h"
#include "ui/terrain/terrain_controller.h"
#include "ui/tools/draw_circle_tool.h"
#include "ui/tools/draw_corridor_tool.h"
#include "ui/tools/draw_polygon_tool.h"
#include "ui/tools/home_tool.h"
#include "ui/tools/pan_tool.h"
#include "ui/tools/select_tool.h"
#include "ui/tools/waypoint_tool.h"
#include "ui/window_shortcut_guard.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QGraphicsScene>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QUndoView>

#include <cmath>

// Resources of a static library must be registered by name from the global namespace.
static void initIconResources() { Q_INIT_RESOURCE(icons); }

namespace pf::ui {

MainWindow::MainWindow(QWidget* parent, bool interactive) : QMainWindow(parent), m_interactive(interactive) {
    setObjectName(QStringLiteral("MainWindow"));
    initIconResources();
    setWindowIcon(QIcon(QStringLiteral(":/icons/photoflight.svg")));
    m_doc = new MissionDocument(this);
    m_scene = new QGraphicsScene(this);
    // The scene changes as tiles stream in; an index would be rebuilt constantly for a few dozen items.
    m_scene->setItemIndexMethod(QGraphicsScene::NoIndex);
    m_view = new MapView(m_scene, this);
    m_tiles = new TileLayer();
    m_scene->addItem(m_tiles);
    m_layer = new MissionLayer(m_doc, m_scene, this);
    m_planner = new PlanController(m_doc, this);
    m_planLayer = new PlanLayer(m_doc, m_planner, m_scene, this);
    m_ground = new GroundStation(m_scene, this);
    // Autosave period in seconds (setting "autosave/intervalSeconds", default one minute); edits are
    // also saved a few seconds after they happen.
    const int autosaveSeconds = std::max(5, QSettings().value(QStringLiteral("autosave/intervalSeconds"), 60).toInt());
    m_autosave = std::make_unique<Autosave>(m_doc, QString(), autosaveSeconds * 1000);
    m_files = new MissionFiles(this, m_doc, m_autosave.get(), m_interactive);
    connect(m_files, &MissionFiles::missionShown, this, &MainWindow::zoomToMission);
    setCentralWidget(m_view);

    auto catalog = io::loadDefaultCatalog();
    if (catalog) m_catalog = std::move(catalog).value();

    m_tools[ToolId::Pan] = new PanTool(m_doc, m_layer, this);
    m_tools[ToolId::Select] = new SelectTool(m_doc, m_layer, this);
    m_tools[ToolId::DrawArea] = new DrawPolygonTool(DrawPolygonTool::Target::Area, m_doc, m_layer, this);
    m_tools[ToolId::DrawNoFly] = new DrawPolygonTool(DrawPolygonTool::Target::NoFlyZone, m_doc, m_layer, this);
    m_tools[ToolId::DrawCircle] = new DrawCircleTool(m_doc, m_layer, this);
    m_tools[ToolId::DrawCorridor] = new DrawCorridorTool(m_doc, m_layer, this);
    m_tools[ToolId::Home] = new HomeTool(m_doc, m_layer, this);
    m_tools[ToolId::Waypoints] = new WaypointTool(m_doc, m_layer, m_planLayer, this);
    for (auto& [id, tool] : m_tools)
        connect(tool, &AbstractTool::statusMessage, this, &MainWindow::showHint);

    // Tool hints wrap rather than be cut off (a status bar's own message is one line).
    m_hint = new QLabel;
    m_hint->setObjectName(QStringLiteral("HintLabel"));
    m_hint->setWordWrap(true);
    statusBar()->addWidget(m_hint, 1);
    m_coords = new QLabel;
    m_coords->setMinimumWidth(230);
    m_scale = new QLabel;
    m_scale->setMinimumWidth(90);
    m_mapLabel = new QLabel;
    m_problems = new QLabel;
    m_problems->setStyleSheet(QStringLiteral("QLabel { color: #8a4b00; background: #ffe8b0; padding: 1px 6px; "
                                             "border-radius: 3px; }"));
    m_problems->hide();
    statusBar()->addPermanentWidget(m_problems);
    statusBar()->addPermanentWidget(m_mapLabel);
    statusBar()->addPermanentWidget(m_scale);
    statusBar()->addPermanentWidget(m_coords);

    buildActions();
    buildDocks();
    buildPlanning();

    connect(m_view, &MapView::cursorMoved, this, [this](const geo::LonLat& p) { m_coords->setText(formatLonLat(p)); });
    connect(m_view, &MapView::cursorLeft, this, [this] { m_coords->clear(); });
    connect(m_view, &MapView::viewChanged, this, &MainWindow::onViewChanged);
    connect(m_view, &MapView::filesDropped, this, &MainWindow::openDropped);
    connect(m_doc, &MissionDocument::dirtyChanged, this, &MainWindow::updateTitle);
    connect(m_doc, &MissionDocument::routesChanged, this, [this] { m_sortiesSent.clear(); });
    connect(m_doc, &MissionDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_doc, &MissionDocument::changed, this, &MainWindow::updateTitle);
    connect(m_layer, &MissionLayer::problemsChanged, this, [this](const QStringList& problems) {
        // Short, so that the tools' hints keep their room; the Problems dock and the tip say it all.
        m_problems->setText(problems.isEmpty() ? QString()
                                               : QStringLiteral("⚠ ") + tr("%n shape problem(s)", nullptr, int(problems.size())));
        m_problems->setToolTip(problems.join(QLatin1Char('\n')));
        m_problems->setVisible(!problems.isEmpty());
    });
    connect(m_ground, &GroundStation::statusChanged, this, [this](const QString& s) { statusBar()->showMessage(s, 5000); });

    QSettings settings;
    const QString map = settings.value(QStringLiteral("map/source"), QStringLiteral("demo")).toString();
    QString error;
    if (!setBaseMap(map, &error) && map != QLatin1String("demo")) setBaseMap(QStringLiteral("demo"));
    setTool(ToolId::Select);
    updateTitle();
    onViewChanged();
    resize(1400, 900);
    new WindowShortcutGuard(this);
}

MainWindow::~MainWindow() {
    // Reaching the destructor is a clean exit: no autosave is left for recovery.
    m_autosave->removeOwn();
    m_ground->stop();
    m_view->setTool(nullptr);
}

AbstractTool* MainWindow::tool(ToolId id) const { return m_tools.at(id); }

void MainWindow::setTool(ToolId id) {
    m_view->setTool(m_tools.at(id));
    if (auto it = m_toolActions.find(id); it != m_toolActions.end()) it->second->setChecked(true);
}

void MainWindow::buildDocks() {
    setDockNestingEnabled(true);
    m_aircraft = new AircraftPanel(m_doc, m_catalog);
    // The form grows with a plane's figures: it scrolls rather than stretch the window past the
    // screen.
    auto* aircraftScroll = new QScrollArea;
    aircraftScroll->setWidget(m_aircraft);
    aircraftScroll->setWidgetResizable(true);
    aircraftScroll->setFrameShape(QFrame::NoFrame);
    aircraftScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* aircraftDock = addDock(tr("Aircraft"), QStringLiteral("AircraftDock"), aircraftScroll,
                                 Qt::RightDockWidgetArea);
    m_missionPanel = new MissionPanel(m_doc, m_layer);
    auto* missionDock = addDock(tr("Mission"), QStringLiteral("MissionDock"), m_missionPanel, Qt::RightDockWidgetArea);
    connect(m_missionPanel, &MissionPanel::shapeActivated, this, [this](const QRectF& r) {
        m_view->fitSceneRect(r.adjusted(-r.width(), -r.height(), r.width(), r.height()));
    });

    auto* undoView = new QUndoView(m_doc->undoStack());
    undoView->setEmptyLabel(tr("<opened>"));
    auto* historyDock = addDock(tr("History"), QStringLiteral("HistoryDock"), undoView, Qt::RightDockWidgetArea);
    // One column of tabs on the right keeps the map tall; the plan's docks go below it.
    tabifyDockWidget(aircraftDock, missionDock);
    tabifyDockWidget(missionDock, historyDock);
    aircraftDock->raise();
    resizeDocks({aircraftDock}, {360}, Qt::Horizontal);

    m_viewMenu->addAction(aircraftDock->toggleViewAction());
    m_viewMenu->addAction(missionDock->toggleViewAction());
    m_viewMenu->addAction(historyDock->toggleViewAction());
    // The Mosaic dock: a tab on the right too, hidden until a mosaic is shown.
    m_viewMenu->addAction(m_mosaic->createPanel()->toggleViewAction());
}

QDockWidget* MainWindow::addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setWidget(widget);
    addDockWidget(area, dock);
    return dock;
}

void MainWindow::updateTitle() {
    setWindowTitle(QStringLiteral("%1[*] — Photoflight").arg(m_doc->displayName()));
    setWindowModified(m_doc->isDirty());
}

void MainWindow::onViewChanged() {
    const double mpp = m_view->metresPerPixel();
    m_layer->setMetresPerPixel(mpp);
    m_ground->setMetresPerPixel(mpp);
    m_planLayer->setMetresPerPixel(mpp);
    const double ground = m_view->groundMetresPerPixel();
    m_scale->setText(ground < 1 ? tr("%1 cm/px").arg(ground * 100, 0, 'f', 1) : tr("%1 m/px").arg(ground, 0, 'f', 2));
}

void MainWindow::showError(const QString& title, const QString& message) {
    reportError(this, m_interactive, title, message);
}

QString MainWindow::statusText() const {
    return statusBar()->currentMessage().isEmpty() ? m_hint->text() : statusBar()->currentMessage();
}

void MainWindow::showHint(const QString& text) {
    statusBar()->clearMessage();
    m_hint->setText(text);
}

void MainWindow::startup(const QString& missionPath) { m_files->startup(missionPath); }
bool MainWindow::openMission(const QString& path, QString* error) { return m_files->openMission(path, error); }
bool MainWindow::openDemoMission(QString* error) { return m_files->openDemoMission(error); }
bool MainWindow::saveMission(const QString& path, QString* error) { return m_files->saveMission(path, error); }
void MainWindow::newMission() { m_files->newMission(); }
int MainWindow::importAreas(const QString& path, ImportRole role, QString* error) {
    return m_files->importAreas(path, role, error);
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!m_files->maybeSave()) {
        e->ignore();
        return;
    }
    m_autosave->removeOwn();
    e->accept();
}

void MainWindow::openDropped(const QStringList& paths) {
    for (const QString& path : paths) {
        if (looksLikeRasterMap(path)) {
            QString error;
            if (!setBaseMap(path, &error)) showError(tr("Base map"), error);
            continue;
        }
        // A mission file opens as the document; anything else is read as polygons.
        if (path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive)) {
            auto m = io::readMissionFile(path.toStdString());
            if (m) {
                if (m_files->maybeSave()) openMission(path);
                continue;
            }
        }
        importAreas(path, ImportRole::Ask);
    }
}

bool MainWindow::setBaseMap(const QString& id, QString* error) {
    std::shared_ptr<TileSource> source;
    QString why;
    if (id == QLatin1String("demo"))
        source = openDemoMap(&why);
    else if (id == QLatin1String("osm"))
        source = openOpenStreetMap(&why);
    else if (id != QLatin1String("none"))
        source = openMapFile(id, &why);
    if (!source && id != QLatin1String("none")) {
        if (error) *error = why;
        statusBar()->showMessage(why, 8000);
        if (auto it = m_baseMapActions.find(m_baseMapId); it != m_baseMapActions.end()) it->second->setChecked(true);
        return false;
    }
    m_tiles->setSource(source);
    m_baseMapId = id;
    m_view->setAttribution(source ? source->attribution() : QString());
    m_mapLabel->setText(source ? source->name() : tr("No base map"));
    if (auto it = m_baseMapActions.find(id); it != m_baseMapActions.end()) it->second->setChecked(true);
    else if (m_baseMapGroup && m_baseMapGroup->checkedAction()) m_baseMapGroup->checkedAction()->setChecked(false);
    QSettings().setValue(QStringLiteral("map/source"), id);
    return true;
}

void MainWindow::zoomToMission() {
    QRectF r = m_layer->missionBounds();
    if (r.isEmpty() || r.width() < 1e-2) {
        if (auto src = m_tiles->source()) r = src->coverage();
    }
    if (r.isEmpty()) return;
    const double pad = std::max(r.width(), r.height()) * 0.08;
    m_view->fitSceneRect(r.adjusted(-pad, -pad, pad, pad));
}

bool MainWindow::waitForMap(int timeoutMs) {
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < timeoutMs) {
        // Rendering is what asks for tiles; a complete render with nothing pending is the goal.
        m_view->viewport()->grab();
        if (m_tiles->pendingCount() == 0 && m_tiles->lastMissingCount() == 0) return true;
        QEventLoop loop;
        QTimer::singleShot(30, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return false;
}

// ---------------------------------------------------------------- planning, viewing, editing

void MainWindow::buildPlanning() {
    auto icon = [](const char* name) { return QIcon(QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name))); };

    // Actions: Plan menu and tool bar.
    QMenu* planMenu = menuBar()->addMenu(tr("&Plan"));
    // The menu goes before Help.
    menuBar()->insertMenu(menuBar()->actions().at(menuBar()->actions().size() - 2), planMenu);
    auto* exportAct = new QAction(icon("export"), tr("&Export waypoints…"), this);
    connect(exportAct, &QAction::triggered, this, &MainWindow::showExportDialog);
    exportAct->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    m_planning = new PlanningToolBar(m_doc, m_planner, exportAct, m_interactive, this);
    addToolBar(m_planning);
    planMenu->addAction(m_planning->planAction());
    planMenu->addAction(m_planning->cancelAction());
    planMenu->addAction(m_planning->autoPlanAction());
    planMenu->addSeparator();
    planMenu->addAction(m_planning->keepInsideAction());
    planMenu->addAction(m_planning->doubleGridAction());
    planMenu->addAction(icon("compare"), tr("Co&mpare planners"), m_planner, &PlanController::compare);
    planMenu->addSeparator();
    planMenu->addAction(exportAct);
    planMenu->addAction(tr("&Open waypoint file…"), m_files, &MissionFiles::askOpenWaypointFile);
    exportAct->setObjectName(QStringLiteral("ExportAction"));
    m_afterImport->parentWidget()->insertAction(m_afterImport, exportAct); // in File too

    // The running plan's progress with Cancel, and the notice of a plan waiting for the user.
    m_progress = new PlanProgressWidget(m_planner);
    statusBar()->insertPermanentWidget(1, m_progress); // 1: first after the hint label
    statusBar()->insertPermanentWidget(1, new PlanNotice(m_planner));
    connect(m_planner, &PlanController::message, this, [this](const QString& text) { statusBar()->showMessage(text, 8000); });

    // Docks: statistics and comparison on the right, waypoints and problems below the map.
    m_statistics = new StatisticsPanel(m_doc, m_planner);
    auto* statsDock = addDock(tr("Statistics"), QStringLiteral("StatisticsDock"), m_statistics, Qt::BottomDockWidgetArea);
    m_waypoints = new WaypointPanel(m_doc, m_planLayer);
    auto* wpDock = addDock(tr("Waypoints"), QStringLiteral("WaypointsDock"), m_waypoints, Qt::BottomDockWidgetArea);
    m_problemList = new ProblemsPanel(m_doc, m_layer, m_planner, m_planLayer);
    auto* problemsDock = addDock(tr("Problems"), QStringLiteral("ProblemsDock"), m_problemList, Qt::BottomDockWidgetArea);
    // Below the map, left to right: waypoints, statistics, problems.
    splitDockWidget(wpDock, statsDock, Qt::Horizontal);
    splitDockWidget(statsDock, problemsDock, Qt::Horizontal);
    // The statistics table needs its columns and the total row; the problems read as sentences. The
    // sizes take once the window is laid out (before, the docks have no room to share).
    QTimer::singleShot(0, this, [this, wpDock, statsDock, problemsDock] {
        resizeDocks({wpDock, statsDock, problemsDock}, {470, 700, 430}, Qt::Horizontal);
        resizeDocks({wpDock}, {285}, Qt::Vertical);
    });
    // The panel selects what an item is about; a waypoint is also brought into view.
    connect(m_problemList, &ProblemsPanel::waypointActivated, this, [this](int r, int w) {
        if (r >= 0 && r < int(m_doc->routes().size()) && w >= 0 &&
            w < int(m_doc->routes()[std::size_t(r)].route.waypoints.size()))
            m_view->centreOn(m_doc->routes()[std::size_t(r)].route.waypoints[std::size_t(w)].position);
    });
    connect(m_problemList, &ProblemsPanel::countChanged, problemsDock, [problemsDock](int n) {
        problemsDock->setWindowTitle(n ? tr("Problems (%1)").arg(n) : tr("Problems"));
    });

    // Layers in the View menu.
    m_viewMenu->addSeparator();
    m_planLayer->addPartActions(m_viewMenu);
    m_viewMenu->addAction((new HillshadeLayer(m_doc, m_scene, this))->toggleAction());
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(statsDock->toggleViewAction());
    m_viewMenu->addAction(wpDock->toggleViewAction());
    m_viewMenu->addAction(problemsDock->toggleViewAction());
    addDockWidget(Qt::BottomDockWidgetArea, m_terrain->dock());
    // The profile needs the width of the statistics: a tab beside them.
    tabifyDockWidget(statsDock, m_terrain->dock());
    statsDock->raise();
    m_viewMenu->addAction(m_terrain->dock()->toggleViewAction());
}

bool MainWindow::planNoticeVisible() const { return m_planner->hasPendingPlan(); }

void MainWindow::planNow() { m_planning->planNow(); }

void MainWindow::replaceEditedPaths() { m_planner->acceptPendingPlan(); }

int MainWindow::openWaypointFile(const QString& path, int assignTo, QString* error) {
    return m_files->openWaypointFile(path, assignTo, error);
}

void MainWindow::showExportDialog() {
    if (m_doc->routes().empty()) {
        showError(tr("Export waypoints"), tr("Nothing to export yet: plan the mission first (F5)."));
        return;
    }
    QSettings settings;
    const QString folder = settings.value(QStringLiteral("export/folder"),
                                          QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
                               .toString();
    ExportDialog dialog(m_doc, m_planner, folder, this);
    dialog.exec();
    settings.setValue(QStringLiteral("export/folder"), dialog.request().folder);
    // Back to the map, so that the window's shortcuts (Ctrl+Z, Ctrl+E, …) work again at once.
    activateWindow();
    m_view->setFocus(Qt::OtherFocusReason);
}

} // namespace pf::ui
