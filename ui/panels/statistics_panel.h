// StatisticsPanel: the plan's figures per aircraft and in total, and the side-by-side comparison of
// the stride, raster and wavefront planners on the current mission.
#pragma once

#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace pf::ui {

class MissionDocument;
class PlanController;

class StatisticsPanel : public QWidget {
    Q_OBJECT
public:
    StatisticsPanel(MissionDocument* doc, PlanController* planner, QWidget* parent = nullptr);

    QTableWidget* statistics() const { return m_stats; }
    QTableWidget* comparison() const { return m_compare; }

private:
    void refreshStatistics();
    void refreshComparison();

    MissionDocument* m_doc;
    PlanController* m_planner;
    QTableWidget* m_stats;
    QTableWidget* m_compare;
    QPushButton* m_compareButton;
    QLabel* m_compareState;
};

} // namespace pf::ui
