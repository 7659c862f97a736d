// DrawCorridorTool: draw a corridor's centre line point by point; its ground is shown as it grows.
#pragma once

#include "ui/map/mission_layer.h"
#include "ui/tools/abstract_tool.h"

#include <memory>

namespace pf::ui {

class DrawCorridorTool : public AbstractTool {
    Q_OBJECT
public:
    DrawCorridorTool(MissionDocument* doc, MissionLayer* layer, QObject* parent = nullptr);
    ~DrawCorridorTool() override;
    QString hint() const override;
    QCursor cursor() const override { return Qt::CrossCursor; }

    void deactivate(MapView* view) override;
    void mousePressed(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseMoved(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseDoubleClicked(QMouseEvent* e, const QPointF& scenePos) override;
    bool keyPressed(QKeyEvent* e) override;

    // Finishes the line being drawn (as Enter or a double-click does): the mission becomes a survey
    // of this corridor, at the width of the mission's corridor or the last one set
    // (corridorWidthM). Returns false with fewer than 2 points or an invalid corridor (the reason
    // goes to the status bar).
    bool finish();
    void cancel();
    int pointCount() const { return m_points.size(); }

    // The width a new corridor gets: the mission's corridor's, else the last one set (settings
    // "corridor/widthM", 50 m at first).
    static double corridorWidthM(const MissionDocument* doc);
    static void rememberWidthM(double widthM);

private:
    void updatePreview(const std::optional<QPointF>& cursor);

    QPolygonF m_points; // scene coordinates
    std::unique_ptr<ShapeItem> m_line, m_ground;
};

// The corridor's ground in scene rings (empty when the corridor is not valid), for previews.
QVector<QPolygonF> corridorGroundRings(const mission::Corridor& corridor);

} // namespace pf::ui
