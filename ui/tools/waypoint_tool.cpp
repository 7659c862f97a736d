#include "ui/tools/waypoint_tool.h"

#include "ui/commands/insert_waypoint_command.h"
#include "ui/commands/move_waypoint_command.h"
#include "ui/commands/remove_waypoints_command.h"
#include "ui/geo_adapter.h"
#include "ui/map/plan_layer.h"
#include "ui/mission_document.h"

#include <QApplication>
#include <QKeyEvent>
#include <QMouseEvent>

#include <cmath>

namespace pf::ui {

namespace {
constexpr double kPickPx = 9.0;
}

WaypointTool::WaypointTool(MissionDocument* doc, MissionLayer* layer, PlanLayer* plan,
                           QObject* parent)
    : AbstractTool(tr("Edit waypoints"), QIcon(QStringLiteral(":/icons/waypoint_edit.svg")),
                   QKeySequence(Qt::Key_W), doc, layer, parent),
      m_plan(plan) {}

QString WaypointTool::hint() const {
    return tr("Click a waypoint to select it (Shift adds); drag it to move it; double-click a leg "
              "to insert a "
              "waypoint; Delete removes the selected waypoints.");
}

void WaypointTool::deactivate(MapView* view) {
    endDrag();
    AbstractTool::deactivate(view);
}

void WaypointTool::endDrag() {
    if (m_drag && m_moved)
        m_plan->setPreview(m_drag->first, m_drag->second, std::nullopt);
    m_drag.reset();
    m_moved = false;
}

void WaypointTool::mousePressed(QMouseEvent* e, const QPointF& p) {
    if (e->button() != Qt::LeftButton)
        return;
    m_pressPos = p;
    m_moved = false;
    const auto hit = m_plan->hitWaypoint(p, pixelsToScene(kPickPx));
    if (!hit) {
        if (!(e->modifiers() & Qt::ShiftModifier))
            m_plan->selectWaypoints(-1, {});
        return;
    }
    QList<int> sel;
    if ((e->modifiers() & Qt::ShiftModifier) && m_plan->selectedRoute() == hit->route) {
        sel = m_plan->selectedWaypoints();
        if (sel.contains(hit->waypoint))
            sel.removeAll(hit->waypoint);
        else
            sel.append(hit->waypoint);
    } else {
        sel = {hit->waypoint};
    }
    m_plan->selectWaypoints(hit->route, sel);
    m_drag = std::make_pair(hit->route, hit->waypoint);
    const auto& w =
        m_doc->routes()[std::size_t(hit->route)].route.waypoints[std::size_t(hit->waypoint)];
    emit statusMessage(
        tr("Waypoint %1 of %2: %3 m, heading %4°")
            .arg(hit->waypoint + 1)
            .arg(QString::fromStdString(m_doc->routes()[std::size_t(hit->route)].route.aircraft))
            .arg(w.altitudeM, 0, 'f', 1)
            .arg(w.headingDeg, 0, 'f', 0));
}

void WaypointTool::mouseMoved(QMouseEvent* e, const QPointF& p) {
    if (!m_drag || !(e->buttons() & Qt::LeftButton))
        return;
    const QPointF d = p - m_pressPos;
    if (!m_moved && std::hypot(d.x(), d.y()) < pixelsToScene(QApplication::startDragDistance()))
        return;
    m_moved = true;
    m_plan->setPreview(m_drag->first, m_drag->second, p);
}

void WaypointTool::mouseReleased(QMouseEvent* e, const QPointF& p) {
    if (e->button() != Qt::LeftButton || !m_drag)
        return;
    const auto drag = *m_drag;
    const bool moved = m_moved;
    m_drag.reset();
    m_moved = false;
    if (moved)
        m_doc->undoStack()->push(
            new MoveWaypointCommand(m_doc, drag.first, drag.second, fromScene(p)));
}

void WaypointTool::mouseDoubleClicked(QMouseEvent* e, const QPointF& p) {
    if (e->button() != Qt::LeftButton)
        return;
    const auto leg = m_plan->hitLeg(p, pixelsToScene(kPickPx));
    if (!leg)
        return;
    const auto& wps = m_doc->routes()[std::size_t(leg->route)].route.waypoints;
    // The new waypoint takes its altitude and heading from the leg it splits; it is a turn point
    // (no photo) unless the user changes its action in the table.
    route::Waypoint w = wps[std::size_t(leg->insertAt - 1)];
    w.position = fromScene(leg->point);
    w.kind = route::WaypointKind::Turn;
    m_doc->undoStack()->push(new InsertWaypointCommand(m_doc, leg->route, leg->insertAt, w));
    m_plan->selectWaypoints(leg->route, {leg->insertAt});
}

bool WaypointTool::keyPressed(QKeyEvent* e) {
    if (e->key() == Qt::Key_Delete || e->key() == Qt::Key_Backspace) {
        deleteSelection();
        return true;
    }
    return false;
}

void WaypointTool::deleteSelection() {
    const int r = m_plan->selectedRoute();
    const QList<int> sel = m_plan->selectedWaypoints();
    if (r < 0 || sel.isEmpty())
        return;
    m_plan->selectWaypoints(-1, {});
    m_doc->undoStack()->push(new RemoveWaypointsCommand(m_doc, r, sel));
}

} // namespace pf::ui
