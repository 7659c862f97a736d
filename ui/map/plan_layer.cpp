#include "ui/map/plan_layer.h"

#include "core/fleet/aircraft.h"
#include "core/geo/local_frame.h"
#include "core/io/mission_items.h"
#include "core/mission/aircraft_naming.h"
#include "core/mission/route_check.h"
#include "core/route/route_sorties.h"
#include "core/sensor/footprint.h"
#include "ui/geo_adapter.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"

#include <QGraphicsScene>
#include <QMenu>
#include <QPainter>
#include <QtMath>

#include <algorithm>
#include <cmath>

namespace pf::ui {

namespace {

constexpr qreal kOutdatedOpacity = 0.35;
constexpr qreal kZPartition = 12, kZGrid = 13, kZFootprints = 14, kZUncovered = 16, kZRoutes = 30;

QColor colourFromHex(const std::string& hex, int fallbackIndex) {
    QColor c(QString::fromStdString(hex));
    if (c.isValid())
        return c;
    return QColor(QString::fromStdString(mission::aircraftColour(static_cast<std::size_t>(std::max(0, fallbackIndex)))));
}

QPainterPath ringsPath(const geo::MultiPolygon& polys, const geo::LocalFrame& frame) {
    QPainterPath path;
    path.setFillRule(Qt::OddEvenFill);
    auto addRing = [&](const geo::Ring& r) {
        QPolygonF q;
        for (const auto& p : r)
            q << toScene(frame.toGeo(p));
        if (!q.isEmpty())
            q << q.first();
        path.addPolygon(q);
    };
    for (const auto& poly : polys) {
        addRing(poly.outer);
        for (const auto& h : poly.holes)
            addRing(h);
    }
    return path;
}

void drawArrow(QPainter* p, const QPointF& at, const QPointF& dir, double sizePx, double mpp) {
    const double len = std::hypot(dir.x(), dir.y());
    if (len <= 0)
        return;
    const QPointF u = dir / len, n(-u.y(), u.x());
    const double s = sizePx * mpp;
    QPolygonF tri;
    tri << at + u * s << at - u * s * 0.7 + n * s * 0.75 << at - u * s * 0.35
        << at - u * s * 0.7 - n * s * 0.75;
    p->drawPolygon(tri);
}

} // namespace

// ---------------------------------------------------------------- RouteItem

RouteItem::RouteItem(QGraphicsItem* parent) : QGraphicsItem(parent) {
    setZValue(kZRoutes);
}

void RouteItem::setData(Data d) {
    prepareGeometryChange();
    m_d = std::move(d);
    QPolygonF all(m_d.points);
    if (m_d.home)
        all << *m_d.home;
    all << m_d.landingLeg;
    m_bounds = all.boundingRect();
}

void RouteItem::setSelection(const QList<int>& selected) {
    m_selected = selected;
    update();
}

void RouteItem::setMetresPerPixel(double mpp) {
    prepareGeometryChange();
    m_mpp = mpp;
}

void RouteItem::setPhotosVisible(bool on) {
    m_photos = on;
    update();
}

void RouteItem::setSortiesVisible(bool on) {
    m_sorties = on;
    update();
}

QRectF RouteItem::boundingRect() const {
    const double m = 14 * m_mpp;
    return m_bounds.adjusted(-m, -m, m, m);
}

void RouteItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
    const auto& pts = m_d.points;
    p->setRenderHint(QPainter::Antialiasing);
    const QColor c = m_d.colour;
    // Legs to and from home: thin and dashed, they are transit, not survey.
    if (m_d.home && !pts.isEmpty()) {
        QPen dash(c, 1.6, Qt::DashLine);
        dash.setCosmetic(true);
        p->setPen(dash);
        p->drawLine(*m_d.home, pts.first());
        if (m_d.landingLeg.isEmpty())
            p->drawLine(pts.last(), *m_d.home);
    }
    if (!m_d.landingLeg.isEmpty() && !pts.isEmpty()) {
        QPen dash(c, 1.6, Qt::DashLine);
        dash.setCosmetic(true);
        p->setPen(dash);
        p->drawPolyline(QPolygonF(QVector<QPointF>{pts.last()} + m_d.landingLeg));
    }
    // A light halo under the path keeps it readable on any base map.
    QPen halo(QColor(255, 255, 255, 170), 4.6, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    halo.setCosmetic(true);
    p->setPen(halo);
    p->drawPolyline(pts);
    QPen solid(c, 2.2, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    solid.setCosmetic(true);
    QPen transit(c, 1.6, Qt::DashLine, Qt::RoundCap, Qt::RoundJoin);
    transit.setCosmetic(true);
    for (int i = 0; i + 1 < pts.size(); ++i) {
        const bool isTransit = m_d.transit.value(i) || m_d.transit.value(i + 1);
        p->setPen(isTransit ? transit : solid);
        p->drawLine(pts[i], pts[i + 1]);
    }
    // Direction arrows spaced along the path in screen pixels, so they never clutter at any zoom.
    p->setPen(Qt::NoPen);
    p->setBrush(c.darker(130));
    const double spacing = 140 * m_mpp;
    double carried = spacing * 0.5;
    for (int i = 0; i + 1 < pts.size(); ++i) {
        const QPointF d = pts[i + 1] - pts[i];
        const double len = std::hypot(d.x(), d.y());
        double at = carried;
        while (at < len) {
            drawArrow(p, pts[i] + d * (at / len), d, 6.5, m_mpp);
            at += spacing;
        }
        carried = at - len;
    }
    // Photo points, only when they are far enough apart on screen to be told apart.
    if (m_photos && pts.size() > 1) {
        double total = 0;
        for (int i = 0; i + 1 < pts.size(); ++i)
            total += std::hypot(pts[i + 1].x() - pts[i].x(), pts[i + 1].y() - pts[i].y());
        const double meanPx = total / (pts.size() - 1) / m_mpp;
        if (meanPx > 5) {
            const double r = std::min(2.6, meanPx / 4) * m_mpp;
            p->setPen(QPen(c.darker(150), 0));
            p->setBrush(Qt::white);
            for (int i = 0; i < pts.size(); ++i)
                if (m_d.photo.value(i))
                    p->drawEllipse(pts[i], r, r);
        }
    }
    // Problems of an edited route: red legs and red rings.
    QPen bad(QColor(220, 20, 20), 4.0, Qt::SolidLine, Qt::RoundCap);
    bad.setCosmetic(true);
    for (int i = 0; i + 1 < pts.size(); ++i)
        if (m_d.badLeg.value(i)) {
            p->setPen(bad);
            p->drawLine(pts[i], pts[i + 1]);
        }
    p->setBrush(QColor(220, 20, 20, 200));
    p->setPen(QPen(Qt::white, 0));
    for (int i = 0; i < pts.size(); ++i)
        if (m_d.badPoint.value(i))
            p->drawEllipse(pts[i], 6 * m_mpp, 6 * m_mpp);
    // Sorties: a numbered badge where each battery's flight leaves the path home.
    if (m_sorties && m_d.sortieStarts.size() > 1) {
        QFont f = p->font();
        f.setPixelSize(10);
        f.setBold(true);
        p->setFont(f);
        for (int s = 0; s < m_d.sortieStarts.size(); ++s) {
            const int i = m_d.sortieStarts[s];
            if (i < 0 || i >= pts.size())
                continue;
            const QRectF badge(pts[i].x() - 9 * m_mpp, pts[i].y() - 22 * m_mpp, 18 * m_mpp,
                               13 * m_mpp);
            p->save();
            p->translate(badge.topLeft());
            p->scale(m_mpp, m_mpp);
            const QRectF local(0, 0, 18, 13);
            p->setPen(QPen(Qt::white, 1));
            p->setBrush(c.darker(140));
            p->drawRoundedRect(local, 3, 3);
            p->drawText(local, Qt::AlignCenter, QString::number(s + 1));
            p->restore();
        }
    }
    // Selected waypoints: a ring in the route's colour.
    QPen sel(Qt::black, 2.0);
    sel.setCosmetic(true);
    p->setPen(sel);
    p->setBrush(QColor(255, 255, 255, 220));
    for (int i : m_selected)
        if (i >= 0 && i < pts.size())
            p->drawEllipse(pts[i], 6 * m_mpp, 6 * m_mpp);
}

// ---------------------------------------------------------------- PathItem

PathItem::PathItem(QPainterPath path, QPen pen, QBrush brush, qreal z, QGraphicsItem* parent)
    : QGraphicsItem(parent), m_path(std::move(path)), m_pen(std::move(pen)),
      m_brush(std::move(brush)) {
    m_pen.setCosmetic(true);
    m_bounds = m_path.boundingRect();
    setZValue(z);
}

QRectF PathItem::boundingRect() const {
    return m_bounds;
}

void PathItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
    p->setRenderHint(QPainter::Antialiasing);
    p->setPen(m_pen);
    p->setBrush(m_brush);
    p->drawPath(m_path);
}

// ---------------------------------------------------------------- PlanLayer

PlanLayer::PlanLayer(MissionDocument* doc, PlanController* planner, QGraphicsScene* scene,
                     QObject* parent)
    : QObject(parent), m_doc(doc), m_planner(planner), m_scene(scene) {
    connect(m_planner, &PlanController::planChanged, this, [this] {
        rebuildPlanItems();
        rebuildRoutes();
    });
    connect(m_doc, &MissionDocument::routesChanged, this, &PlanLayer::rebuildRoutes);
    // The no-fly zones and the margin decide which waypoints of an edited route are flagged.
    connect(m_doc, &MissionDocument::changed, this, &PlanLayer::rebuildRoutes);
}

bool PlanLayer::isOutdated() const {
    return m_planner->isOutdated();
}

PlanLayer::~PlanLayer() = default; // the scene owns and deletes the items

void PlanLayer::clearItems(std::vector<QGraphicsItem*>& items) {
    for (auto* i : items) {
        m_scene->removeItem(i);
        delete i;
    }
    items.clear();
}

QColor PlanLayer::colourOf(int route) const {
    const auto& routes = m_doc->routes();
    if (route < 0 || route >= int(routes.size()))
        return Qt::gray;
    const std::string& name = routes[std::size_t(route)].route.aircraft;
    const auto& aircraft = m_doc->mission().aircraft;
    for (std::size_t i = 0; i < aircraft.size(); ++i)
        if (aircraft[i].name == name)
            return colourFromHex(aircraft[i].colour, int(i));
    return colourFromHex(std::string(), route);
}

void PlanLayer::rebuildPlanItems() {
    clearItems(m_partition);
    clearItems(m_grid);
    clearItems(m_footprints);
    clearItems(m_uncovered);
    m_footprintCount = 0;
    const auto& plan = m_planner->plan();
    if (!plan || !plan->frame)
        return;
    // Patches no photo sees (the core's independent coverage check): hatched red.
    for (const auto& u : plan->uncovered) {
        QBrush hatch(QColor(230, 20, 20, 170), Qt::BDiagPattern);
        auto* item = new PathItem(ringsPath(u.shape, *plan->frame), QPen(QColor(200, 0, 0), 1.4),
                                  hatch, kZUncovered);
        item->setToolTip(tr("Not covered by any photo: %1 m²").arg(u.areaM2, 0, 'f', 0));
        m_scene->addItem(item);
        m_uncovered.push_back(item);
    }
    const geo::LocalFrame& frame = *plan->frame;
    const auto& aircraft = m_doc->mission().aircraft;
    for (std::size_t a = 0; a < plan->aircraft.size(); ++a) {
        const auto& ap = plan->aircraft[a];
        QColor c = colourFromHex(std::string(), int(a));
        for (std::size_t k = 0; k < aircraft.size(); ++k)
            if (aircraft[k].name == ap.aircraft)
                c = colourFromHex(aircraft[k].colour, int(k));
        // Partition: the region this aircraft covers.
        QColor fill = c;
        fill.setAlpha(38);
        QColor edge = c;
        edge.setAlpha(140);
        auto* region =
            new PathItem(ringsPath(ap.subarea.empty() ? ap.grid.admissible() : ap.subarea, frame),
                         QPen(edge, 1.2, Qt::DashLine), fill, kZPartition);
        m_scene->addItem(region);
        m_partition.push_back(region);
        // Grid: cells by state (free, shifted, unflyable).
        QPainterPath free, shifted, unflyable;
        for (int i = 0; i < ap.grid.cellCount(); ++i) {
            const auto st = ap.grid.state(i);
            if (st == grid::CellState::Outside)
                continue;
            QPolygonF q;
            for (const auto& v : ap.grid.cellCorners(i))
                q << toScene(frame.toGeo(v));
            if (!q.isEmpty())
                q << q.first();
            (st == grid::CellState::Free      ? free
             : st == grid::CellState::Shifted ? shifted
                                              : unflyable)
                .addPolygon(q);
        }
        const std::pair<QPainterPath*, QColor> parts[] = {{&free, QColor(255, 255, 255, 0)},
                                                          {&shifted, QColor(255, 200, 0, 70)},
                                                          {&unflyable, QColor(220, 30, 30, 90)}};
        for (const auto& [path, brush] : parts) {
            if (path->isEmpty())
                continue;
            auto* g = new PathItem(*path, QPen(QColor(40, 40, 40, 110), 0.6), brush, kZGrid);
            m_scene->addItem(g);
            m_grid.push_back(g);
        }
    }
    applyVisibility();
}

void PlanLayer::rebuildRoutes() {
    const auto& routes = m_doc->routes();
    const auto& m = m_doc->mission();
    while (m_routes.size() > routes.size()) {
        m_scene->removeItem(m_routes.back());
        delete m_routes.back();
        m_routes.pop_back();
    }
    while (m_routes.size() < routes.size()) {
        auto* item = new RouteItem;
        item->setMetresPerPixel(m_mpp);
        m_scene->addItem(item);
        m_routes.push_back(item);
    }
    // A new set of routes (a plan, a reset): indices of the old selection name other waypoints now.
    if (m_generation != m_doc->routeGeneration()) {
        m_generation = m_doc->routeGeneration();
        if (m_selRoute >= 0) {
            m_selRoute = -1;
            m_selWaypoints.clear();
            emit waypointSelectionChanged();
        }
    }
    m_issues.clear();
    m_problems.clear();
    clearItems(m_footprints);
    m_footprintCount = 0;
    const auto& plan = m_planner->plan();
    for (std::size_t r = 0; r < routes.size(); ++r) {
        QPainterPath footprints;
        const auto& pr = routes[r];
        RouteItem::Data d;
        d.colour = colourOf(int(r));
        d.edited = pr.edited;
        std::optional<geo::LonLat> home = pr.route.home ? pr.route.home : m.home;
        if (home)
            d.home = toScene(*home);
        // A plane lands as its vehicle files make it land (the export's default heading).
        const bool plane = std::any_of(m.aircraft.begin(), m.aircraft.end(), [&](const auto& a) {
            return a.name == pr.route.aircraft && fleet::fliesAsPlane(a.kind);
        });
        if (plane) {
            auto leg = io::planeLandingLeg(io::makeExportContext(m, {pr.route}), 0);
            for (const auto& q : leg ? *leg : std::vector<geo::LonLat>{})
                d.landingLeg << toScene(q);
            if (!leg)
                m_problems << tr("%1, landing: %2")
                                  .arg(QString::fromStdString(pr.route.aircraft),
                                       QString::fromStdString(leg.error().message));
        }
        for (const auto& w : pr.route.waypoints) {
            d.points << toScene(w.position);
            d.photo << (w.kind == route::WaypointKind::Photo);
            d.transit << (w.kind == route::WaypointKind::Transit);
        }
        // Sorties as the files and uploads cut them (edited routes too): at the waypoint at home.
        {
            const auto sorties =
                route::sortieRanges(pr.route, mission::routeLimits(m, pr.route).home);
            if (sorties.size() > 1)
                for (const auto& s : sorties)
                    d.sortieStarts << int(s.first);
        }
        RouteIssues issues = validateRoute(m, pr.route);
        const QString who = QString::fromStdString(pr.route.aircraft);
        if (!issues.fromHome.isEmpty())
            m_problems << tr("%1, take-off: %2").arg(who, issues.fromHome);
        if (!issues.toHome.isEmpty())
            m_problems << tr("%1, landing: %2").arg(who, issues.toHome);
        for (std::size_t i = 0; i < issues.waypoint.size(); ++i) {
            d.badPoint << !issues.waypoint[i].isEmpty();
            if (!issues.waypoint[i].isEmpty())
                m_problems << tr("%1, waypoint %2: %3")
                                  .arg(QString::fromStdString(pr.route.aircraft))
                                  .arg(i + 1)
                                  .arg(issues.waypoint[i]);
        }
        for (std::size_t i = 0; i < issues.leg.size(); ++i) {
            d.badLeg << !issues.leg[i].isEmpty();
            if (!issues.leg[i].isEmpty())
                m_problems << tr("%1, waypoint %2: %3")
                                  .arg(QString::fromStdString(pr.route.aircraft))
                                  .arg(i + 1)
                                  .arg(issues.leg[i]);
        }
        m_issues.push_back(std::move(issues));
        m_routes[r]->setData(std::move(d));
        m_routes[r]->setSelection(int(r) == m_selRoute ? m_selWaypoints : QList<int>());
        // Footprints: the real ground rectangle of every photo, turned to the waypoint's heading
        // and scaled with its altitude (an edited altitude changes what the photo covers).
        if (plan && plan->frame) {
            for (const auto& ap : plan->aircraft) {
                if (ap.aircraft != pr.route.aircraft || ap.altitudeM <= 0)
                    continue;
                for (const auto& w : pr.route.waypoints) {
                    if (w.kind != route::WaypointKind::Photo)
                        continue;
                    const sensor::PhotoFootprint f =
                        sensor::photoTakenFrom(plan->frame->toLocal(w.position), w.headingDeg,
                                               ap.footprint.real, w.altitudeM / ap.altitudeM);
                    QPolygonF q;
                    for (const auto& corner : sensor::footprintRing(f))
                        q << toScene(plan->frame->toGeo(corner));
                    q << q.first();
                    footprints.addPolygon(q);
                    ++m_footprintCount;
                }
            }
        }
        if (!footprints.isEmpty()) {
            // In the route's colour, so that overlapping aircraft can be told apart.
            const QColor c = colourOf(int(r));
            QColor edge = c.darker(120), fill = c;
            edge.setAlpha(150);
            fill.setAlpha(22);
            auto* f = new PathItem(footprints, QPen(edge, 0.7), fill, kZFootprints);
            m_scene->addItem(f);
            m_footprints.push_back(f);
        }
    }
    if (m_selRoute >= int(routes.size())) {
        m_selRoute = -1;
        m_selWaypoints.clear();
        emit waypointSelectionChanged();
    }
    applyVisibility();
    emit routeProblemsChanged(m_problems);
}

void PlanLayer::applyVisibility() {
    // An outdated plan is drawn faded: it is not what the mission asks for any more.
    const qreal opacity = isOutdated() ? kOutdatedOpacity : 1.0;
    for (auto* list : {&m_partition, &m_grid, &m_footprints, &m_uncovered})
        for (auto* i : *list)
            i->setOpacity(opacity);
    for (auto* r : m_routes)
        r->setOpacity(opacity);
    for (auto* i : m_partition)
        i->setVisible(isVisible(Part::Partition));
    for (auto* i : m_grid)
        i->setVisible(isVisible(Part::Grid));
    for (auto* i : m_footprints)
        i->setVisible(isVisible(Part::Footprints));
    for (auto* i : m_uncovered)
        i->setVisible(isVisible(Part::Uncovered));
    for (auto* r : m_routes) {
        r->setVisible(isVisible(Part::Paths));
        r->setPhotosVisible(isVisible(Part::Photos));
        r->setSortiesVisible(isVisible(Part::Sorties));
    }
}

void PlanLayer::setVisible(Part part, bool on) {
    m_show[int(part)] = on;
    applyVisibility();
}

bool PlanLayer::isVisible(Part part) const {
    return m_show[int(part)];
}

void PlanLayer::addPartActions(QMenu* menu) {
    const std::pair<Part, QString> parts[] = {
        {Part::Paths, tr("Flight &paths")},       {Part::Photos, tr("P&hoto points")},
        {Part::Footprints, tr("Photo &footprints")}, {Part::Partition, tr("&Partition of the area")},
        {Part::Grid, tr("&Grid cells")},          {Part::Sorties, tr("&Sorties (batteries)")},
        {Part::Uncovered, tr("&Uncovered patches")}};
    for (const auto& [part, text] : parts) {
        auto* a = menu->addAction(text);
        a->setCheckable(true);
        a->setChecked(isVisible(part));
        const auto p = part;
        connect(a, &QAction::toggled, this, [this, p](bool on) { setVisible(p, on); });
    }
}

void PlanLayer::setMetresPerPixel(double mpp) {
    m_mpp = mpp;
    for (auto* r : m_routes)
        r->setMetresPerPixel(mpp);
}

std::optional<PlanLayer::WaypointHit> PlanLayer::hitWaypoint(const QPointF& s,
                                                             double tolerance) const {
    std::optional<WaypointHit> best;
    double bestD = tolerance;
    for (std::size_t r = 0; r < m_routes.size(); ++r) {
        if (!m_routes[r]->isVisible())
            continue;
        const auto& pts = m_routes[r]->data().points;
        for (int i = 0; i < pts.size(); ++i) {
            const double d = std::hypot(pts[i].x() - s.x(), pts[i].y() - s.y());
            if (d <= bestD) {
                bestD = d;
                best = WaypointHit{int(r), i};
            }
        }
    }
    return best;
}

std::optional<PlanLayer::LegHit> PlanLayer::hitLeg(const QPointF& s, double tolerance) const {
    std::optional<LegHit> best;
    double bestD = tolerance;
    for (std::size_t r = 0; r < m_routes.size(); ++r) {
        if (!m_routes[r]->isVisible())
            continue;
        const auto& pts = m_routes[r]->data().points;
        for (int i = 0; i + 1 < pts.size(); ++i) {
            const QPointF a = pts[i], b = pts[i + 1], ab = b - a;
            const double l2 = QPointF::dotProduct(ab, ab);
            const double t =
                l2 > 0 ? std::clamp(QPointF::dotProduct(s - a, ab) / l2, 0.0, 1.0) : 0.0;
            const QPointF q = a + ab * t;
            const double d = std::hypot(q.x() - s.x(), q.y() - s.y());
            if (d <= bestD) {
                bestD = d;
                best = LegHit{int(r), i + 1, q};
            }
        }
    }
    return best;
}

void PlanLayer::selectWaypoints(int route, QList<int> waypoints) {
    if (route < 0 || route >= int(m_routes.size())) {
        route = -1;
        waypoints.clear();
    }
    std::sort(waypoints.begin(), waypoints.end());
    if (route == m_selRoute && waypoints == m_selWaypoints)
        return;
    m_selRoute = route;
    m_selWaypoints = waypoints;
    for (std::size_t r = 0; r < m_routes.size(); ++r)
        m_routes[r]->setSelection(int(r) == route ? waypoints : QList<int>());
    emit waypointSelectionChanged();
}

void PlanLayer::setPreview(int route, int waypoint, std::optional<QPointF> scenePos) {
    if (route < 0 || route >= int(m_routes.size()))
        return;
    if (!scenePos) {
        rebuildRoutes();
        return;
    }
    RouteItem::Data d = m_routes[std::size_t(route)]->data();
    if (waypoint < 0 || waypoint >= d.points.size())
        return;
    d.points[waypoint] = *scenePos;
    m_routes[std::size_t(route)]->setData(std::move(d));
}

} // namespace pf::ui
