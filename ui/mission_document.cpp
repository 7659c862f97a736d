#include "ui/mission_document.h"

#include "core/io/mission_file.h"
#include "core/mission/corridor.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <algorithm>

namespace pf::ui {

MissionDocument::MissionDocument(QObject* parent) : QObject(parent) {
    connect(&m_undo, &QUndoStack::cleanChanged, this, [this](bool clean) { emit dirtyChanged(!clean); });
}

QString MissionDocument::displayName() const {
    if (!m_mission.name.empty()) return QString::fromStdString(m_mission.name);
    if (!m_filePath.isEmpty()) return QFileInfo(m_filePath).completeBaseName();
    return tr("Untitled");
}

void MissionDocument::reset(mission::Mission m, const QString& filePath, bool markDirty) {
    std::vector<route::Route> edited = std::move(m.editedRoutes);
    m.editedRoutes.clear();
    m_mission = std::move(m);
    m_undo.clear();
    if (markDirty) {
        // A recovered mission differs from its file: make the stack unclean so the title shows it.
        m_undo.resetClean();
    } else {
        m_undo.setClean();
    }
    if (m_filePath != filePath) {
        m_filePath = filePath;
        emit filePathChanged(m_filePath);
    }
    m_routes.clear();
    for (auto& r : edited) m_routes.push_back({std::move(r), true});
    ++m_routeGeneration;
    emit routesChanged();
    emit missionReset();
    emit areaChanged();
    emit noFlyZonesChanged();
    emit homeChanged();
    emit aircraftChanged();
    emit changed();
    emit dirtyChanged(isDirty());
}

bool MissionDocument::load(const QString& path, QString* error) {
    auto m = io::readMissionFile(path.toStdString());
    if (!m) {
        if (error) *error = QString::fromStdString(m.error().message);
        return false;
    }
    reset(std::move(m).value(), QFileInfo(path).absoluteFilePath());
    return true;
}

mission::Mission MissionDocument::missionWithEditedRoutes() const {
    mission::Mission m = m_mission;
    for (const auto& r : m_routes)
        if (r.edited) m.editedRoutes.push_back(r.route);
    return m;
}

bool MissionDocument::writeCopy(const QString& path, QString* error) const {
    const mission::Mission m = missionWithEditedRoutes();
    // Never replace a good file with one that cannot be opened again.
    if (auto ok = io::checkWritable(m, path.toStdString()); !ok) {
        if (error) *error = QString::fromStdString(ok.error().message);
        return false;
    }
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        if (error) *error = tr("Cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    const std::string json = io::missionToJson(m);
    f.write(json.data(), qint64(json.size()));
    if (!f.commit()) {
        if (error) *error = tr("Cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

bool MissionDocument::save(const QString& path, QString* error) {
    if (!writeCopy(path, error)) return false;
    const QString abs = QFileInfo(path).absoluteFilePath();
    if (abs != m_filePath) {
        m_filePath = abs;
        emit filePathChanged(m_filePath);
    }
    m_undo.setClean();
    emit dirtyChanged(false);
    return true;
}

geo::GeoPolygon MissionDocument::shape(const ShapeRef& ref) const {
    if (ref.kind == ShapeRef::Kind::Area) return m_mission.area;
    if (ref.kind == ShapeRef::Kind::Corridor)
        return m_mission.corridor ? geo::GeoPolygon{m_mission.corridor->line, {}}
                                  : geo::GeoPolygon{};
    return hasShape(ref) ? m_mission.noFlyZones[std::size_t(ref.index)].polygon : geo::GeoPolygon{};
}

bool MissionDocument::hasShape(const ShapeRef& ref) const {
    if (ref.kind == ShapeRef::Kind::Area) return !m_mission.area.outer.empty();
    if (ref.kind == ShapeRef::Kind::Corridor)
        return m_mission.corridor.has_value();
    return ref.index >= 0 && std::size_t(ref.index) < m_mission.noFlyZones.size();
}

void MissionDocument::setShape(const ShapeRef& ref, const geo::GeoPolygon& poly) {
    if (ref.kind == ShapeRef::Kind::Area) {
        setArea(poly);
        return;
    }
    if (ref.kind == ShapeRef::Kind::Corridor) {
        mission::Corridor c = m_mission.corridor.value_or(mission::Corridor{});
        c.line = poly.outer;
        setCorridor(c);
        return;
    }
    auto zone = m_mission.noFlyZones.at(std::size_t(ref.index));
    zone.polygon = poly;
    setNoFlyZone(ref.index, zone);
}

void MissionDocument::setArea(const geo::GeoPolygon& area) {
    m_mission.area = area;
    emit areaChanged();
    emit changed();
}

void MissionDocument::setCorridor(const std::optional<mission::Corridor>& corridor) {
    mission::applyCorridor(m_mission, corridor);
    emit areaChanged();
    emit changed();
}

void MissionDocument::insertNoFlyZone(int index, const mission::NoFlyZone& zone) {
    auto& z = m_mission.noFlyZones;
    z.insert(z.begin() + std::clamp<std::ptrdiff_t>(index, 0, std::ptrdiff_t(z.size())), zone);
    emit noFlyZonesChanged();
    emit changed();
}

void MissionDocument::removeNoFlyZone(int index) {
    auto& z = m_mission.noFlyZones;
    z.erase(z.begin() + index);
    emit noFlyZonesChanged();
    emit changed();
}

void MissionDocument::setNoFlyZone(int index, const mission::NoFlyZone& zone) {
    m_mission.noFlyZones.at(std::size_t(index)) = zone;
    emit noFlyZonesChanged();
    emit changed();
}

void MissionDocument::setHome(const std::optional<geo::LonLat>& home) {
    m_mission.home = home;
    emit homeChanged();
    emit changed();
}

void MissionDocument::insertAircraft(int index, const mission::AircraftConfig& aircraft) {
    auto& a = m_mission.aircraft;
    a.insert(a.begin() + std::clamp<std::ptrdiff_t>(index, 0, std::ptrdiff_t(a.size())), aircraft);
    emit aircraftChanged();
    emit changed();
}

void MissionDocument::removeAircraft(int index) {
    auto& a = m_mission.aircraft;
    a.erase(a.begin() + index);
    emit aircraftChanged();
    emit changed();
}

void MissionDocument::setAircraft(int index, const mission::AircraftConfig& aircraft) {
    m_mission.aircraft.at(std::size_t(index)) = aircraft;
    emit aircraftChanged();
    emit changed();
}

void MissionDocument::setOptions(const mission::PlannerOptions& options) {
    m_mission.options = options;
    emit optionsChanged();
    emit changed();
}

void MissionDocument::setTerrain(const mission::TerrainOptions& terrain) {
    m_mission.terrain = terrain;
    emit optionsChanged();
    emit changed();
}

QString MissionDocument::nextNoFlyZoneName(const QString& base) const {
    for (int n = 1;; ++n) {
        const std::string candidate = QStringLiteral("%1 %2").arg(base).arg(n).toStdString();
        bool used = false;
        for (const auto& z : m_mission.noFlyZones) used = used || z.name == candidate;
        if (!used) return QString::fromStdString(candidate);
    }
}

bool MissionDocument::anyRouteEdited() const {
    for (const auto& r : m_routes)
        if (r.edited) return true;
    return false;
}

void MissionDocument::setPlannedRoutes(std::vector<route::Route> routes) {
    m_routes.clear();
    for (auto& r : routes) m_routes.push_back({std::move(r), false});
    ++m_routeGeneration;
    emit routesChanged();
}

void MissionDocument::mergePlannedRoutes(std::vector<route::Route> routes) {
    std::vector<PlannedRoute> edited;
    for (auto& r : m_routes)
        if (r.edited) edited.push_back(std::move(r));
    m_routes.clear();
    for (auto& r : routes) {
        auto it = std::find_if(edited.begin(), edited.end(),
                               [&](const PlannedRoute& e) { return e.route.aircraft == r.aircraft; });
        if (it != edited.end()) {
            m_routes.push_back(std::move(*it));
            edited.erase(it);
        } else {
            m_routes.push_back({std::move(r), false});
        }
    }
    for (auto& e : edited) m_routes.push_back(std::move(e));
    ++m_routeGeneration;
    emit routesChanged();
}

void MissionDocument::setRoute(int index, const std::optional<PlannedRoute>& route) {
    if (index < 0 || index > int(m_routes.size())) return;
    if (!route) {
        if (index == int(m_routes.size()) - 1) m_routes.pop_back();
    } else if (index == int(m_routes.size())) {
        m_routes.push_back(*route);
    } else {
        m_routes[std::size_t(index)] = *route;
    }
    emit routesChanged();
}

} // namespace pf::ui
