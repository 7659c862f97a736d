#include "ui/tools/draw_circle_tool.h"

#include "core/geo/geodesic.h"
#include "ui/commands/add_no_fly_zone_command.h"
#include "ui/geo_adapter.h"
#include "ui/map/map_view.h"

#include <QGraphicsScene>
#include <QMouseEvent>

namespace pf::ui {

namespace {
constexpr double kMinRadiusM = 1.0;
}

DrawCircleTool::DrawCircleTool(MissionDocument* doc, MissionLayer* layer, QObject* parent)
    : AbstractTool(tr("Draw circular no-fly zone"), QIcon(QStringLiteral(":/icons/draw_circle.svg")),
                   QKeySequence(Qt::Key_C), doc, layer, parent) {}

DrawCircleTool::~DrawCircleTool() = default;

QString DrawCircleTool::hint() const {
    return tr("Press at the centre of the no-fly zone and drag to its radius.");
}

geo::GeoRing DrawCircleTool::circle(const geo::LonLat& centre, double radiusM, int segments) {
    geo::GeoRing ring;
    for (int i = 0; i < segments; ++i) ring.push_back(geo::geodesicDirect(centre, 360.0 * i / segments, radiusM));
    return ring;
}

void DrawCircleTool::deactivate(MapView* view) {
    m_centre.reset();
    m_preview.reset();
    AbstractTool::deactivate(view);
}

void DrawCircleTool::mousePressed(QMouseEvent* e, const QPointF& p) {
    if (e->button() != Qt::LeftButton) return;
    m_centre = p;
}

void DrawCircleTool::mouseMoved(QMouseEvent*, const QPointF& p) {
    if (!m_centre || !m_view) return;
    const geo::LonLat c = fromScene(*m_centre);
    const double r = geo::geodesicDistance(c, fromScene(p));
    if (!m_preview) {
        m_preview = std::make_unique<ShapeItem>(ShapeStyle::NoFly);
        m_preview->setZValue(60);
        m_view->scene()->addItem(m_preview.get());
    }
    m_preview->setRings({toScene(circle(c, std::max(r, kMinRadiusM)))});
    m_preview->setHandleMargin(pixelsToScene(60));
    m_preview->setLabel(tr("r = %1 m").arg(r, 0, 'f', 1));
    emit statusMessage(tr("Radius %1 m").arg(r, 0, 'f', 1));
}

void DrawCircleTool::mouseReleased(QMouseEvent* e, const QPointF& p) {
    if (e->button() != Qt::LeftButton || !m_centre) return;
    const geo::LonLat c = fromScene(*m_centre);
    const double r = geo::geodesicDistance(c, fromScene(p));
    m_centre.reset();
    m_preview.reset();
    if (r < kMinRadiusM) {
        emit statusMessage(tr("Drag from the centre to set the radius (at least %1 m).").arg(kMinRadiusM));
        return;
    }
    mission::NoFlyZone zone;
    zone.name = m_doc->nextNoFlyZoneName(tr("Circle")).toStdString();
    zone.polygon.outer = circle(c, r);
    m_doc->undoStack()->push(new AddNoFlyZoneCommand(m_doc, zone));
    m_layer->select(ShapeRef::noFly(int(m_doc->mission().noFlyZones.size()) - 1));
}

} // namespace pf::ui
