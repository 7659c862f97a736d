#include "ui/map/mission_layer.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/mission/corridor.h"
#include "ui/geo_adapter.h"
#include "ui/shape_validation.h"

#include <QGraphicsScene>
#include <QGraphicsView>
#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <cmath>
#include <limits>

namespace pf::ui {

namespace {

constexpr double kHandlePx = 8.0;

struct Palette {
    QColor stroke;
    QColor fill;
};

Palette paletteFor(ShapeStyle style, bool problem) {
    if (problem) return {QColor(245, 130, 0), QColor(255, 170, 0, 70)};
    switch (style) {
    case ShapeStyle::Area: return {QColor(0, 110, 230), QColor(0, 110, 230, 40)};
    case ShapeStyle::NoFly: return {QColor(210, 30, 35), QColor(210, 30, 35, 45)};
    case ShapeStyle::Preview: return {QColor(20, 20, 20), QColor(255, 255, 255, 50)};
    }
    return {};
}

double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b, QPointF* nearest) {
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const QPointF q = a + t * ab;
    if (nearest) *nearest = q;
    return std::hypot(p.x() - q.x(), p.y() - q.y());
}

QString formatArea(double m2) {
    if (m2 >= 10000) return QStringLiteral("%1 ha").arg(m2 / 10000.0, 0, 'f', 2);
    return QStringLiteral("%1 m²").arg(m2, 0, 'f', 0);
}

// A point well inside `rings` (ring 0 outer, others holes) and outside `avoid`, as far as possible from
// every edge: where a label reads best. A coarse grid search is plenty for a label.
std::optional<QPointF> labelPoint(const QVector<QPolygonF>& rings, const QVector<QPolygonF>& avoid) {
    if (rings.isEmpty() || rings[0].size() < 3) return std::nullopt;
    const QRectF box = rings[0].boundingRect();
    std::optional<QPointF> best;
    double bestD = -1;
    constexpr int n = 16;
    for (int i = 1; i < n; ++i) {
        for (int j = 1; j < n; ++j) {
            const QPointF p(box.left() + box.width() * i / n, box.top() + box.height() * j / n);
            if (!rings[0].containsPoint(p, Qt::OddEvenFill)) continue;
            bool blocked = false;
            for (int r = 1; r < rings.size() && !blocked; ++r) blocked = rings[r].containsPoint(p, Qt::OddEvenFill);
            for (const auto& a : avoid) blocked = blocked || a.containsPoint(p, Qt::OddEvenFill);
            if (blocked) continue;
            double d = std::numeric_limits<double>::max();
            auto edges = [&](const QPolygonF& ring) {
                for (int k = 0; k < ring.size(); ++k) d = std::min(d, distanceToSegment(p, ring[k], ring[(k + 1) % ring.size()], nullptr));
            };
            for (const auto& r : rings) edges(r);
            for (const auto& a : avoid) edges(a);
            if (d > bestD) {
                bestD = d;
                best = p;
            }
        }
    }
    return best;
}

} // namespace

// ---------------------------------------------------------------- ShapeItem

namespace {

// A shape's name drawn at a constant screen size above the flight paths (z 45; routes are at 30).
class ShapeLabelItem : public QGraphicsItem {
public:
    // `slot`: the owner's pointer to this label, cleared when the scene deletes the label first.
    explicit ShapeLabelItem(QGraphicsItem** slot) : m_slot(slot) {
        setFlag(ItemIgnoresTransformations);
        setZValue(45);
        setAcceptedMouseButtons(Qt::NoButton);
    }
    void set(const QString& text, const QColor& colour, double shapeWidthScene) {
        prepareGeometryChange();
        m_text = text;
        m_colour = colour;
        m_shapeWidth = shapeWidthScene;
        QFont f;
        f.setPointSizeF(8.5);
        f.setBold(true);
        m_font = f;
        m_box = QRectF(QFontMetricsF(f).boundingRect(m_text)).adjusted(-5, -2, 5, 2);
        m_box.moveCenter(QPointF(0, 0));
        setVisible(!m_text.isEmpty());
    }
    ~ShapeLabelItem() override {
        if (m_slot) *m_slot = nullptr;
    }
    void release() { m_slot = nullptr; }
    QRectF boundingRect() const override { return m_box; }
    void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget* widget) override {
        // Only where the label fits its shape on screen.
        auto* view = widget ? qobject_cast<QGraphicsView*>(widget->parentWidget()) : nullptr;
        if (view && m_box.width() > m_shapeWidth * view->transform().m11() * 1.5) return;
        p->setRenderHint(QPainter::Antialiasing);
        p->setPen(Qt::NoPen);
        p->setBrush(QColor(255, 255, 255, 210));
        p->drawRoundedRect(m_box, 3, 3);
        p->setFont(m_font);
        p->setPen(m_colour);
        p->drawText(m_box, Qt::AlignCenter, m_text);
    }

private:
    QString m_text;
    QColor m_colour;
    QFont m_font;
    QRectF m_box;
    double m_shapeWidth = 0;
    QGraphicsItem** m_slot;
};

} // namespace

ShapeItem::ShapeItem(ShapeStyle style, QGraphicsItem* parent) : QGraphicsItem(parent), m_style(style) {
    setZValue(style == ShapeStyle::Area ? 10 : style == ShapeStyle::NoFly ? 20 : 50);
    m_labelItem = new ShapeLabelItem(&m_labelItem);
    m_labelItem->setVisible(false);
}

ShapeItem::~ShapeItem() {
    if (!m_labelItem) return;
    static_cast<ShapeLabelItem*>(m_labelItem)->release();
    delete m_labelItem;
}

QVariant ShapeItem::itemChange(GraphicsItemChange change, const QVariant& value) {
    if (!m_labelItem) return QGraphicsItem::itemChange(change, value);
    if (change == ItemSceneHasChanged) {
        if (m_labelItem->scene()) m_labelItem->scene()->removeItem(m_labelItem);
        if (scene()) scene()->addItem(m_labelItem);
    }
    if (change == ItemVisibleHasChanged) m_labelItem->setVisible(isVisible() && !m_label.isEmpty());
    return QGraphicsItem::itemChange(change, value);
}

void ShapeItem::placeLabel() {
    if (!m_labelItem) return;
    QRectF r;
    for (const auto& ring : m_rings) r = r.united(ring.boundingRect());
    const Palette pal = paletteFor(m_style, !m_problem.isEmpty());
    static_cast<ShapeLabelItem*>(m_labelItem)->set(m_rings.isEmpty() ? QString() : m_label, pal.stroke.darker(130), r.width());
    m_labelItem->setPos(m_labelAnchor ? *m_labelAnchor : r.center());
    m_labelItem->setVisible(isVisible() && !m_label.isEmpty() && !m_rings.isEmpty());
}

void ShapeItem::setRings(const QVector<QPolygonF>& rings) {
    prepareGeometryChange();
    m_rings = rings;
    placeLabel();
}

void ShapeItem::setProblem(const QString& problem) {
    m_problem = problem;
    placeLabel();
    update();
}

void ShapeItem::setLabel(const QString& label) {
    m_label = label;
    placeLabel();
    update();
}

void ShapeItem::setLabelAnchor(std::optional<QPointF> anchor) {
    m_labelAnchor = anchor;
    placeLabel();
    update();
}

void ShapeItem::setHighlighted(bool on, std::optional<VertexRef> vertex) {
    m_highlighted = on;
    m_vertex = vertex;
    update();
}

void ShapeItem::setClosed(bool closed) {
    m_closed = closed;
    update();
}

void ShapeItem::setHandleMargin(double sceneMetres) {
    prepareGeometryChange();
    m_margin = sceneMetres;
}

QPainterPath ShapeItem::path() const {
    QPainterPath p;
    p.setFillRule(Qt::OddEvenFill);
    for (const auto& ring : m_rings) {
        if (ring.isEmpty()) continue;
        p.moveTo(ring.first());
        for (int i = 1; i < ring.size(); ++i) p.lineTo(ring[i]);
        if (m_closed) p.closeSubpath();
    }
    return p;
}

QRectF ShapeItem::boundingRect() const {
    QRectF r;
    for (const auto& ring : m_rings) r = r.united(ring.boundingRect());
    // Labels and handles are drawn in screen pixels around the shape.
    return r.adjusted(-m_margin, -m_margin, m_margin, m_margin);
}

QPainterPath ShapeItem::shape() const { return path(); }

void ShapeItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
    if (m_rings.isEmpty()) return;
    const Palette pal = paletteFor(m_style, !m_problem.isEmpty());
    const QTransform toDevice = painter->worldTransform();
    // Everything is drawn in device pixels so line widths, hatching and handles keep their
    // on-screen size at every zoom.
    QPainterPath devicePath = toDevice.map(path());
    devicePath.setFillRule(Qt::OddEvenFill);
    painter->save();
    painter->resetTransform();
    painter->setRenderHint(QPainter::Antialiasing);
    if (m_closed) {
        painter->setPen(Qt::NoPen);
        painter->setBrush(pal.fill);
        painter->drawPath(devicePath);
        if (m_style == ShapeStyle::NoFly || !m_problem.isEmpty()) {
            QBrush hatch(QColor(pal.stroke.red(), pal.stroke.green(), pal.stroke.blue(), 150),
                         m_problem.isEmpty() ? Qt::BDiagPattern : Qt::DiagCrossPattern);
            painter->setBrush(hatch);
            painter->drawPath(devicePath);
        }
    }
    // A white casing under the coloured stroke keeps outlines readable on any base map.
    const double width = m_highlighted ? 3.5 : 2.5;
    painter->setBrush(Qt::NoBrush);
    painter->setPen(QPen(QColor(255, 255, 255, 200), width + 2.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter->drawPath(devicePath);
    QPen stroke(pal.stroke, width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    if (!m_problem.isEmpty() || m_style == ShapeStyle::Preview) stroke.setStyle(Qt::DashLine);
    painter->setPen(stroke);
    painter->drawPath(devicePath);

    if (m_highlighted || m_style == ShapeStyle::Preview) {
        for (int r = 0; r < m_rings.size(); ++r) {
            for (int i = 0; i < m_rings[r].size(); ++i) {
                const QPointF c = toDevice.map(m_rings[r][i]);
                const bool sel = m_vertex && m_vertex->ring == r && m_vertex->index == i;
                painter->setPen(QPen(pal.stroke.darker(120), 1.5));
                painter->setBrush(sel ? pal.stroke : QColor(Qt::white));
                const double h = sel ? kHandlePx + 3 : kHandlePx;
                painter->drawRect(QRectF(c.x() - h / 2, c.y() - h / 2, h, h));
            }
        }
    }
    painter->restore();
}

// ---------------------------------------------------------------- HomeItem

HomeItem::HomeItem(QGraphicsItem* parent) : QGraphicsItem(parent) {
    setFlag(ItemIgnoresTransformations);
    setZValue(40);
}

QRectF HomeItem::boundingRect() const { return {-16, -16, 32, 32}; }

void HomeItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
    // A helipad: white disc, dark ring, "H".
    p->setRenderHint(QPainter::Antialiasing);
    p->setPen(QPen(QColor(0, 0, 0, 90), 1));
    p->setBrush(QColor(0, 0, 0, 60));
    p->drawEllipse(QPointF(1.5, 1.5), 13, 13);
    p->setPen(QPen(QColor(20, 120, 60), 3));
    p->setBrush(Qt::white);
    p->drawEllipse(QPointF(0, 0), 12, 12);
    QFont f = p->font();
    f.setPixelSize(14);
    f.setBold(true);
    p->setFont(f);
    p->setPen(QColor(20, 120, 60));
    p->drawText(QRectF(-12, -12, 24, 24), Qt::AlignCenter, QStringLiteral("H"));
}

// ---------------------------------------------------------------- MissionLayer

MissionLayer::MissionLayer(MissionDocument* doc, QGraphicsScene* scene, QObject* parent)
    : QObject(parent), m_doc(doc), m_scene(scene) {
    connect(doc, &MissionDocument::changed, this, &MissionLayer::rebuild);
    connect(doc, &MissionDocument::missionReset, this, [this] { select(std::nullopt); });
    rebuild();
}

// The items belong to the scene, which deletes them; the layer never outlives the window's scene.
MissionLayer::~MissionLayer() = default;

QVector<QPolygonF> MissionLayer::sceneRings(const ShapeRef& ref) const {
    QVector<QPolygonF> rings;
    if (!m_doc->hasShape(ref)) return rings;
    const geo::GeoPolygon poly = m_doc->shape(ref);
    rings << toScene(poly.outer);
    for (const auto& h : poly.holes) rings << toScene(h);
    return rings;
}

ShapeItem* MissionLayer::itemFor(const ShapeRef& ref) const {
    if (ref.kind == ShapeRef::Kind::Area) return m_area;
    if (ref.kind == ShapeRef::Kind::Corridor)
        return m_corridorLine;
    return ref.index >= 0 && std::size_t(ref.index) < m_noFly.size() ? m_noFly[std::size_t(ref.index)] : nullptr;
}

void MissionLayer::rebuild() {
    const auto& m = m_doc->mission();
    QStringList problems;
    const double margin = 60 * m_mpp;
    if (!m_area) {
        m_area = new ShapeItem(ShapeStyle::Area);
        m_scene->addItem(m_area);
    }
    m_area->setRings(sceneRings(ShapeRef::area()));
    m_area->setHandleMargin(margin);
    if (!m_corridorLine) {
        m_corridorLine = new ShapeItem(ShapeStyle::Area);
        m_corridorLine->setClosed(false);
        m_corridorLine->setZValue(11);
        m_scene->addItem(m_corridorLine);
    }
    m_corridorLine->setRings(sceneRings(ShapeRef::corridor()));
    m_corridorLine->setHandleMargin(margin);
    if (m.corridor) {
        // The corridor's ground is the area: its problems are the line's and the width's.
        const QString problem = corridorProblem(*m.corridor);
        m_corridorLine->setProblem(problem);
        m_area->setProblem({});
        if (!problem.isEmpty())
            problems << problem;
        m_area->setLabel(problem.isEmpty()
                             ? tr("Corridor · %1 km × %2 m")
                                   .arg(mission::corridorLengthM(*m.corridor) / 1000.0, 0, 'f', 2)
                                   .arg(m.corridor->widthM, 0, 'f', 0)
                             : tr("Corridor (invalid)"));
        m_area->setLabelAnchor(std::nullopt);
    } else if (!m.area.outer.empty()) {
        const QString problem = shapeProblem(m.area, tr("the area"));
        m_area->setProblem(problem);
        if (!problem.isEmpty()) problems << problem;
        m_area->setLabel(problem.isEmpty() ? tr("Area · %1").arg(formatArea(geo::groundAreaM2(m.area))) : tr("Area (invalid)"));
        QVector<QPolygonF> zones;
        for (std::size_t i = 0; i < m.noFlyZones.size(); ++i) zones << toScene(m.noFlyZones[i].polygon.outer);
        m_area->setLabelAnchor(labelPoint(sceneRings(ShapeRef::area()), zones));
    } else {
        m_area->setProblem({});
        m_area->setLabel({});
    }
    while (m_noFly.size() > m.noFlyZones.size()) {
        delete m_noFly.back();
        m_noFly.pop_back();
    }
    while (m_noFly.size() < m.noFlyZones.size()) {
        m_noFly.push_back(new ShapeItem(ShapeStyle::NoFly));
        m_scene->addItem(m_noFly.back());
    }
    for (std::size_t i = 0; i < m.noFlyZones.size(); ++i) {
        ShapeItem* item = m_noFly[i];
        item->setRings(sceneRings(ShapeRef::noFly(int(i))));
        item->setHandleMargin(margin);
        const QString name = QString::fromStdString(m.noFlyZones[i].name);
        const QString problem = shapeProblem(m.noFlyZones[i].polygon, tr("no-fly zone \"%1\"").arg(name));
        item->setProblem(problem);
        item->setLabel(name);
        if (!problem.isEmpty()) problems << problem;
    }
    if (m.home) {
        if (!m_home) {
            m_home = new HomeItem();
            m_scene->addItem(m_home);
        }
        m_home->setPos(toScene(*m.home));
        m_home->setToolTip(tr("Home / take-off point"));
    } else if (m_home) {
        delete m_home;
        m_home = nullptr;
    }
    // Keep the selection if it still points at something.
    if (m_selected && !m_doc->hasShape(*m_selected)) {
        m_selected.reset();
        m_selectedVertex.reset();
    }
    if (m_selected && m_selectedVertex) {
        const auto rings = sceneRings(*m_selected);
        if (m_selectedVertex->ring >= rings.size() || m_selectedVertex->index >= rings[m_selectedVertex->ring].size())
            m_selectedVertex.reset();
    }
    applySelection();
    if (problems != m_problems) {
        m_problems = problems;
        emit problemsChanged(m_problems);
    }
}

void MissionLayer::applySelection() {
    if (m_area) m_area->setHighlighted(m_selected && *m_selected == ShapeRef::area(), m_selectedVertex);
    if (m_corridorLine)
        m_corridorLine->setHighlighted(m_selected && *m_selected == ShapeRef::corridor(),
                                       m_selectedVertex);
    for (std::size_t i = 0; i < m_noFly.size(); ++i)
        m_noFly[i]->setHighlighted(m_selected && *m_selected == ShapeRef::noFly(int(i)), m_selectedVertex);
}

void MissionLayer::select(std::optional<ShapeRef> shape, std::optional<VertexRef> vertex) {
    if (shape && !m_doc->hasShape(*shape)) shape.reset();
    m_selected = shape;
    m_selectedVertex = shape ? vertex : std::nullopt;
    applySelection();
    emit selectionChanged();
}

void MissionLayer::setShapeHidden(const ShapeRef& ref, bool hidden) {
    if (ShapeItem* item = itemFor(ref)) item->setVisible(!hidden);
}

void MissionLayer::setHomeHidden(bool hidden) {
    if (m_home) m_home->setVisible(!hidden);
}

void MissionLayer::setMetresPerPixel(double mpp) {
    if (std::abs(mpp - m_mpp) < 1e-12) return;
    m_mpp = mpp;
    if (m_area) m_area->setHandleMargin(60 * mpp);
    if (m_corridorLine)
        m_corridorLine->setHandleMargin(60 * mpp);
    for (auto* item : m_noFly) item->setHandleMargin(60 * mpp);
}

QRectF MissionLayer::missionBounds() const {
    QRectF r;
    const auto& m = m_doc->mission();
    auto add = [&](const QPointF& p) { r = r.isNull() ? QRectF(p, QSizeF(1e-3, 1e-3)) : r.united(QRectF(p, QSizeF(1e-3, 1e-3))); };
    for (const auto& p : m.area.outer) add(toScene(p));
    for (const auto& z : m.noFlyZones)
        for (const auto& p : z.polygon.outer) add(toScene(p));
    if (m.home) add(toScene(*m.home));
    return r;
}

namespace {
std::vector<ShapeRef> hitOrder(const std::optional<ShapeRef>& selected,
                               const MissionDocument& doc) {
    std::vector<ShapeRef> order;
    if (selected) order.push_back(*selected);
    for (std::size_t i = doc.mission().noFlyZones.size(); i-- > 0;)
        if (!selected || *selected != ShapeRef::noFly(int(i))) order.push_back(ShapeRef::noFly(int(i)));
    // A corridor's ground is edited through its line: the corridor is the shape, not the area.
    const ShapeRef ground = doc.mission().corridor ? ShapeRef::corridor() : ShapeRef::area();
    if (doc.hasShape(ground) && (!selected || *selected != ground))
        order.push_back(ground);
    return order;
}
} // namespace

std::optional<MissionLayer::VertexHit> MissionLayer::hitVertex(const QPointF& p, double tol) const {
    for (const auto& ref : hitOrder(m_selected, *m_doc)) {
        const auto rings = sceneRings(ref);
        std::optional<VertexHit> best;
        double bestD = tol;
        for (int r = 0; r < rings.size(); ++r)
            for (int i = 0; i < rings[r].size(); ++i) {
                const double d = std::hypot(rings[r][i].x() - p.x(), rings[r][i].y() - p.y());
                if (d <= bestD) {
                    bestD = d;
                    best = VertexHit{ref, VertexRef{r, i}};
                }
            }
        if (best) return best;
    }
    return std::nullopt;
}

std::optional<MissionLayer::EdgeHit> MissionLayer::hitEdge(const QPointF& p, double tol) const {
    for (const auto& ref : hitOrder(m_selected, *m_doc)) {
        const auto rings = sceneRings(ref);
        std::optional<EdgeHit> best;
        double bestD = tol;
        // A corridor's line is open: no edge from its last point back to its first.
        const int open = ref.kind == ShapeRef::Kind::Corridor ? 1 : 0;
        for (int r = 0; r < rings.size(); ++r) {
            const QPolygonF& ring = rings[r];
            for (int i = 0; i + open < ring.size(); ++i) {
                QPointF q;
                const double d = distanceToSegment(p, ring[i], ring[(i + 1) % ring.size()], &q);
                if (d <= bestD) {
                    bestD = d;
                    best = EdgeHit{ref, VertexRef{r, i + 1}, q};
                }
            }
        }
        if (best) return best;
    }
    return std::nullopt;
}

std::optional<ShapeRef> MissionLayer::hitShape(const QPointF& p) const {
    for (const auto& ref : hitOrder(std::nullopt, *m_doc)) {
        // Inside a corridor is inside its ground.
        const auto rings =
            sceneRings(ref.kind == ShapeRef::Kind::Corridor ? ShapeRef::area() : ref);
        if (rings.isEmpty()) continue;
        bool inside = rings[0].containsPoint(p, Qt::OddEvenFill);
        for (int r = 1; r < rings.size() && inside; ++r)
            if (rings[r].containsPoint(p, Qt::OddEvenFill)) inside = false;
        if (inside) return ref;
    }
    return std::nullopt;
}

bool MissionLayer::hitHome(const QPointF& p, double tol) const {
    const auto& home = m_doc->mission().home;
    if (!home) return false;
    const QPointF h = toScene(*home);
    return std::hypot(h.x() - p.x(), h.y() - p.y()) <= tol;
}

} // namespace pf::ui
