#include "ui/mission_files.h"

#include "core/data_dir.h"
#include "core/geo/polygon_ops.h"
#include "core/io/area_import.h"
#include "core/io/mission_file.h"
#include "core/io/waypoint_formats.h"
#include "core/mission/corridor.h"
#include "ui/autosave.h"
#include "ui/commands/add_no_fly_zone_command.h"
#include "ui/commands/replace_route_command.h"
#include "ui/commands/set_area_command.h"
#include "ui/commands/set_corridor_command.h"
#include "ui/mission_document.h"
#include "ui/tools/draw_corridor_tool.h"

#include <QPushButton>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLocale>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>

#include <algorithm>

namespace pf::ui {

namespace {

constexpr int kMaxRecent = 8;

QString importFilter() {
    return QCoreApplication::translate(
        "MainWindow", "Areas and corridor lines (*.geojson *.json *.kml *.gpx *.shp "
                      "*.gpkg *.gml);;All files (*)");
}

// A file with lines and no polygon: its longest line becomes the corridor's centre line (one undo
// step), at the width the next corridor gets. Returns false when the file holds no line either.
bool importCorridorLine(MissionDocument* doc, const QString& path) {
    auto lines = io::importLines(path.toStdString());
    if (!lines || lines->empty())
        return false;
    const auto longest =
        std::max_element(lines->begin(), lines->end(), [](const auto& a, const auto& b) {
            return mission::corridorLengthM({a.line, 1.0}) <
                   mission::corridorLengthM({b.line, 1.0});
        });
    const mission::Corridor c{longest->line, DrawCorridorTool::corridorWidthM(doc)};
    doc->undoStack()->push(
        new SetCorridorCommand(doc, c,
                               QCoreApplication::translate("MainWindow", "Import corridor %1")
                                   .arg(QString::fromStdString(longest->name))));
    return true;
}

} // namespace

QString missionExtension() { return QStringLiteral(".json"); }

QString missionFilter() {
    return QCoreApplication::translate("MainWindow", "Photoflight missions (*.json);;All files (*)");
}

QString withMissionExtension(const QString& path) {
    if (path.isEmpty() || path.endsWith(missionExtension(), Qt::CaseInsensitive)) return path;
    return path + missionExtension();
}

QString askMissionSavePath(QWidget* parent, const QString& title, const QString& start) {
    QFileDialog dialog(parent, title, start, missionFilter());
    dialog.setObjectName(QStringLiteral("MissionSaveDialog"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix(missionExtension().mid(1));
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return {};
    return withMissionExtension(dialog.selectedFiles().first());
}

QString askMissionOpenPath(QWidget* parent, const QString& title) {
    QFileDialog dialog(parent, title, QString(), missionFilter());
    dialog.setObjectName(QStringLiteral("MissionOpenDialog"));
    dialog.setAcceptMode(QFileDialog::AcceptOpen);
    dialog.setFileMode(QFileDialog::ExistingFile);
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return {};
    return dialog.selectedFiles().first();
}

void reportError(QMainWindow* window, bool interactive, const QString& title, const QString& message) {
    if (interactive)
        QMessageBox::warning(window, title, message);
    else
        window->statusBar()->showMessage(message);
}

MissionFiles::MissionFiles(QMainWindow* window, MissionDocument* doc, Autosave* autosave, bool interactive)
    : QObject(window), m_window(window), m_doc(doc), m_autosave(autosave), m_interactive(interactive) {}

void MissionFiles::showError(const QString& title, const QString& message) {
    reportError(m_window, m_interactive, title, message);
}

bool MissionFiles::fail(QString* error, const QString& title, const QString& why) {
    if (error) *error = why;
    showError(title, why);
    return false;
}

void MissionFiles::showStatus(const QString& message, int timeoutMs) {
    m_window->statusBar()->showMessage(message, timeoutMs);
}

void MissionFiles::askNewMission() {
    if (maybeSave()) newMission();
}

void MissionFiles::askOpenMission() {
    if (!maybeSave()) return;
    const QString path = askMissionOpenPath(m_window, tr("Open mission"));
    if (!path.isEmpty()) openMission(path);
}

void MissionFiles::askOpenDemoMission() {
    if (maybeSave()) openDemoMission();
}

void MissionFiles::save() {
    QString path = m_doc->filePath();
    if (path.isEmpty()) path = askMissionSavePath(m_window, tr("Save mission"), QString());
    if (!path.isEmpty()) saveMission(path);
}

void MissionFiles::saveAs() {
    const QString path = askMissionSavePath(m_window, tr("Save mission as"), m_doc->filePath());
    if (!path.isEmpty()) saveMission(path);
}

void MissionFiles::askImportAreas() {
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Import polygons"), QString(), importFilter());
    if (!path.isEmpty()) importAreas(path, ImportRole::Ask);
}

void MissionFiles::askOpenWaypointFile() {
    const QString path = QFileDialog::getOpenFileName(
        m_window, tr("Open waypoint file"), QString(),
        tr("Waypoint files (*.plan *.waypoints *.gpx *.geojson *.json *.csv);;All files (*)"));
    if (!path.isEmpty()) openWaypointFile(path);
}

void MissionFiles::startup(const QString& missionPath) {
    QSettings settings;
    const auto leftovers = m_autosave->leftovers();
    if (!leftovers.isEmpty() && m_interactive) {
        const auto& r = leftovers.first();
        const QString what = r.originalPath.isEmpty() ? tr("an unsaved mission") : QFileInfo(r.originalPath).fileName();
        const auto answer = QMessageBox::question(
            m_window, tr("Recover mission"),
            tr("Photoflight did not close properly. Restore the automatically saved copy of %1 from %2?")
                .arg(what, QLocale().toString(r.savedAt, QLocale::ShortFormat)),
            QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
        if (answer == QMessageBox::Yes) {
            QString error;
            if (m_autosave->recover(r, &error)) {
                for (int i = 1; i < leftovers.size(); ++i) m_autosave->discard(leftovers[i]);
                emit missionShown();
                showStatus(tr("Recovered the automatically saved mission."), 8000);
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

bool MissionFiles::openMission(const QString& path, QString* error) {
    QString why;
    if (!m_doc->load(path, &why))
        return fail(error, tr("Open mission"), why);
    addRecentFile(m_doc->filePath());
    emit missionShown();
    showStatus(tr("Opened %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

bool MissionFiles::openDemoMission(QString* error) {
    const QString data = QString::fromStdString(pf::dataDirectory());
    const QString path = data + QStringLiteral("/demo/demo_mission.json");
    if (data.isEmpty() || !QFileInfo::exists(path)) {
        const QString why = tr("The demo mission was not found (looked for demo/demo_mission.json in the data directory).");
        return fail(error, tr("Open demo mission"), why);
    }
    QString why;
    if (!m_doc->load(path, &why))
        return fail(error, tr("Open demo mission"), why);
    // The bundled file is read-only data: saving asks for a new place.
    m_doc->reset(m_doc->missionWithEditedRoutes(), QString());
    emit missionShown();
    return true;
}

bool MissionFiles::saveMission(const QString& chosen, QString* error) {
    // Every mission file gets its extension, so that File > Open shows it again.
    const QString path = withMissionExtension(chosen);
    QString why;
    if (!m_doc->save(path, &why))
        return fail(error, tr("Save mission"), why);
    addRecentFile(m_doc->filePath());
    showStatus(tr("Saved %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

void MissionFiles::newMission() {
    mission::Mission m;
    m.name = tr("New mission").toStdString();
    m_doc->reset(m, QString());
}

void MissionFiles::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(QStringLiteral("recentFiles")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue(QStringLiteral("recentFiles"), recent);
}

void MissionFiles::fillRecentMenu(QMenu* menu) {
    menu->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (const QString& path : recent) {
        auto* a = menu->addAction(QFileInfo(path).fileName(), this, [this, path] {
            if (maybeSave()) openMission(path);
        });
        a->setToolTip(path);
        a->setEnabled(QFileInfo::exists(path));
    }
    if (recent.isEmpty()) menu->addAction(tr("(none)"))->setEnabled(false);
}

bool MissionFiles::maybeSave() {
    if (!m_doc->isDirty() || !m_interactive) return true;
    const auto answer = QMessageBox::question(m_window, tr("Unsaved changes"),
                                              m_doc->filePath().isEmpty()
                                                  ? tr("Save the changes to %1 (not saved yet)?").arg(m_doc->displayName())
                                                  : tr("Save the changes to %1?").arg(QFileInfo(m_doc->filePath()).fileName()),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Discard) return true;
    QString path = m_doc->filePath();
    if (path.isEmpty()) path = askMissionSavePath(m_window, tr("Save mission"), QString());
    return !path.isEmpty() && saveMission(path);
}

int MissionFiles::importAreas(const QString& path, ImportRole role, QString* error) {
    auto imported = io::importPolygons(path.toStdString());
    if (!imported && imported.error().code == ErrorCode::InvalidGeometry &&
        importCorridorLine(m_doc, path)) {
        showStatus(
            tr("Imported a corridor's centre line from %1: set its width in the Mission dock")
                .arg(QFileInfo(path).fileName()),
            8000);
        emit missionShown();
        return 1;
    }
    if (!imported) {
        fail(error, tr("Import"), QString::fromStdString(imported.error().message));
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
                            QMessageBox::Cancel, m_window);
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

    // The polygon whose attribute role is "area" is the area (the sample and generated area files);
    // without one, the largest (an area file often carries small features beside it).
    std::size_t largest = 0;
    std::size_t roleAreas = 0;
    for (std::size_t i = 0; i < polys.size(); ++i)
        if (polys[i].role == "area") {
            ++roleAreas;
            largest = i;
        }
    if (areaFromFile && roleAreas != 1) {
        largest = 0;
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
    showStatus(tr("Imported %n polygon(s) from %1", nullptr, count).arg(QFileInfo(path).fileName()), 5000);
    if (!hasArea) emit missionShown();
    return count;
}

int MissionFiles::openWaypointFile(const QString& path, int assignTo, QString* error) {
    auto imported = io::importWaypoints(path.toStdString());
    if (!imported) {
        fail(error, tr("Open waypoint file"), QString::fromStdString(imported.error().message));
        return 0;
    }
    const io::ImportedWaypoints file = std::move(imported).value();
    std::vector<route::Route> routes = file.routes;
    for (auto& r : routes)
        if (!r.home) r.home = file.home;
    if (routes.empty()) {
        const QString why = tr("%1 holds no waypoints.").arg(QFileInfo(path).fileName());
        fail(error, tr("Open waypoint file"), why);
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
            const QString pick = QInputDialog::getItem(m_window, tr("Open waypoint file"),
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
    showStatus(tr("Loaded %n route(s) from %1", nullptr, count).arg(QFileInfo(path).fileName()), 5000);
    return count;
}

} // namespace pf::ui
