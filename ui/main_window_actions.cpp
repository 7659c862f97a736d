// MainWindow's menus and tool bars: one builder per menu, in the order they appear in the menu bar
// (the Plan menu and its tool bar are buildPlanning's).
#include "ui/main_window.h"

#include "ui/commands/set_home_command.h"
#include "ui/ground_station.h"
#include "ui/help/help_menu.h"
#include "ui/map/map_view.h"
#include "ui/mission_document.h"
#include "ui/mission_files.h"
#include "ui/mosaic/mosaic_controller.h"
#include "ui/terrain/terrain_controller.h"
#include "ui/tools/abstract_tool.h"
#include "ui/tools/select_tool.h"
#include "ui/tools/waypoint_tool.h"
#include "ui/vehicle/upload_dialog.h"

#include <QAction>
#include <QActionGroup>
#include <QFileDialog>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenuBar>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

namespace pf::ui {

namespace {

// An icon of the application's resources by its file name (":/icons/NAME.svg").
QIcon icon(const char* name) {
    return QIcon(QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name)));
}

// The tools in the order of the Tools menu and tool bar.
constexpr ToolId kToolOrder[] = {ToolId::Pan,       ToolId::Select,     ToolId::DrawArea,
                                 ToolId::DrawNoFly, ToolId::DrawCircle, ToolId::DrawCorridor,
                                 ToolId::Home,      ToolId::Waypoints};

} // namespace

// The actions the menus make that the tool bars show too.
struct MainWindow::BarActions {
    QAction* undo = nullptr;
    QAction* redo = nullptr;
    QAction* newMission = nullptr;
    QAction* open = nullptr;
    QAction* save = nullptr;
    QAction* importFile = nullptr;
    QAction* del = nullptr;
    QAction* zoomIn = nullptr;
    QAction* zoomOut = nullptr;
    QAction* zoomFit = nullptr;
    QAction* centreMe = nullptr;
};

void MainWindow::buildActions() {
    BarActions bar;
    buildUndoRedoActions(bar);
    buildFileMenu(bar);
    buildEditMenu(bar);
    buildToolsMenu();
    buildViewMenu(bar);
    buildGroundStationMenu(bar);
    // Help: the user guide, the keyboard shortcuts, What's this and About (ui/help/).
    addHelpMenu(this);
    buildToolBars(bar);
}

// Undo and redo of the mission's edits, for the Edit menu and the main tool bar.
void MainWindow::buildUndoRedoActions(BarActions& bar) {
    bar.undo = m_doc->undoStack()->createUndoAction(this, tr("&Undo"));
    bar.undo->setShortcut(QKeySequence::Undo);
    bar.undo->setIcon(icon("undo"));
    bar.redo = m_doc->undoStack()->createRedoAction(this, tr("&Redo"));
    bar.redo->setShortcut(QKeySequence::Redo);
    bar.redo->setIcon(icon("redo"));
}

// File: missions, import, mosaic, terrain and quit.
void MainWindow::buildFileMenu(BarActions& bar) {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    bar.newMission =
        file->addAction(icon("new"), tr("&New mission"), m_files, &MissionFiles::askNewMission);
    bar.newMission->setShortcut(QKeySequence::New);
    bar.open =
        file->addAction(icon("open"), tr("&Open mission…"), m_files, &MissionFiles::askOpenMission);
    bar.open->setShortcut(QKeySequence::Open);
    m_recentMenu = file->addMenu(tr("Open &recent"));
    connect(m_recentMenu, &QMenu::aboutToShow, this,
            [this] { m_files->fillRecentMenu(m_recentMenu); });
    file->addAction(tr("Open &demo mission"), m_files, &MissionFiles::askOpenDemoMission);
    file->addSeparator();
    bar.save = file->addAction(icon("save"), tr("&Save"), m_files, &MissionFiles::save);
    bar.save->setShortcut(QKeySequence::Save);
    file->addAction(tr("Save &as…"), m_files, &MissionFiles::saveAs)
        ->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    bar.importFile = file->addAction(icon("import"), tr("&Import area or no-fly zones…"), m_files,
                                     &MissionFiles::askImportAreas);
    bar.importFile->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    m_afterImport = file->addSeparator(); // Export waypoints goes before it (buildPlanning)
    // Mosaic (issue 19): the dialog, the map layer and the dock live in ui/mosaic/.
    m_mosaic = new MosaicController(this, m_view, m_scene, m_planner, &m_catalog);
    file->addAction(icon("map"), tr("Build &mosaic from photos…"), m_mosaic,
                    &MosaicController::showDialog);
    // Terrain following (issue 18): the DEM, follow or off, the clearance, the profile dock
    // (ui/terrain/).
    m_terrain = new TerrainController(this, m_doc, m_planner, m_interactive);
    connect(m_view, &MapView::demDropped, m_terrain, &TerrainController::useDem);
    file->addMenu(m_terrain->menu());
    file->addSeparator();
    auto* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
}

// Edit: undo, redo, delete the selection, clear the home point.
void MainWindow::buildEditMenu(BarActions& bar) {
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(bar.undo);
    edit->addAction(bar.redo);
    edit->addSeparator();
    bar.del = edit->addAction(icon("remove"), tr("&Delete selected vertex or shape"), this, [this] {
        if (m_view->tool() == m_tools.at(ToolId::Waypoints))
            static_cast<WaypointTool*>(m_tools.at(ToolId::Waypoints))->deleteSelection();
        else
            static_cast<SelectTool*>(m_tools.at(ToolId::Select))->deleteSelection();
    });
    bar.del->setShortcut(QKeySequence::Delete);
    bar.del->setShortcutContext(
        Qt::WidgetWithChildrenShortcut); // the map only: spin boxes keep Delete
    m_view->addAction(bar.del);
    edit->addAction(tr("Clear &home point"), this, [this] {
        if (m_doc->mission().home)
            m_doc->undoStack()->push(new SetHomeCommand(m_doc, std::nullopt));
    });
}

// Tools: one checkable action per map tool, exclusive, with its shortcut and hint.
void MainWindow::buildToolsMenu() {
    QMenu* toolsMenu = menuBar()->addMenu(tr("&Tools"));
    auto* toolGroup = new QActionGroup(this);
    for (ToolId id : kToolOrder) {
        AbstractTool* t = m_tools.at(id);
        auto* a = toolsMenu->addAction(t->icon(), t->name());
        a->setCheckable(true);
        a->setShortcut(t->shortcut());
        a->setToolTip(QStringLiteral("%1 (%2)").arg(
            t->name(), t->shortcut().toString(QKeySequence::NativeText)));
        a->setStatusTip(t->hint());
        toolGroup->addAction(a);
        connect(a, &QAction::triggered, this, [this, id] { setTool(id); });
        m_toolActions[id] = a;
    }
}

// View: zoom, graticule and base map (buildPlanning adds the layers and docks after these).
void MainWindow::buildViewMenu(BarActions& bar) {
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    bar.zoomIn = m_viewMenu->addAction(icon("zoom_in"), tr("Zoom &in"), this,
                                       [this] { m_view->zoomBy(1.5); });
    bar.zoomIn->setShortcut(QKeySequence::ZoomIn);
    bar.zoomOut = m_viewMenu->addAction(icon("zoom_out"), tr("Zoom &out"), this,
                                        [this] { m_view->zoomBy(1 / 1.5); });
    bar.zoomOut->setShortcut(QKeySequence::ZoomOut);
    bar.zoomFit = m_viewMenu->addAction(icon("zoom_fit"), tr("Zoom to &mission"), this,
                                        &MainWindow::zoomToMission);
    bar.zoomFit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    auto* grat = m_viewMenu->addAction(tr("&Graticule"));
    grat->setCheckable(true);
    grat->setChecked(true);
    connect(grat, &QAction::toggled, m_view, &MapView::setGraticuleVisible);
    buildBaseMapMenu();
    m_viewMenu->addSeparator();
}

// View > Base map: the built-in maps, exclusive, and a map file to open.
void MainWindow::buildBaseMapMenu() {
    QMenu* baseMenu = m_viewMenu->addMenu(icon("map"), tr("&Base map"));
    m_baseMapGroup = new QActionGroup(this);
    auto addBase = [&](const QString& id, const QString& text) {
        auto* a = baseMenu->addAction(text);
        a->setCheckable(true);
        m_baseMapGroup->addAction(a);
        m_baseMapActions[id] = a;
        connect(a, &QAction::triggered, this, [this, id] {
            QString error;
            if (!setBaseMap(id, &error))
                showError(tr("Base map"), error);
        });
    };
    addBase(QStringLiteral("demo"), tr("Demo map (synthetic, offline)"));
    addBase(QStringLiteral("osm"), tr("OpenStreetMap (online, cached)"));
    addBase(QStringLiteral("none"), tr("No base map"));
    baseMenu->addSeparator();
    baseMenu->addAction(tr("Open map file (GeoTIFF, MBTiles, VRT)…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open map"), QString(),
            tr("Maps (*.tif *.tiff *.mbtiles *.vrt *.jp2);;All files (*)"));
        QString error;
        if (!path.isEmpty() && !setBaseMap(path, &error))
            showError(tr("Base map"), error);
    });
}

// Ground station: NMEA log or receiver, centre on me, stop, and the upload to a vehicle.
void MainWindow::buildGroundStationMenu(BarActions& bar) {
    QMenu* gs = menuBar()->addMenu(tr("&Ground station"));
    gs->addAction(tr("Replay NMEA &log…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("NMEA log"), QString(), tr("NMEA (*.nmea *.log *.txt);;All files (*)"));
        QString error;
        if (!path.isEmpty() && !m_ground->openNmeaFile(path, &error))
            showError(tr("Ground station"), error);
    });
    gs->addAction(tr("Read GNSS &receiver…"), this, [this] {
        bool ok = false;
        const QString dev =
            QInputDialog::getText(this, tr("GNSS receiver"), tr("NMEA device (e.g. /dev/ttyACM0):"),
                                  QLineEdit::Normal, QStringLiteral("/dev/ttyACM0"), &ok);
        QString error;
        if (ok && !dev.isEmpty() && !m_ground->openNmeaDevice(dev, &error))
            showError(tr("Ground station"), error);
    });
    bar.centreMe = gs->addAction(icon("locate"), tr("&Centre on me"), this, [this] {
        if (auto p = m_ground->position())
            m_view->centreOn(*p);
        else
            statusBar()->showMessage(
                tr("No ground-station position yet: replay an NMEA log or connect a receiver."),
                5000);
    });
    bar.centreMe->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    gs->addAction(tr("&Stop"), m_ground, &GroundStation::stop);
    // Vehicles: the mission upload over MAVLink (ui/vehicle).
    gs->addSeparator();
    auto* uploadAct = gs->addAction(icon("export"), tr("Connect and &Upload…"), this, [this] {
        if (m_doc->routes().empty()) {
            showError(tr("Connect and Upload"),
                      tr("Nothing to upload yet: plan the mission first (F5)."));
            return;
        }
        UploadDialog dialog(m_doc, this, &m_sortiesSent);
        dialog.exec();
    });
    uploadAct->setObjectName(QStringLiteral("ConnectAndUploadAction"));
}

// The Main, Tools and View tool bars, from the menus' actions.
void MainWindow::buildToolBars(const BarActions& bar) {
    QToolBar* main = addToolBar(tr("Main"));
    main->setObjectName(QStringLiteral("MainToolBar"));
    main->setIconSize(QSize(22, 22));
    main->addAction(bar.newMission);
    main->addAction(bar.open);
    main->addAction(bar.save);
    main->addAction(bar.importFile);
    main->addSeparator();
    main->addAction(bar.undo);
    main->addAction(bar.redo);
    QToolBar* tools = addToolBar(tr("Tools"));
    tools->setObjectName(QStringLiteral("ToolsToolBar"));
    tools->setIconSize(QSize(22, 22));
    for (ToolId id : kToolOrder)
        tools->addAction(m_toolActions[id]);
    tools->addAction(bar.del);
    QToolBar* view = addToolBar(tr("View"));
    view->setObjectName(QStringLiteral("ViewToolBar"));
    view->setIconSize(QSize(22, 22));
    view->addAction(bar.zoomIn);
    view->addAction(bar.zoomOut);
    view->addAction(bar.zoomFit);
    view->addAction(bar.centreMe);
}

} // namespace pf::ui
