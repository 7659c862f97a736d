// WaypointTool: select, drag, insert and delete waypoints of the planned routes on the map.
#pragma once

#include "ui/tools/abstract_tool.h"

#include <optional>

namespace pf::ui {

class PlanLayer;

class WaypointTool : public AbstractTool {
    Q_OBJECT
public:
    WaypointTool(MissionDocument* doc, MissionLayer* layer, PlanLayer* plan,
                 QObject* parent = nullptr);
    QString hint() const override;
    void deactivate(MapView* view) override;
    void mousePressed(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseMoved(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseReleased(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseDoubleClicked(QMouseEvent* e, const QPointF& scenePos) override;
    bool keyPressed(QKeyEvent* e) override;

    // Deletes the selected waypoints (one undo step).
    void deleteSelection();

private:
    void endDrag();
    PlanLayer* m_plan;
    std::optional<std::pair<int, int>> m_drag; // route, waypoint
    QPointF m_pressPos;
    bool m_moved = false;
};

} // namespace pf::ui
