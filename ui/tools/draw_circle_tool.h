// DrawCircleTool: draw a circular no-fly zone (press at the centre, drag to the radius).
#pragma once

#include "ui/map/mission_layer.h"
#include "ui/tools/abstract_tool.h"

#include <memory>

namespace pf::ui {

class DrawCircleTool : public AbstractTool {
    Q_OBJECT
public:
    DrawCircleTool(MissionDocument* doc, MissionLayer* layer, QObject* parent = nullptr);
    ~DrawCircleTool() override;
    QString hint() const override;
    QCursor cursor() const override { return Qt::CrossCursor; }

    void deactivate(MapView* view) override;
    void mousePressed(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseMoved(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseReleased(QMouseEvent* e, const QPointF& scenePos) override;

    // A geodesic circle approximated by a polygon of `segments` vertices.
    static geo::GeoRing circle(const geo::LonLat& centre, double radiusM, int segments = 32);

private:
    std::optional<QPointF> m_centre;
    std::unique_ptr<ShapeItem> m_preview;
};

} // namespace pf::ui
