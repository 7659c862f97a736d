// PlanLayer: the scene items showing the planned and edited routes (paths with direction arrows,
// photo points, footprints, the partition of the area, the grid, problems of edited routes), in
// z-order.
#pragma once

#include "ui/planning/route_validation.h"

#include <QBrush>
#include <QColor>
#include <QGraphicsItem>
#include <QList>
#include <QObject>
#include <QPainterPath>
#include <QPen>

#include <optional>
#include <vector>

class QGraphicsScene;
class QMenu;

namespace pf::ui {

class MissionDocument;
class PlanController;

// One route: its path with arrows, photo points, the selection and the flagged waypoints and legs.
class RouteItem : public QGraphicsItem {
public:
    RouteItem(QGraphicsItem* parent = nullptr);
    struct Data {
        QColor colour;
        QVector<QPointF> points; // scene, flight order
        QVector<bool> photo;     // per point: a photo waypoint
        QVector<bool> transit;   // per point: a transit waypoint
        std::optional<QPointF> home;
        // A plane's way down after the last point (its approach, its landing); empty: back home.
        QVector<QPointF> landingLeg;
        QVector<bool> badPoint; // per point
        QVector<bool> badLeg;   // per leg i -> i + 1
        QVector<int>
            sortieStarts; // first waypoint of every battery's flight (more than one sortie)
        bool edited = false;
    };
    void setData(Data d);
    const Data& data() const { return m_d; }
    void setSelection(const QList<int>& selected);
    void setMetresPerPixel(double mpp);
    void setPhotosVisible(bool on);
    void setSortiesVisible(bool on);

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    Data m_d;
    QList<int> m_selected;
    QRectF m_bounds;
    double m_mpp = 1.0;
    bool m_photos = true;
    bool m_sorties = true;
};

// A fixed path painted with a pen and a brush (grid cells, footprints, partition fills).
class PathItem : public QGraphicsItem {
public:
    PathItem(QPainterPath path, QPen pen, QBrush brush, qreal z, QGraphicsItem* parent = nullptr);
    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;
    const QPainterPath& path() const { return m_path; }

private:
    QPainterPath m_path;
    QPen m_pen;
    QBrush m_brush;
    QRectF m_bounds;
};

class PlanLayer : public QObject {
    Q_OBJECT
public:
    PlanLayer(MissionDocument* doc, PlanController* planner, QGraphicsScene* scene,
              QObject* parent = nullptr);
    ~PlanLayer() override;

    enum class Part { Paths, Photos, Footprints, Partition, Grid, Sorties, Uncovered };
    void setVisible(Part part, bool on);
    bool isVisible(Part part) const;
    // One checkable action per part (Flight paths, Photo points, …) into `menu`, toggling it.
    void addPartActions(QMenu* menu);

    void setMetresPerPixel(double mpp);

    struct WaypointHit {
        int route = -1;
        int waypoint = -1;
    };
    struct LegHit {
        int route = -1;
        int insertAt = -1; // index the new waypoint gets
        QPointF point;     // nearest point on the leg (scene)
    };
    std::optional<WaypointHit> hitWaypoint(const QPointF& scenePos, double tolerance) const;
    std::optional<LegHit> hitLeg(const QPointF& scenePos, double tolerance) const;

    int selectedRoute() const { return m_selRoute; }
    QList<int> selectedWaypoints() const { return m_selWaypoints; }
    void selectWaypoints(int route, QList<int> waypoints);

    // Hides one waypoint's drawn position while a tool drags its preview.
    void setPreview(int route, int waypoint, std::optional<QPointF> scenePos);

    // Items, for tests and the screenshot: one RouteItem per route.
    const std::vector<RouteItem*>& routeItems() const { return m_routes; }
    int footprintCount() const { return m_footprintCount; }
    int uncoveredPatchCount() const { return int(m_uncovered.size()); }
    // Problems of the edited routes in words, one per flagged waypoint or leg.
    QStringList routeProblems() const { return m_problems; }
    const std::vector<RouteIssues>& issues() const { return m_issues; }
    QColor colourOf(int route) const;
    // The plan drawn is outdated (the mission changed since): every item is drawn faded.
    bool isOutdated() const;

signals:
    void waypointSelectionChanged();
    void routeProblemsChanged(const QStringList& problems);

private:
    void rebuildPlanItems();
    void rebuildRoutes();
    void clearItems(std::vector<QGraphicsItem*>& items);
    void applyVisibility();

    MissionDocument* m_doc;
    PlanController* m_planner;
    QGraphicsScene* m_scene;
    std::vector<RouteItem*> m_routes;
    std::vector<QGraphicsItem*> m_partition;
    std::vector<QGraphicsItem*> m_grid;
    std::vector<QGraphicsItem*> m_footprints;
    std::vector<QGraphicsItem*> m_uncovered;
    std::vector<RouteIssues> m_issues;
    QStringList m_problems;
    int m_footprintCount = 0;
    int m_selRoute = -1;
    int m_generation = -1; // the document's route generation the selection belongs to
    QList<int> m_selWaypoints;
    double m_mpp = 1.0;
    bool m_show[7] = {true, true, false, true, false, true, true};
};

} // namespace pf::ui
