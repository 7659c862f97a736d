// MissionDocument: one open mission, its undo stack, file path and dirty state.
#pragma once

#include "core/mission/mission.h"
#include "core/route/waypoint.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

namespace pf::ui {

// Addresses one editable shape of the mission: the area, a no-fly zone or the corridor's centre
// line (its vertices as the "outer ring" of an open shape: the vertex commands edit it as they edit
// a ring).
struct ShapeRef {
    enum class Kind { Area, NoFlyZone, Corridor };
    Kind kind = Kind::Area;
    int index = 0; // no-fly zone index; 0 for the area and the corridor
    static ShapeRef area() { return {Kind::Area, 0}; }
    static ShapeRef noFly(int i) { return {Kind::NoFlyZone, i}; }
    static ShapeRef corridor() { return {Kind::Corridor, 0}; }
    friend bool operator==(const ShapeRef& a, const ShapeRef& b) { return a.kind == b.kind && a.index == b.index; }
    friend bool operator!=(const ShapeRef& a, const ShapeRef& b) { return !(a == b); }
};

// Edits go through undo commands (ui/commands/), which call the setters below; the setters
// emit the signals that views listen to. Nothing else should call the setters.
class MissionDocument : public QObject {
    Q_OBJECT
public:
    explicit MissionDocument(QObject* parent = nullptr);

    const mission::Mission& mission() const { return m_mission; }
    QUndoStack* undoStack() { return &m_undo; }

    QString filePath() const { return m_filePath; }
    // The mission's name, or the file name, or "Untitled".
    QString displayName() const;
    bool isDirty() const { return !m_undo.isClean(); }

    // Replaces the whole mission (new, open, recover): clears the undo history. The mission's
    // editedRoutes become the document's routes, marked edited (so a new plan waits for consent).
    // `markDirty` is for recovered autosaves, which differ from what is on disk.
    void reset(mission::Mission m, const QString& filePath, bool markDirty = false);
    // The mission as it is saved: mission() plus the routes marked edited, in their order.
    mission::Mission missionWithEditedRoutes() const;
    // Reads a mission file; on failure the document is unchanged and `error` says why.
    bool load(const QString& path, QString* error);
    // Writes atomically (QSaveFile), edited routes included, and marks the document clean.
    bool save(const QString& path, QString* error);
    // Writes a copy (edited routes included) without changing the path or the clean state (autosave).
    bool writeCopy(const QString& path, QString* error) const;

    // --- setters used by undo commands ---
    geo::GeoPolygon shape(const ShapeRef& ref) const;
    bool hasShape(const ShapeRef& ref) const;
    void setShape(const ShapeRef& ref, const geo::GeoPolygon& poly);
    void setArea(const geo::GeoPolygon& area);
    // The corridor (its line and width) and with it the area, its ground; nullopt: an area mission
    // again, without an area.
    void setCorridor(const std::optional<mission::Corridor>& corridor);
    void insertNoFlyZone(int index, const mission::NoFlyZone& zone);
    void removeNoFlyZone(int index);
    void setNoFlyZone(int index, const mission::NoFlyZone& zone);
    void setHome(const std::optional<geo::LonLat>& home);
    void insertAircraft(int index, const mission::AircraftConfig& aircraft);
    void removeAircraft(int index);
    void setAircraft(int index, const mission::AircraftConfig& aircraft);
    void setOptions(const mission::PlannerOptions& options);
    // Terrain following and its DEM (emits optionsChanged: planning reads them).
    void setTerrain(const mission::TerrainOptions& terrain);
    // "<base> N" with the smallest N no zone is named after: each kind of zone counts on its own
    // ("Circle 1", "No-fly zone 1").
    QString nextNoFlyZoneName(const QString& base) const;

    // --- the planned (and possibly hand-edited) routes, one per planned aircraft ---
    // mission() never holds them (planning must not see them). Saving writes the routes marked
    // `edited` into the mission file (mission::Mission::editedRoutes); unedited ones are recomputed.
    // A route marked `edited` was changed by hand and is never replaced without the user's consent.
    struct PlannedRoute {
        route::Route route;
        bool edited = false;
    };
    const std::vector<PlannedRoute>& routes() const { return m_routes; }
    bool anyRouteEdited() const;
    // Counts replacements of the whole set (a new plan, a reset): route edit commands recorded
    // against an older set become obsolete instead of restoring routes of a replaced plan.
    int routeGeneration() const { return m_routeGeneration; }
    // A new plan: replaces every route, clears the edited marks.
    void setPlannedRoutes(std::vector<route::Route> routes);
    // A new plan that keeps the edits: each aircraft with a route edited by hand keeps it, the others
    // get the new plan's route; edited routes of aircraft the plan no longer has are kept at the end.
    void mergePlannedRoutes(std::vector<route::Route> routes);
    // One route (an edit or an import). index == routes().size() appends; nullopt removes the last.
    void setRoute(int index, const std::optional<PlannedRoute>& route);

signals:
    void areaChanged();
    void noFlyZonesChanged();
    void homeChanged();
    void aircraftChanged();
    void optionsChanged();
    // Routes changed (not part of `changed`: editing a route must not trigger a new plan).
    void routesChanged();
    // Any change of content (including reset); views that draw everything listen to this one.
    void changed();
    // The whole mission was replaced.
    void missionReset();
    void dirtyChanged(bool dirty);
    void filePathChanged(const QString& path);

private:
    mission::Mission m_mission;
    QUndoStack m_undo;
    QString m_filePath;
    std::vector<PlannedRoute> m_routes;
    int m_routeGeneration = 0;
};

} // namespace pf::ui
