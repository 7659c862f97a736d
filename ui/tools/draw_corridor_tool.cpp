#include "ui/tools/draw_corridor_tool.h"

#include "core/mission/corridor.h"
#include "ui/commands/set_corridor_command.h"
#include "ui/geo_adapter.h"
#include "ui/map/map_view.h"
#include "ui/shape_validation.h"

#include <QGraphicsScene>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QSettings>

#include <cmath>

namespace pf::ui {

namespace {
constexpr double kDefaultWidthM = 50.0;
const char* const kWidthKey = "corridor/widthM";
} // namespace

QVector<QPolygonF> corridorGroundRings(const mission::Corridor& corridor) {
    QVector<QPolygonF> rings;
    auto ground = mission::corridorArea(corridor);
    if (!ground)
        return rings;
    rings << toScene(ground->outer);
    for (const auto& h : ground->holes)
        rings << toScene(h);
    return rings;
}

DrawCorridorTool::DrawCorridorTool(MissionDocument* doc, MissionLayer* layer, QObject* parent)
    : AbstractTool(tr("Draw corridor"), QIcon(QStringLiteral(":/icons/draw_corridor.svg")),
                   QKeySequence(Qt::Key_R), doc, layer, parent) {}

DrawCorridorTool::~DrawCorridorTool() = default;

QString DrawCorridorTool::hint() const {
    return tr("Click the corridor's centre line point by point (a road, a river, a pipeline). "
              "Finish: double-click or "
              "Enter. Backspace: last point off. Esc: cancel. Width: %1 m (Mission dock).")
        .arg(corridorWidthM(m_doc), 0, 'f', 0);
}

double DrawCorridorTool::corridorWidthM(const MissionDocument* doc) {
    if (doc && doc->mission().corridor && doc->mission().corridor->widthM > 0)
        return doc->mission().corridor->widthM;
    const double w = QSettings().value(QLatin1String(kWidthKey), kDefaultWidthM).toDouble();
    return w > 0 && w <= mission::kMaxCorridorWidthM ? w : kDefaultWidthM;
}

void DrawCorridorTool::rememberWidthM(double widthM) {
    if (widthM > 0 && widthM <= mission::kMaxCorridorWidthM)
        QSettings().setValue(QLatin1String(kWidthKey), widthM);
}

void DrawCorridorTool::deactivate(MapView* view) {
    cancel();
    AbstractTool::deactivate(view);
}

void DrawCorridorTool::mousePressed(QMouseEvent* e, const QPointF& p) {
    if (e->button() == Qt::RightButton) {
        finish();
        return;
    }
    if (e->button() != Qt::LeftButton)
        return;
    // The second click of a double-click arrives here too: do not add a duplicate point.
    if (!m_points.isEmpty()) {
        const QPointF d = p - m_points.last();
        if (std::hypot(d.x(), d.y()) <= pixelsToScene(2.0))
            return;
    }
    m_points << p;
    updatePreview(p);
}

void DrawCorridorTool::mouseMoved(QMouseEvent*, const QPointF& p) {
    if (!m_points.isEmpty())
        updatePreview(p);
}

void DrawCorridorTool::mouseDoubleClicked(QMouseEvent*, const QPointF&) {
    finish();
}

bool DrawCorridorTool::keyPressed(QKeyEvent* e) {
    switch (e->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter:
        finish();
        return true;
    case Qt::Key_Escape:
        cancel();
        return true;
    case Qt::Key_Backspace:
        if (!m_points.isEmpty()) {
            m_points.removeLast();
            updatePreview(std::nullopt);
        }
        return true;
    default:
        return false;
    }
}

void DrawCorridorTool::updatePreview(const std::optional<QPointF>& cursor) {
    if (m_points.isEmpty()) {
        m_line.reset();
        m_ground.reset();
        return;
    }
    if (!m_line && m_view) {
        m_ground = std::make_unique<ShapeItem>(ShapeStyle::Area);
        m_ground->setZValue(59);
        m_view->scene()->addItem(m_ground.get());
        m_line = std::make_unique<ShapeItem>(ShapeStyle::Preview);
        m_line->setZValue(60);
        m_line->setClosed(false);
        m_view->scene()->addItem(m_line.get());
    }
    if (!m_line)
        return;
    QPolygonF line = m_points;
    if (cursor && line.last() != *cursor)
        line << *cursor;
    m_line->setRings({line});
    m_line->setHighlighted(true);
    m_line->setHandleMargin(pixelsToScene(60));
    const mission::Corridor c{ringFromScene(line), corridorWidthM(m_doc)};
    m_ground->setRings(line.size() >= 2 ? corridorGroundRings(c) : QVector<QPolygonF>{});
    const QString problem = line.size() >= 2 ? corridorProblem(c) : QString();
    m_line->setProblem(problem);
    const double km = mission::corridorLengthM(c) / 1000.0;
    emit statusMessage(problem.isEmpty() ? tr("%n point(s), %1 km × %2 m", nullptr, m_points.size())
                                               .arg(km, 0, 'f', 2)
                                               .arg(c.widthM, 0, 'f', 0)
                                         : problem);
}

bool DrawCorridorTool::finish() {
    if (m_points.size() < 2) {
        if (!m_points.isEmpty())
            emit statusMessage(tr("A corridor's line needs at least 2 points."));
        return false;
    }
    const mission::Corridor c{ringFromScene(m_points), corridorWidthM(m_doc)};
    const QString problem = corridorProblem(c);
    if (!problem.isEmpty()) {
        emit statusMessage(
            tr("Cannot finish: %1. Click elsewhere, or press Backspace to remove the last point.")
                .arg(problem));
        return false;
    }
    m_doc->undoStack()->push(new SetCorridorCommand(m_doc, c, tr("Draw corridor")));
    m_layer->select(ShapeRef::corridor());
    m_points.clear();
    m_line.reset();
    m_ground.reset();
    emit statusMessage(hint());
    return true;
}

void DrawCorridorTool::cancel() {
    const bool drawing = !m_points.isEmpty();
    m_points.clear();
    m_line.reset();
    m_ground.reset();
    if (drawing)
        emit statusMessage(hint());
}

} // namespace pf::ui
