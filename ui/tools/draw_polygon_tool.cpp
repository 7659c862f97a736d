#include "ui/tools/draw_polygon_tool.h"

#include "ui/commands/add_no_fly_zone_command.h"
#include "ui/commands/set_area_command.h"
#include "ui/geo_adapter.h"
#include "ui/map/map_view.h"
#include "ui/shape_validation.h"

#include <QGraphicsScene>
#include <QKeyEvent>
#include <QMouseEvent>

#include <cmath>

namespace pf::ui {

namespace {
constexpr double kCloseRingPx = 10.0;
}

DrawPolygonTool::DrawPolygonTool(Target target, MissionDocument* doc, MissionLayer* layer, QObject* parent)
    : AbstractTool(target == Target::Area ? tr("Draw area") : tr("Draw no-fly zone"),
                   QIcon(target == Target::Area ? QStringLiteral(":/icons/draw_area.svg")
                                                : QStringLiteral(":/icons/draw_nofly.svg")),
                   QKeySequence(target == Target::Area ? Qt::Key_A : Qt::Key_N), doc, layer, parent),
      m_target(target) {}

DrawPolygonTool::~DrawPolygonTool() = default;

QString DrawPolygonTool::hint() const {
    return m_target == Target::Area
               ? tr("Click the area's corners. Finish: double-click, Enter or the first corner. "
                    "Backspace: last corner off. Esc: cancel.")
               : tr("Click the zone's corners. Finish: double-click, Enter or the first corner. "
                    "Backspace: last corner off. Esc: cancel.");
}

void DrawPolygonTool::deactivate(MapView* view) {
    cancel();
    AbstractTool::deactivate(view);
}

void DrawPolygonTool::mousePressed(QMouseEvent* e, const QPointF& p) {
    if (e->button() == Qt::RightButton) {
        finish();
        return;
    }
    if (e->button() != Qt::LeftButton) return;
    // Clicking the first vertex closes the ring.
    if (m_points.size() >= 3) {
        const QPointF d = p - m_points.first();
        if (std::hypot(d.x(), d.y()) <= pixelsToScene(kCloseRingPx)) {
            finish();
            return;
        }
    }
    // The second click of a double-click arrives here too: do not add a duplicate vertex.
    if (!m_points.isEmpty()) {
        const QPointF d = p - m_points.last();
        if (std::hypot(d.x(), d.y()) <= pixelsToScene(2.0)) return;
    }
    m_points << p;
    updatePreview(p);
}

void DrawPolygonTool::mouseMoved(QMouseEvent*, const QPointF& p) {
    if (!m_points.isEmpty()) updatePreview(p);
}

void DrawPolygonTool::mouseDoubleClicked(QMouseEvent*, const QPointF&) { finish(); }

bool DrawPolygonTool::keyPressed(QKeyEvent* e) {
    switch (e->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter: finish(); return true;
    case Qt::Key_Escape: cancel(); return true;
    case Qt::Key_Backspace:
        if (!m_points.isEmpty()) {
            m_points.removeLast();
            updatePreview(std::nullopt);
        }
        return true;
    default: return false;
    }
}

void DrawPolygonTool::updatePreview(const std::optional<QPointF>& cursor) {
    if (m_points.isEmpty()) {
        m_preview.reset();
        return;
    }
    if (!m_preview && m_view) {
        m_preview = std::make_unique<ShapeItem>(m_target == Target::Area ? ShapeStyle::Area : ShapeStyle::NoFly);
        m_preview->setZValue(60);
        m_view->scene()->addItem(m_preview.get());
    }
    if (!m_preview) return;
    QPolygonF ring = m_points;
    if (cursor && (ring.isEmpty() || ring.last() != *cursor)) ring << *cursor;
    m_preview->setRings({ring});
    m_preview->setClosed(ring.size() >= 3);
    m_preview->setHighlighted(true);
    m_preview->setHandleMargin(pixelsToScene(60));
    QString problem;
    if (ring.size() >= 3) {
        geo::GeoPolygon poly;
        poly.outer = ringFromScene(ring);
        problem = shapeProblem(poly);
    }
    m_preview->setProblem(problem);
    emit statusMessage(problem.isEmpty() ? tr("%n vertices", nullptr, m_points.size())
                                         : problem);
}

bool DrawPolygonTool::finish() {
    if (m_points.size() < 3) {
        if (!m_points.isEmpty()) emit statusMessage(tr("A polygon needs at least 3 vertices."));
        return false;
    }
    geo::GeoPolygon poly;
    poly.outer = ringFromScene(m_points);
    const QString problem = shapeProblem(poly);
    if (!problem.isEmpty()) {
        emit statusMessage(tr("Cannot finish: %1. Click elsewhere, or press Backspace to remove the last vertex.")
                               .arg(problem));
        return false;
    }
    if (m_target == Target::Area) {
        m_doc->undoStack()->push(new SetAreaCommand(m_doc, poly, tr("Draw area")));
        m_layer->select(ShapeRef::area());
    } else {
        mission::NoFlyZone zone;
        zone.name = m_doc->nextNoFlyZoneName(tr("No-fly zone")).toStdString();
        zone.polygon = poly;
        m_doc->undoStack()->push(new AddNoFlyZoneCommand(m_doc, zone));
        m_layer->select(ShapeRef::noFly(int(m_doc->mission().noFlyZones.size()) - 1));
    }
    m_points.clear();
    m_preview.reset();
    emit statusMessage(hint());
    return true;
}

void DrawPolygonTool::cancel() {
    const bool drawing = !m_points.isEmpty();
    m_points.clear();
    m_preview.reset();
    // The drawing's message (e.g. why the ring is invalid) goes with it.
    if (drawing) emit statusMessage(hint());
}

} // namespace pf::ui
