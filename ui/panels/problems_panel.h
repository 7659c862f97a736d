// ProblemsPanel: the Problems dock's list: invalid shapes, planning errors, the planner's notes, the
// coverage check and every route check problem, each with the map object it is about.
#pragma once

#include "core/mission/route_check.h"

#include <QListWidget>

namespace pf::ui {

class MissionDocument;
class MissionLayer;
class PlanController;
class PlanLayer;

class ProblemsPanel : public QListWidget {
    Q_OBJECT
public:
    ProblemsPanel(MissionDocument* doc, MissionLayer* shapes, PlanController* planner, PlanLayer* plan,
                  QWidget* parent = nullptr);

    enum class Severity { Error, Warning, Info };
    // The items' severities, in list order (for tests).
    Severity severityOf(int row) const;
    // The waypoints an item is about (selected on the map when it is clicked); empty for others.
    QList<int> waypointsOf(int row) const;
    void refresh();

signals:
    // An item was clicked; the panel has selected what it is about on the map.
    void areaActivated();
    void noFlyZoneActivated(int zone);
    void waypointActivated(int route, int waypoint);
    // The number of items changed (for the dock's title).
    void countChanged(int count);

private:
    QListWidgetItem* add(const QString& text, const QString& source, Severity severity);
    void addPlanItems();
    void addRouteItems();
    void addOutsideItem(int route, const QString& name, const mission::OutsideGroup& group);

    MissionDocument* m_doc;
    MissionLayer* m_shapes;
    PlanController* m_planner;
    PlanLayer* m_plan;
};

} // namespace pf::ui
