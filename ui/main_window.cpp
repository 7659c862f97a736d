#include "ui/main_window.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/io/area_import.h"
#include "core/io/mission_file.h"
#include "ui/autosave.h"
#include "ui/commands/add_no_fly_zone_command.h"
#include "ui/commands/set_area_command.h"
#include "ui/commands/set_home_command.h"
#include "ui/geo_adapter.h"
#include "ui/ground_station.h"
#include "ui/map/base_maps.h"
#include "ui/map/hillshade_layer.h"
#include "ui/map/map_view.h"
#include "ui/map/mission_layer.h"
#include "ui/map/tile_layer.h"
#include "ui/mission_document.h"
#include "ui/terrain/terrain_controller.h"
#include "ui/mission_files.h"
#include "ui/panels/problems_panel.h"
#include "core/mission/planner_kinds.h"
#include "ui/panels/aircraft_panel.h"
#include "ui/panels/mission_panel.h"
#include "ui/tools/draw_circle_tool.h"
#include "ui/tools/draw_polygon_tool.h"
#include "ui/tools/home_tool.h"
#include "ui/tools/pan_tool.h"
#include "ui/tools/select_tool.h"
#include "ui/tools/waypoint_tool.h"
#include "ui/commands/replace_route_command.h"
#include "ui/commands/set_planner_options_command.h"
#include "ui/dialogs/export_dialog.h"
#include "ui/vehicle/upload_dialog.h"
#include "ui/map/plan_layer.h"
#include "ui/mosaic/mosaic_controller.h"
#include "ui/panels/statistics_panel.h"
#include "ui/panels/waypoint_panel.h"
#include "ui/planning/plan_controller.h"
#include "ui/planning/plan_progress_widget.h"
#include "core/io/waypoint_formats.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QListWidget>
#include <QProgressBar>
#include <QStandardPaths>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QGraphicsScene>
#include <QInputDialog>
#include <QKeyEvent>
#include <QLineEdit>
#include <QAbstractSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QUndoView>

#include <cmath>

// Resources of a static library must be registered by name from the global namespace.
static void initIconResources() { Q_INIT_RESOURCE(icons); }

namespace pf::ui {

namespace {

constexpr int kMaxRecent = 8;

QString importFilter() {
    return QCoreApplication::translate("MainWindow",
                                       "Areas (*.geojson *.json *.kml *.shp *.gpkg *.gml);;All files (*)");
}

QString formatLonLat(const geo::LonLat& p) {
    return QStringLiteral("%1° %2, %3° %4")
        .arg(std::abs(p.lat), 0, 'f', 6)
        .arg(p.lat >= 0 ? QLatin1Char('N') : QLatin1Char('S'))
        .arg(std::abs(p.lon), 0, 'f', 6)
        .arg(p.lon >= 0 ? QLatin1Char('E') : QLatin1Char('W'));
}

} // namespace

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
    setCentralWidget(m_view);

    auto catalog = io::loadDefaultCatalog();
    if (catalog) m_catalog = std::move(catalog).value();

    m_tools[ToolId::Pan] = new PanTool(m_doc, m_layer, this);
    m_tools[ToolId::Select] = new SelectTool(m_doc, m_layer, this);
    m_tools[ToolId::DrawArea] = new DrawPolygonTool(DrawPolygonTool::Target::Area, m_doc, m_layer, this);
    m_tools[ToolId::DrawNoFly] = new DrawPolygonTool(DrawPolygonTool::Target::NoFlyZone, m_doc, m_layer, this);
    m_tools[ToolId::DrawCircle] = new DrawCircleTool(m_doc, m_layer, this);
    m_tools[ToolId::Home] = new HomeTool(m_doc, m_layer, this);
    m_tools[ToolId::Waypoints] = new WaypointTool(m_doc, m_layer, m_planLayer, this);
    for (auto& [id, tool] : m_tools)
        connect(tool, &AbstractTool::statusMessage, this, [this](const QString& text) { statusBar()->showMessage(text); });

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
    qApp->installEventFilter(this);
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    // A line edit (and so every spin box) claims Ctrl+E as "end of line" through a shortcut override,
    // which would silence Plan > Export while the focus is in the Aircraft dock. The window's action
    // wins; End still moves to the end of the line.
    if (event->type() == QEvent::ShortcutOverride) {
        auto* w = qobject_cast<QWidget*>(watched);
        auto* key = static_cast<QKeyEvent*>(event);
        if (w && w->window() == this && (qobject_cast<QLineEdit*>(w) || qobject_cast<QAbstractSpinBox*>(w)) &&
            QKeySequence(int(key->modifiers()) | key->key()) == QKeySequence(Qt::CTRL | Qt::Key_E)) {
            event->ignore();
            return true;
        }
    }
    return QMainWindow::eventFilter(watched, event);
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

void MainWindow::buildActions() {
    auto icon = [](const char* name) { return QIcon(QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name))); };
    auto* undo = m_doc->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(icon("undo"));
    auto* redo = m_doc->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    redo->setIcon(icon("redo"));

    // File
    QMenu* file = menuBar()->addMenu(tr("&File"));
    auto* newAct = file->addAction(icon("new"), tr("&New mission"), this, [this] {
        if (maybeSave()) newMission();
    });
    newAct->setShortcut(QKeySequence::New);
    auto* openAct = file->addAction(icon("open"), tr("&Open mission…"), this, [this] {
        if (!maybeSave()) return;
        const QString path = askMissionOpenPath(this, tr("Open mission"));
        if (!path.isEmpty()) openMission(path);
    });
    openAct->setShortcut(QKeySequence::Open);
    m_recentMenu = file->addMenu(tr("Open &recent"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::rebuildRecentMenu);
    file->addAction(tr("Open &demo mission"), this, [this] {
        if (maybeSave()) openDemoMission();
    });
    file->addSeparator();
    auto* saveAct = file->addAction(icon("save"), tr("&Save"), this, [this] {
        QString path = m_doc->filePath();
        if (path.isEmpty()) path = askMissionSavePath(this, tr("Save mission"), QString());
        if (!path.isEmpty()) saveMission(path);
    });
    saveAct->setShortcut(QKeySequence::Save);
    auto* saveAsAct = file->addAction(tr("Save &as…"), this, [this] {
        const QString path = askMissionSavePath(this, tr("Save mission as"), m_doc->filePath());
        if (!path.isEmpty()) saveMission(path);
    });
    saveAsAct->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    auto* importAct = file->addAction(icon("import"), tr("&Import area or no-fly zones…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Import polygons"), QString(), importFilter());
        if (!path.isEmpty()) importAreas(path, ImportRole::Ask);
    });
    importAct->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    file->addSeparator();
    // Mosaic (issue 19): the dialog, the map layer and the dock live in ui/mosaic/.
    m_mosaic = new MosaicController(this, m_view, m_scene, m_planner, &m_catalog);
    file->addAction(icon("map"), tr("Build &mosaic from photos…"), m_mosaic, &MosaicController::showDialog);
    // Terrain following (issue 18): the DEM, follow or off, the clearance, the profile dock (ui/terrain/).
    m_terrain = new TerrainController(this, m_doc, m_planner, m_interactive);
    connect(m_view, &MapView::demDropped, m_terrain, &TerrainController::useDem);
    file->addMenu(m_terrain->menu());
    file->addSeparator();
    auto* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    // Edit
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    auto* del = edit->addAction(icon("remove"), tr("&Delete selected vertex or shape"), this, [this] {
        if (m_view->tool() == m_tools.at(ToolId::Waypoints))
            static_cast<WaypointTool*>(m_tools.at(ToolId::Waypoints))->deleteSelection();
        else
            static_cast<SelectTool*>(m_tools.at(ToolId::Select))->deleteSelection();
    });
    del->setShortcut(QKeySequence::Delete);
    del->setShortcutContext(Qt::WidgetWithChildrenShortcut); // the map only: spin boxes keep Delete
    m_view->addAction(del);
    edit->addAction(tr("Clear &home point"), this, [this] {
        if (m_doc->mission().home) m_doc->undoStack()->push(new SetHomeCommand(m_doc, std::nullopt));
    });

    // Tools
    QMenu* toolsMenu = menuBar()->addMenu(tr("&Tools"));
    auto* toolGroup = new QActionGroup(this);
    const ToolId order[] = {ToolId::Pan,        ToolId::Select, ToolId::DrawArea, ToolId::DrawNoFly,
                            ToolId::DrawCircle, ToolId::Home,   ToolId::Waypoints};
    for (ToolId id : order) {
        AbstractTool* t = m_tools.at(id);
        auto* a = toolsMenu->addAction(t->icon(), t->name());
        a->setCheckable(true);
        a->setShortcut(t->shortcut());
        a->setToolTip(QStringLiteral("%1 (%2)").arg(t->name(), t->shortcut().toString(QKeySequence::NativeText)));
        a->setStatusTip(t->hint());
        toolGroup->addAction(a);
        connect(a, &QAction::triggered, this, [this, id] { setTool(id); });
        m_toolActions[id] = a;
    }

    // View
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    auto* zin = m_viewMenu->addAction(icon("zoom_in"), tr("Zoom &in"), this, [this] { m_view->zoomBy(1.5); });
    zin->setShortcut(QKeySequence::ZoomIn);
    auto* zout = m_viewMenu->addAction(icon("zoom_out"), tr("Zoom &out"), this, [this] { m_view->zoomBy(1 / 1.5); });
    zout->setShortcut(QKeySequence::ZoomOut);
    auto* zfit = m_viewMenu->addAction(icon("zoom_fit"), tr("Zoom to &mission"), this, &MainWindow::zoomToMission);
    zfit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    auto* grat = m_viewMenu->addAction(tr("&Graticule"));
    grat->setCheckable(true);
    grat->setChecked(true);
    connect(grat, &QAction::toggled, m_view, &MapView::setGraticuleVisible);
    QMenu* baseMenu = m_viewMenu->addMenu(icon("map"), tr("&Base map"));
    m_baseMapGroup = new QActionGroup(this);
    auto addBase = [&](const QString& id, const QString& text) {
        auto* a = baseMenu->addAction(text);
        a->setCheckable(true);
        m_baseMapGroup->addAction(a);
        m_baseMapActions[id] = a;
        connect(a, &QAction::triggered, this, [this, id] {
            QString error;
            if (!setBaseMap(id, &error)) showError(tr("Base map"), error);
        });
    };
    addBase(QStringLiteral("demo"), tr("Demo map (synthetic, offline)"));
    addBase(QStringLiteral("osm"), tr("OpenStreetMap (online, cached)"));
    addBase(QStringLiteral("none"), tr("No base map"));
    baseMenu->addSeparator();
    baseMenu->addAction(tr("Open map file (GeoTIFF, MBTiles, VRT)…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open map"), QString(),
                                                          tr("Maps (*.tif *.tiff *.mbtiles *.vrt *.jp2);;All files (*)"));
        QString error;
        if (!path.isEmpty() && !setBaseMap(path, &error)) showError(tr("Base map"), error);
    });
    m_viewMenu->addSeparator();

    // Ground station
    QMenu* gs = menuBar()->addMenu(tr("&Ground station"));
    gs->addAction(tr("Replay NMEA &log…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("NMEA log"), QString(), tr("NMEA (*.nmea *.log *.txt);;All files (*)"));
        QString error;
        if (!path.isEmpty() && !m_ground->openNmeaFile(path, &error)) showError(tr("Ground station"), error);
    });
    gs->addAction(tr("Read GNSS &receiver…"), this, [this] {
        bool ok = false;
        const QString dev = QInputDialog::getText(this, tr("GNSS receiver"), tr("NMEA device (e.g. /dev/ttyACM0):"),
                                                  QLineEdit::Normal, QStringLiteral("/dev/ttyACM0"), &ok);
        QString error;
        if (ok && !dev.isEmpty() && !m_ground->openNmeaDevice(dev, &error)) showError(tr("Ground station"), error);
    });
    auto* centreMe = gs->addAction(icon("locate"), tr("&Centre on me"), this, [this] {
        if (auto p = m_ground->position())
            m_view->centreOn(*p);
        else
            statusBar()->showMessage(tr("No ground-station position yet: replay an NMEA log or connect a receiver."), 5000);
    });
    centreMe->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    gs->addAction(tr("&Stop"), m_ground, &GroundStation::stop);
    // Vehicles: the mission upload over MAVLink (ui/vehicle).
    gs->addSeparator();
    auto* uploadAct = gs->addAction(icon("export"), tr("Connect and &Upload…"), this, [this] {
        if (m_doc->routes().empty()) {
            showError(tr("Connect and Upload"), tr("Nothing to upload yet: plan the mission first (F5)."));
            return;
        }
        UploadDialog dialog(m_doc, this);
        dialog.exec();
    });
    uploadAct->setObjectName(QStringLiteral("ConnectAndUploadAction"));

    // Help
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About Photoflight"), this, [this] {
        QMessageBox::about(this, tr("About Photoflight"),
                           tr("<b>Photoflight %1</b><br>Photo-survey flight planning for one or several UAVs.<br><br>"
                              "The demo map is synthetic: it is drawn by the program and shows no real place.")
                               .arg(QStringLiteral(PF_VERSION)));
    });

    // Tool bars
    QToolBar* main = addToolBar(tr("Main"));
    main->setObjectName(QStringLiteral("MainToolBar"));
    main->setIconSize(QSize(22, 22));
    main->addAction(newAct);
    main->addAction(openAct);
    main->addAction(saveAct);
    main->addAction(importAct);
    main->addSeparator();
    main->addAction(undo);
    main->addAction(redo);
    QToolBar* tools = addToolBar(tr("Tools"));
    tools->setObjectName(QStringLiteral("ToolsToolBar"));
    tools->setIconSize(QSize(22, 22));
    for (ToolId id : order) tools->addAction(m_toolActions[id]);
    tools->addAction(del);
    QToolBar* view = addToolBar(tr("View"));
    view->setObjectName(QStringLiteral("ViewToolBar"));
    view->setIconSize(QSize(22, 22));
    view->addAction(zin);
    view->addAction(zout);
    view->addAction(zfit);
    view->addAction(centreMe);
}

void MainWindow::buildDocks() {
    setDockNestingEnabled(true);
    auto* aircraftDock = new QDockWidget(tr("Aircraft"), this);
    aircraftDock->setObjectName(QStringLiteral("AircraftDock"));
    m_aircraft = new AircraftPanel(m_doc, m_catalog, aircraftDock);
    aircraftDock->setWidget(m_aircraft);
    addDockWidget(Qt::RightDockWidgetArea, aircraftDock);

    auto* missionDock = new QDockWidget(tr("Mission"), this);
    missionDock->setObjectName(QStringLiteral("MissionDock"));
    m_missionPanel = new MissionPanel(m_doc, m_layer, missionDock);
    missionDock->setWidget(m_missionPanel);
    addDockWidget(Qt::RightDockWidgetArea, missionDock);
    connect(m_missionPanel, &MissionPanel::shapeActivated, this, [this](const QRectF& r) {
        m_view->fitSceneRect(r.adjusted(-r.width(), -r.height(), r.width(), r.height()));
    });

    auto* historyDock = new QDockWidget(tr("History"), this);
    historyDock->setObjectName(QStringLiteral("HistoryDock"));
    auto* undoView = new QUndoView(m_doc->undoStack(), historyDock);
    undoView->setEmptyLabel(tr("<opened>"));
    historyDock->setWidget(undoView);
    addDockWidget(Qt::RightDockWidgetArea, historyDock);
    // One column of tabs on the right keeps the map tall; the plan's docks go below it.
    tabifyDockWidget(aircraftDock, missionDock);
    tabifyDockWidget(missionDock, historyDock);
    aircraftDock->raise();
    resizeDocks({aircraftDock}, {360}, Qt::Horizontal);

    m_viewMenu->addAction(aircraftDock->toggleViewAction());
    m_viewMenu->addAction(missionDock->toggleViewAction());
    m_viewMenu->addAction(historyDock->toggleViewAction());
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
    if (m_interactive)
        QMessageBox::warning(this, title, message);
    else
        statusBar()->showMessage(message);
}

QString MainWindow::statusText() const { return statusBar()->currentMessage(); }

void MainWindow::startup(const QString& missionPath) {
    QSettings settings;
    const auto leftovers = m_autosave->leftovers();
    if (!leftovers.isEmpty() && m_interactive) {
        const auto& r = leftovers.first();
        const QString what = r.originalPath.isEmpty() ? tr("an unsaved mission") : QFileInfo(r.originalPath).fileName();
        const auto answer = QMessageBox::question(
            this, tr("Recover mission"),
            tr("Photoflight did not close properly. Restore the automatically saved copy of %1 from %2?")
                .arg(what, QLocale().toString(r.savedAt, QLocale::ShortFormat)),
            QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
        if (answer == QMessageBox::Yes) {
            QString error;
            if (m_autosave->recover(r, &error)) {
                for (int i = 1; i < leftovers.size(); ++i) m_autosave->discard(leftovers[i]);
                zoomToMission();
                statusBar()->showMessage(tr("Recovered the automatically saved mission."), 8000);
                return;
            }
            showError(tr("Recover mission"), error);
        }
        for (const auto& l : leftovers) m_autosave->discard(l);
    }
    if (!missionPath.isEmpty()) {
        openMission(missionPath);
        return;
    }
    const bool firstStart = !settings.value(QStringLiteral("startedBefore"), false).toBool();
    settings.setValue(QStringLiteral("startedBefore"), true);
    const QStringList recent = settings.value(QStringLiteral("recentFiles")).toStringList();
    if (!firstStart && !recent.isEmpty() && QFileInfo::exists(recent.first())) {
        openMission(recent.first());
        return;
    }
    openDemoMission();
}

bool MainWindow::openMission(const QString& path, QString* error) {
    QString why;
    if (!m_doc->load(path, &why)) {
        if (error) *error = why;
        showError(tr("Open mission"), why);
        return false;
    }
    addRecentFile(m_doc->filePath());
    zoomToMission();
    statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

bool MainWindow::openDemoMission(QString* error) {
    const QString data = QString::fromStdString(io::dataDirectory());
    const QString path = data + QStringLiteral("/demo/demo_mission.json");
    if (data.isEmpty() || !QFileInfo::exists(path)) {
        const QString why = tr("The demo mission was not found (looked for demo/demo_mission.json in the data directory).");
        if (error) *error = why;
        showError(tr("Open demo mission"), why);
        return false;
    }
    QString why;
    if (!m_doc->load(path, &why)) {
        if (error) *error = why;
        showError(tr("Open demo mission"), why);
        return false;
    }
    // The bundled file is read-only data: saving asks for a new place.
    m_doc->reset(m_doc->missionWithEditedRoutes(), QString());
    zoomToMission();
    return true;
}

bool MainWindow::saveMission(const QString& chosen, QString* error) {
    // Every mission file gets its extension, so that File > Open shows it again.
    const QString path = withMissionExtension(chosen);
    QString why;
    if (!m_doc->save(path, &why)) {
        if (error) *error = why;
        showError(tr("Save mission"), why);
        return false;
    }
    addRecentFile(m_doc->filePath());
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

void MainWindow::newMission() {
    mission::Mission m;
    m.name = tr("New mission").toStdString();
    m_doc->reset(m, QString());
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(QStringLiteral("recentFiles")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue(QStringLiteral("recentFiles"), recent);
}

void MainWindow::rebuildRecentMenu() {
    m_recentMenu->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (const QString& path : recent) {
        auto* a = m_recentMenu->addAction(QFileInfo(path).fileName(), this, [this, path] {
            if (maybeSave()) openMission(path);
        });
        a->setToolTip(path);
        a->setEnabled(QFileInfo::exists(path));
    }
    if (recent.isEmpty()) m_recentMenu->addAction(tr("(none)"))->setEnabled(false);
}

bool MainWindow::maybeSave() {
    if (!m_doc->isDirty() || !m_interactive) return true;
    const auto answer = QMessageBox::question(this, tr("Unsaved changes"),
                                              m_doc->filePath().isEmpty()
                                                  ? tr("Save the changes to %1 (not saved yet)?").arg(m_doc->displayName())
                                                  : tr("Save the changes to %1?").arg(QFileInfo(m_doc->filePath()).fileName()),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Discard) return true;
    QString path = m_doc->filePath();
    if (path.isEmpty()) path = askMissionSavePath(this, tr("Save mission"), QString());
    return !path.isEmpty() && saveMission(path);
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!maybeSave()) {
        e->ignore();
        return;
    }
    m_autosave->removeOwn();
    e->accept();
}

int MainWindow::importAreas(const QString& path, ImportRole role, QString* error) {
    auto imported = io::importPolygons(path.toStdString());
    if (!imported) {
        const QString why = QString::fromStdString(imported.error().message);
        if (error) *error = why;
        showError(tr("Import"), why);
        return 0;
    }
    std::vector<io::ImportedPolygon> polys = std::move(imported).value();
    if (polys.empty()) return 0;
    const bool hasArea = !m_doc->mission().area.outer.empty();
    bool areaFromFile = !hasArea;
    if (hasArea && role == ImportRole::Ask) {
        if (!m_interactive) {
            role = ImportRole::NoFlyZones;
        } else {
            QMessageBox box(QMessageBox::Question, tr("Import"),
                            tr("%1 contains %n polygon(s). How should they be used?", nullptr, int(polys.size()))
                                .arg(QFileInfo(path).fileName()),
                            QMessageBox::Cancel, this);
            auto* asArea = box.addButton(tr("Replace the area"), QMessageBox::AcceptRole);
            auto* asNoFly = box.addButton(tr("Add as no-fly zones"), QMessageBox::AcceptRole);
            box.setDefaultButton(asNoFly);
            box.exec();
            if (box.clickedButton() == static_cast<QAbstractButton*>(asArea))
                role = ImportRole::Area;
            else if (box.clickedButton() == static_cast<QAbstractButton*>(asNoFly))
                role = ImportRole::NoFlyZones;
            else
                return 0;
        }
    }
    if (role == ImportRole::Area) areaFromFile = true;
    if (role == ImportRole::NoFlyZones) areaFromFile = false;

    // The largest polygon is the area (an area file often carries small features beside it).
    std::size_t largest = 0;
    if (areaFromFile) {
        double best = -1;
        for (std::size_t i = 0; i < polys.size(); ++i) {
            const double a = geo::groundAreaM2(polys[i].polygon);
            if (a > best) {
                best = a;
                largest = i;
            }
        }
    }
    auto* stack = m_doc->undoStack();
    stack->beginMacro(tr("Import %1").arg(QFileInfo(path).fileName()));
    int count = 0;
    for (std::size_t i = 0; i < polys.size(); ++i) {
        if (areaFromFile && i == largest) {
            stack->push(new SetAreaCommand(m_doc, polys[i].polygon, tr("Import area")));
        } else {
            mission::NoFlyZone zone;
            zone.name = polys[i].name.empty() ? tr("Imported %1").arg(i + 1).toStdString() : polys[i].name;
            zone.polygon = polys[i].polygon;
            stack->push(new AddNoFlyZoneCommand(m_doc, zone));
        }
        ++count;
    }
    stack->endMacro();
    statusBar()->showMessage(tr("Imported %n polygon(s) from %1", nullptr, count).arg(QFileInfo(path).fileName()), 5000);
    if (!hasArea) zoomToMission();
    return count;
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
                if (maybeSave()) openMission(path);
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
    m_planAct = planMenu->addAction(icon("plan"), tr("&Plan now"), this, &MainWindow::planNow);
    m_planAct->setShortcut(QKeySequence(Qt::Key_F5));
    m_planAct->setToolTip(tr("Plan the mission (F5)"));
    m_cancelAct = planMenu->addAction(icon("cancel"), tr("&Cancel planning"), m_planner, &PlanController::cancel);
    m_cancelAct->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    m_cancelAct->setEnabled(false);
    m_autoAct = planMenu->addAction(tr("Plan &automatically after edits"));
    m_autoAct->setCheckable(true);
    m_autoAct->setChecked(QSettings().value(QStringLiteral("plan/auto"), true).toBool());
    m_planner->setAutoPlan(m_autoAct->isChecked());
    connect(m_autoAct, &QAction::toggled, this, [this](bool on) {
        m_planner->setAutoPlan(on);
        QSettings().setValue(QStringLiteral("plan/auto"), on);
    });
    planMenu->addSeparator();
    auto* compareAct = planMenu->addAction(icon("compare"), tr("Co&mpare planners"), m_planner, &PlanController::compare);
    planMenu->addSeparator();
    auto* exportAct = planMenu->addAction(icon("export"), tr("&Export waypoints…"), this, &MainWindow::showExportDialog);
    exportAct->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    planMenu->addAction(tr("&Open waypoint file…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open waypoint file"), QString(),
            tr("Waypoint files (*.plan *.waypoints *.gpx *.geojson *.json *.csv);;All files (*)"));
        if (!path.isEmpty()) openWaypointFile(path);
    });

    m_plannerBox = new QComboBox;
    m_plannerBox->setObjectName(QStringLiteral("PlannerBox"));
    m_plannerBox->setToolTip(tr("Coverage planner"));
    for (const auto& k : mission::plannerKinds()) {
        m_plannerBox->addItem(plannerName(k.kind), int(k.kind));
        m_plannerBox->setItemData(m_plannerBox->count() - 1, QString::fromLatin1(k.summary), Qt::ToolTipRole);
    }
    // Keep inside area, one click away: waypoints stay inside the area (as far as each photo still
    // sees the ground it is responsible for).
    m_keepInsideAct = new QAction(icon("keep_inside"), tr("Keep inside area"), this);
    m_keepInsideAct->setObjectName(QStringLiteral("KeepInsideAction"));
    m_keepInsideAct->setCheckable(true);
    m_keepInsideAct->setToolTip(
        tr("Keep inside area: off, lanes end where the photos cover the boundary, so waypoints may lie "
           "outside the area; on, waypoints stay within it"));
    connect(m_keepInsideAct, &QAction::triggered, this, [this](bool on) {
        auto o = m_doc->mission().options;
        if (o.keepInsideArea == on) return;
        o.keepInsideArea = on;
        m_doc->undoStack()->push(new SetPlannerOptionsCommand(
            m_doc, o, on ? tr("Keep waypoints inside the area") : tr("Let lanes end beyond the area")));
    });
    planMenu->insertAction(compareAct, m_keepInsideAct);
    m_angleBox = new QDoubleSpinBox;
    m_angleBox->setObjectName(QStringLiteral("GridAngleBox"));
    m_angleBox->setToolTip(tr("Grid angle in degrees from east; Auto tries many angles and keeps the fastest plan"));
    m_angleBox->setRange(-1, 179);
    m_angleBox->setDecimals(0);
    m_angleBox->setSingleStep(5);
    m_angleBox->setSuffix(QStringLiteral("°"));
    m_angleBox->setSpecialValueText(tr("Auto angle"));
    m_angleBox->setKeyboardTracking(false);
    connect(m_plannerBox, QOverload<int>::of(&QComboBox::activated), this, [this](int i) {
        auto o = m_doc->mission().options;
        const auto kind = mission::PlannerKind(m_plannerBox->itemData(i).toInt());
        if (o.planner == kind) return;
        o.planner = kind;
        m_doc->undoStack()->push(new SetPlannerOptionsCommand(m_doc, o, tr("Planner %1").arg(plannerName(kind))));
    });
    connect(m_angleBox, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        auto o = m_doc->mission().options;
        std::optional<double> angle;
        if (v >= 0) angle = v;
        if (o.gridAngleDeg == angle) return;
        o.gridAngleDeg = angle;
        m_doc->undoStack()->push(new SetPlannerOptionsCommand(
            m_doc, o, angle ? tr("Grid angle %1°").arg(*angle, 0, 'f', 0) : tr("Automatic grid angle")));
    });
    connect(m_doc, &MissionDocument::optionsChanged, this, &MainWindow::syncPlannerControls);
    connect(m_doc, &MissionDocument::missionReset, this, &MainWindow::syncPlannerControls);

    QToolBar* bar = addToolBar(tr("Planning"));
    bar->setObjectName(QStringLiteral("PlanningToolBar"));
    bar->setIconSize(QSize(22, 22));
    bar->addAction(m_planAct);
    bar->addAction(m_cancelAct);
    bar->addWidget(m_plannerBox);
    bar->addWidget(m_angleBox);
    bar->addAction(m_keepInsideAct);
    bar->addAction(exportAct);

    // The running plan's progress with Cancel, and the notice of a plan waiting for the user.
    m_progress = new PlanProgressWidget(m_planner);
    statusBar()->insertPermanentWidget(0, m_progress);
    m_notice = new QWidget;
    auto* nl = new QHBoxLayout(m_notice);
    nl->setContentsMargins(6, 0, 6, 0);
    m_noticeText = new QLabel(tr("New plan ready — your edited paths are kept."));
    m_noticeText->setStyleSheet(QStringLiteral("QLabel { color: #0b3d91; font-weight: bold; }"));
    auto* replace = new QPushButton(tr("Replace edited paths"));
    auto* keep = new QPushButton(tr("Keep edits"));
    nl->addWidget(m_noticeText);
    nl->addWidget(replace);
    nl->addWidget(keep);
    m_notice->setStyleSheet(QStringLiteral("QWidget { background: #dbe8ff; }"));
    m_notice->hide();
    statusBar()->insertPermanentWidget(0, m_notice);
    connect(replace, &QPushButton::clicked, this, &MainWindow::replaceEditedPaths);
    keep->setToolTip(tr("Keep the paths you edited; the other aircraft get the new plan"));
    replace->setToolTip(tr("The new plan replaces every path, the edited ones too"));
    connect(keep, &QPushButton::clicked, m_planner, &PlanController::keepEditsWithPendingPlan);
    connect(m_planner, &PlanController::pendingPlanChanged, m_notice, &QWidget::setVisible);
    connect(m_planner, &PlanController::busyChanged, this, [this](bool busy) {
        m_cancelAct->setEnabled(busy);
    });
    connect(m_planner, &PlanController::message, this, [this](const QString& text) { statusBar()->showMessage(text, 8000); });

    // Docks: statistics and comparison on the right, waypoints and problems below the map.
    auto* statsDock = new QDockWidget(tr("Statistics"), this);
    statsDock->setObjectName(QStringLiteral("StatisticsDock"));
    m_statistics = new StatisticsPanel(m_doc, m_planner, statsDock);
    statsDock->setWidget(m_statistics);
    addDockWidget(Qt::BottomDockWidgetArea, statsDock);

    auto* wpDock = new QDockWidget(tr("Waypoints"), this);
    wpDock->setObjectName(QStringLiteral("WaypointsDock"));
    m_waypoints = new WaypointPanel(m_doc, m_planLayer, wpDock);
    wpDock->setWidget(m_waypoints);
    addDockWidget(Qt::BottomDockWidgetArea, wpDock);

    auto* problemsDock = new QDockWidget(tr("Problems"), this);
    problemsDock->setObjectName(QStringLiteral("ProblemsDock"));
    m_problemList = new ProblemsPanel(m_doc, m_layer, m_planner, m_planLayer, problemsDock);
    problemsDock->setWidget(m_problemList);
    addDockWidget(Qt::BottomDockWidgetArea, problemsDock);
    // Below the map, left to right: waypoints, statistics, problems.
    splitDockWidget(wpDock, statsDock, Qt::Horizontal);
    splitDockWidget(statsDock, problemsDock, Qt::Horizontal);
    resizeDocks({wpDock, statsDock, problemsDock}, {500, 640, 400}, Qt::Horizontal);
    resizeDocks({wpDock}, {250}, Qt::Vertical);
    connect(m_problemList, &ProblemsPanel::areaActivated, this, [this] { m_layer->select(ShapeRef::area()); });
    connect(m_problemList, &ProblemsPanel::noFlyZoneActivated, this, [this](int i) { m_layer->select(ShapeRef::noFly(i)); });
    connect(m_problemList, &ProblemsPanel::waypointActivated, this, [this](int r, int w) {
        m_planLayer->selectWaypoints(r, {w});
        if (r >= 0 && r < int(m_doc->routes().size()) && w >= 0 &&
            w < int(m_doc->routes()[std::size_t(r)].route.waypoints.size()))
            m_view->centreOn(m_doc->routes()[std::size_t(r)].route.waypoints[std::size_t(w)].position);
    });
    connect(m_problemList, &ProblemsPanel::countChanged, problemsDock, [problemsDock](int n) {
        problemsDock->setWindowTitle(n ? tr("Problems (%1)").arg(n) : tr("Problems"));
    });

    // Layers in the View menu.
    m_viewMenu->addSeparator();
    const std::pair<PlanLayer::Part, QString> parts[] = {
        {PlanLayer::Part::Paths, tr("Flight &paths")},       {PlanLayer::Part::Photos, tr("P&hoto points")},
        {PlanLayer::Part::Footprints, tr("Photo &footprints")}, {PlanLayer::Part::Partition, tr("&Partition of the area")},
        {PlanLayer::Part::Grid, tr("&Grid cells")},          {PlanLayer::Part::Sorties, tr("&Sorties (batteries)")},
        {PlanLayer::Part::Uncovered, tr("&Uncovered patches")}};
    for (const auto& [part, text] : parts) {
        auto* a = m_viewMenu->addAction(text);
        a->setCheckable(true);
        a->setChecked(m_planLayer->isVisible(part));
        const auto p = part;
        connect(a, &QAction::toggled, this, [this, p](bool on) { m_planLayer->setVisible(p, on); });
    }
    m_viewMenu->addAction((new HillshadeLayer(m_doc, m_scene, this))->toggleAction());
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(statsDock->toggleViewAction());
    m_viewMenu->addAction(wpDock->toggleViewAction());
    m_viewMenu->addAction(problemsDock->toggleViewAction());
    addDockWidget(Qt::BottomDockWidgetArea, m_terrain->dock());
    tabifyDockWidget(statsDock, m_terrain->dock());
    statsDock->raise();
    m_viewMenu->addAction(m_terrain->dock()->toggleViewAction());
    syncPlannerControls();
}

void MainWindow::syncPlannerControls() {
    const auto& o = m_doc->mission().options;
    const QSignalBlocker b1(m_plannerBox), b2(m_angleBox);
    m_plannerBox->setCurrentIndex(m_plannerBox->findData(int(o.planner)));
    m_keepInsideAct->setChecked(o.keepInsideArea);
    m_angleBox->setValue(o.gridAngleDeg ? *o.gridAngleDeg : -1.0);
}

bool MainWindow::planNoticeVisible() const { return m_planner->hasPendingPlan(); }

void MainWindow::planNow() {
    if (m_doc->anyRouteEdited() && m_interactive) {
        const auto answer = QMessageBox::question(
            this, tr("Replace edited paths?"),
            tr("Some paths were edited by hand. A new plan replaces them. Plan now and replace the edited paths?"),
            QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Yes) return;
        m_planner->planNow(/*replaceEdited=*/true); // consent given
        return;
    }
    m_planner->planNow();
}

void MainWindow::replaceEditedPaths() { m_planner->acceptPendingPlan(); }

int MainWindow::openWaypointFile(const QString& path, int assignTo, QString* error) {
    auto imported = io::importWaypoints(path.toStdString());
    if (!imported) {
        const QString why = QString::fromStdString(imported.error().message);
        if (error) *error = why;
        showError(tr("Open waypoint file"), why);
        return 0;
    }
    const io::ImportedWaypoints file = std::move(imported).value();
    std::vector<route::Route> routes = file.routes;
    for (auto& r : routes)
        if (!r.home) r.home = file.home;
    if (routes.empty()) {
        const QString why = tr("%1 holds no waypoints.").arg(QFileInfo(path).fileName());
        if (error) *error = why;
        showError(tr("Open waypoint file"), why);
        return 0;
    }
    const auto& existing = m_doc->routes();
    const QString base = QFileInfo(path).completeBaseName();
    auto target = [&](std::size_t k, const route::Route& r) -> int {
        if (assignTo >= 0) return std::min(assignTo + int(k), int(existing.size()));
        for (std::size_t i = 0; i < existing.size(); ++i) {
            const auto& name = existing[i].route.aircraft;
            if (!r.aircraft.empty() && r.aircraft == name) return int(i);
        }
        // Formats without a vehicle name (.plan, .waypoints, .csv): the exported file is named after it
        // (with the characters unsafe in file names replaced, by the export's own rule).
        for (std::size_t i = 0; i < existing.size(); ++i) {
            const QString name = QString::fromStdString(io::fileNameSafe(existing[i].route.aircraft));
            if (!name.isEmpty() && routes.size() == 1 && base.endsWith(name, Qt::CaseInsensitive)) return int(i);
        }
        if (m_interactive && !existing.empty()) {
            QStringList items;
            for (const auto& e : existing) items << QString::fromStdString(e.route.aircraft);
            items << tr("A new route");
            bool ok = false;
            const QString pick = QInputDialog::getItem(this, tr("Open waypoint file"),
                                                       tr("Which aircraft flies this route?"), items, 0, false, &ok);
            if (!ok) return -1;
            const int i = items.indexOf(pick);
            return i < int(existing.size()) ? i : int(existing.size());
        }
        return int(existing.size());
    };
    auto* stack = m_doc->undoStack();
    stack->beginMacro(tr("Open %1").arg(QFileInfo(path).fileName()));
    int count = 0;
    for (std::size_t k = 0; k < routes.size(); ++k) {
        route::Route r = routes[k];
        const int i = target(k, r);
        if (i < 0) continue;
        if (i < int(m_doc->routes().size())) {
            // The route keeps the aircraft it is assigned to (its colour and export name).
            r.aircraft = m_doc->routes()[std::size_t(i)].route.aircraft;
            if (!r.home) r.home = m_doc->routes()[std::size_t(i)].route.home;
        } else if (r.aircraft.empty()) {
            r.aircraft = base.toStdString();
        }
        stack->push(new ReplaceRouteCommand(m_doc, i, r));
        ++count;
    }
    stack->endMacro();
    statusBar()->showMessage(tr("Loaded %n route(s) from %1", nullptr, count).arg(QFileInfo(path).fileName()), 5000);
    return count;
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
