// WaypointPanel: the waypoint table of one route with insert, delete, "set altitude" and reverse.
#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QTableView;

namespace pf::ui {

class MissionDocument;
class PlanLayer;
class WaypointTableModel;

class WaypointPanel : public QWidget {
    Q_OBJECT
public:
    WaypointPanel(MissionDocument* doc, PlanLayer* layer, QWidget* parent = nullptr);

    WaypointTableModel* model() const { return m_model; }
    QTableView* table() const { return m_table; }
    int currentRoute() const;
    void setCurrentRoute(int route);
    // Selected rows of the table (waypoint indices).
    QList<int> selectedWaypoints() const;

    // One altitude for the selected waypoints, or every waypoint when `all` (one undo step).
    void setAltitude(double altitudeM, bool all);
    void reverseRoute();
    void deleteSelected();
    void insertAfterSelected();

private:
    void rebuildRouteList();
    void syncFromLayer();
    void syncToLayer();
    void askAltitude();

    MissionDocument* m_doc;
    PlanLayer* m_layer;
    WaypointTableModel* m_model;
    QComboBox* m_routes;
    QTableView* m_table;
    QLabel* m_state;
    bool m_syncing = false;
};

} // namespace pf::ui
