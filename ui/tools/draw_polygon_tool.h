// DrawPolygonTool: draw the area of interest or a no-fly zone vertex by vertex.
#pragma once

#include "ui/map/mission_layer.h"
#include "ui/tools/abstract_tool.h"

#include <memory>

namespace pf::ui {

class DrawPolygonTool : public AbstractTool {
    Q_OBJECT
public:
    enum class Target { Area, NoFlyZone };
    DrawPolygonTool(Target target, MissionDocument* doc, MissionLayer* layer, QObject* parent = nullptr);
    ~DrawPolygonTool() override;
    QString hint() const override;
    QCursor cursor() const override { return Qt::CrossCursor; }

    void deactivate(MapView* view) override;
    void mousePressed(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseMoved(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseDoubleClicked(QMouseEvent* e, const QPointF& scenePos) override;
    bool keyPressed(QKeyEvent* e) override;

    // Finishes the polygon being drawn (as Enter or a double-click does). Returns false if it has
    // fewer than 3 vertices or is invalid (the reason goes to the status bar).
    bool finish();
    void cancel();
    int vertexCount() const { return m_points.size(); }

private:
    void updatePreview(const std::optional<QPointF>& cursor);

    Target m_target;
    QPolygonF m_points; // scene coordinates
    std::unique_ptr<ShapeItem> m_preview;
};

} // namespace pf::ui
