#include "ui/tools/select_tool.h"

#include "ui/commands/insert_vertex_command.h"
#include "ui/commands/move_shape_command.h"
#include "ui/commands/move_vertex_command.h"
#include "ui/commands/remove_no_fly_zone_command.h"
#include "ui/commands/remove_vertex_command.h"
#include "ui/commands/set_area_command.h"
#include "ui/commands/set_corridor_command.h"
#include "ui/commands/set_home_command.h"
#include "ui/geo_adapter.h"
#include "ui/map/map_view.h"
#include "ui/shape_validation.h"
#include "ui/tools/draw_corridor_tool.h"

#include <QApplication>
#include <QGraphicsScene>
#include <QKeyEvent>
#include <QMouseEvent>

namespace pf::ui {

namespace {
constexpr double kPickPx = 9.0;
}

SelectTool::SelectTool(MissionDocument* doc, MissionLayer* layer, QObject* parent)
    : AbstractTool(tr("Select and edit"), QIcon(QStringLiteral(":/icons/select.svg")), QKeySequence(Qt::Key_S), doc,
                   layer, parent) {}

SelectTool::~SelectTool() = default;

QString SelectTool::hint() const {
    return tr("Click a shape to select it; drag a vertex or the shape to move it; double-click an edge to add a "
              "vertex; Delete removes the selected vertex or shape.");
}

void SelectTool::deactivate(MapView* view) {
    endDrag();
    AbstractTool::deactivate(view);
}

void SelectTool::mousePressed(QMouseEvent* e, const QPointF& p) {
    if (e->button() != Qt::LeftButton) return;
    const double tol = pixelsToScene(kPickPx);
    m_pressPos = p;
    m_moved = false;
    if (auto v = m_layer->hitVertex(p, tol)) {
        m_layer->select(v->shape, v->vertex);
        m_drag = Drag::Vertex;
        m_dragShape = v->shape;
        m_dragVertex = v->vertex;
        return;
    }
    if (m_layer->hitHome(p, pixelsToScene(14.0))) {
        m_drag = Drag::Home;
        return;
    }
    if (auto s = m_layer->hitShape(p)) {
        m_layer->select(*s);
        m_drag = Drag::Shape;
        m_dragShape = *s;
        return;
    }
    m_layer->select(std::nullopt);
}

void SelectTool::updatePreview(const QPointF& p) {
    if (m_drag == Drag::Home) {
        if (!m_homePreview) {
            m_homePreview = std::make_unique<HomeItem>();
            m_view->scene()->addItem(m_homePreview.get());
            m_layer->setHomeHidden(true);
        }
        m_homePreview->setPos(p);
        return;
    }
    const bool corridor = m_dragShape.kind == ShapeRef::Kind::Corridor;
    if (!m_preview) {
        m_preview = std::make_unique<ShapeItem>(
            m_dragShape.kind == ShapeRef::Kind::NoFlyZone ? ShapeStyle::NoFly : ShapeStyle::Area);
        m_preview->setZValue(60);
        m_preview->setClosed(!corridor);
        m_view->scene()->addItem(m_preview.get());
        m_layer->setShapeHidden(m_dragShape, true);
        if (corridor) { // the ground follows the line as it is dragged
            m_groundPreview = std::make_unique<ShapeItem>(ShapeStyle::Area);
            m_groundPreview->setZValue(59);
            m_view->scene()->addItem(m_groundPreview.get());
            m_layer->setShapeHidden(ShapeRef::area(), true);
        }
    }
    QVector<QPolygonF> rings = m_layer->sceneRings(m_dragShape);
    if (m_drag == Drag::Vertex) {
        rings[m_dragVertex.ring][m_dragVertex.index] = p;
        m_preview->setHighlighted(true, m_dragVertex);
    } else {
        for (auto& r : rings) r.translate(p - m_pressPos);
        m_preview->setHighlighted(true);
    }
    m_preview->setRings(rings);
    m_preview->setHandleMargin(pixelsToScene(60));
    // Live validation while dragging.
    geo::GeoPolygon poly;
    poly.outer = ringFromScene(rings[0]);
    for (int r = 1; r < rings.size(); ++r) poly.holes.push_back(ringFromScene(rings[r]));
    QString problem;
    if (corridor) {
        const mission::Corridor c{poly.outer, DrawCorridorTool::corridorWidthM(m_doc)};
        problem = corridorProblem(c);
        m_groundPreview->setRings(corridorGroundRings(c));
    } else {
        problem = shapeProblem(poly);
    }
    m_preview->setProblem(problem);
    emit statusMessage(problem);
}

void SelectTool::mouseMoved(QMouseEvent* e, const QPointF& p) {
    if (m_drag == Drag::None || !(e->buttons() & Qt::LeftButton)) {
        if (m_view) {
            const double tol = pixelsToScene(kPickPx);
            const bool overVertex = m_layer->hitVertex(p, tol).has_value();
            const bool overShape = m_layer->hitHome(p, pixelsToScene(14)) || m_layer->hitShape(p).has_value();
            m_view->viewport()->setCursor(overVertex ? Qt::CrossCursor : overShape ? Qt::SizeAllCursor : Qt::ArrowCursor);
        }
        return;
    }
    if (!m_moved && m_view &&
        QLineF(m_view->mapFromScene(m_pressPos), m_view->mapFromScene(p)).length() < QApplication::startDragDistance())
        return;
    m_moved = true;
    updatePreview(p);
}

void SelectTool::mouseReleased(QMouseEvent* e, const QPointF& p) {
    if (e->button() != Qt::LeftButton || m_drag == Drag::None) return;
    const Drag drag = m_drag;
    const bool moved = m_moved;
    const ShapeRef shape = m_dragShape;
    const VertexRef vertex = m_dragVertex;
    endDrag();
    if (!moved) return;
    auto* stack = m_doc->undoStack();
    switch (drag) {
    case Drag::Vertex: stack->push(new MoveVertexCommand(m_doc, shape, vertex, fromScene(p))); break;
    case Drag::Shape: stack->push(new MoveShapeCommand(m_doc, shape, p - m_pressPos)); break;
    case Drag::Home: stack->push(new SetHomeCommand(m_doc, fromScene(p))); break;
    case Drag::None: break;
    }
}

void SelectTool::mouseDoubleClicked(QMouseEvent*, const QPointF& p) {
    endDrag();
    if (m_layer->hitVertex(p, pixelsToScene(kPickPx))) return;
    if (auto edge = m_layer->hitEdge(p, pixelsToScene(kPickPx))) {
        m_doc->undoStack()->push(new InsertVertexCommand(m_doc, edge->shape, edge->insertAt, fromScene(edge->point)));
        m_layer->select(edge->shape, edge->insertAt);
    }
}

bool SelectTool::keyPressed(QKeyEvent* e) {
    if (e->key() == Qt::Key_Delete || e->key() == Qt::Key_Backspace) {
        deleteSelection();
        return true;
    }
    if (e->key() == Qt::Key_Escape) {
        endDrag();
        m_layer->select(std::nullopt);
        return true;
    }
    return false;
}

void SelectTool::deleteSelection() {
    const auto shape = m_layer->selectedShape();
    if (!shape) return;
    auto* stack = m_doc->undoStack();
    const bool corridor = shape->kind == ShapeRef::Kind::Corridor;
    if (const auto vertex = m_layer->selectedVertex()) {
        const geo::GeoPolygon poly = m_doc->shape(*shape);
        const auto& ring = vertex->ring == 0 ? poly.outer : poly.holes.at(std::size_t(vertex->ring - 1));
        if (corridor && ring.size() <= 2) {
            emit statusMessage(tr(
                "A corridor's line needs at least 2 points: delete the whole corridor instead."));
            m_layer->select(*shape);
            return;
        }
        if (!corridor && ring.size() <= 3) {
            emit statusMessage(tr("A polygon needs at least 3 vertices: delete the whole shape instead."));
            m_layer->select(*shape);
            return;
        }
        stack->push(new RemoveVertexCommand(m_doc, *shape, *vertex));
        m_layer->select(*shape);
        return;
    }
    if (corridor)
        stack->push(new SetCorridorCommand(m_doc, std::nullopt, tr("Delete corridor")));
    else if (shape->kind == ShapeRef::Kind::Area)
        stack->push(new SetAreaCommand(m_doc, geo::GeoPolygon{}, tr("Delete area")));
    else
        stack->push(new RemoveNoFlyZoneCommand(m_doc, shape->index));
    m_layer->select(std::nullopt);
}

void SelectTool::endDrag() {
    if (m_preview) {
        m_layer->setShapeHidden(m_dragShape, false);
        m_preview.reset();
    }
    if (m_groundPreview) {
        m_layer->setShapeHidden(ShapeRef::area(), false);
        m_groundPreview.reset();
    }
    if (m_homePreview) {
        m_layer->setHomeHidden(false);
        m_homePreview.reset();
    }
    m_drag = Drag::None;
}

} // namespace pf::ui
