// StatisticsPanel: the plan's figures per aircraft and in total (marked when the plan is outdated),
// and the side-by-side comparison of every planner kind on the current mission, with "Use".
#pragma once

#include "core/mission/mission.h"
#include "core/mission/mission_plan.h"

#include <QWidget>

class QLabel;
class QPushButton;
class QTabWidget;
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
    // "Outdated: …" while the plan shown is not the mission's; empty when it is current.
    QString stateText() const;
    QLabel* planTimeLabel() const { return m_planTime; }
    // "Plan" and "Compare planners".
    QTabWidget* pages() const { return m_pages; }
    // The comparison's "Use" button of a planner kind (nullptr if it has no row).
    QPushButton* useButton(mission::PlannerKind kind) const;
    // Makes `kind` the mission's planner (one undo step), as the "Use" buttons do; false (nothing
    // changed) for a planner not offered (PlanController::plannerRefusal).
    bool usePlanner(mission::PlannerKind kind);
    // Below the comparison: why a planner is shown as the yardstick only; empty when none is.
    QString compareNote() const;

    enum StatColumn { Aircraft, Photos, Km, Time, Turns, Sorties, Cover, PlanMs, StatColumns };
    enum CompareColumn { Planner, CPhotos, CKm, CTime, CTurns, CCover, CNoFly, CPlanMs, CUse, CompareColumns };

private:
    // The Plan page's figures summed over the aircraft rows, for the Total row.
    struct StatTotals {
        int batteries = 0, photos = 0, turns = 0;
        double distanceM = 0.0, longestS = 0.0, planMs = 0.0;
    };
    void refreshStatistics();
    // The Total row and the planning-time line under the table.
    void addTotalRow(const mission::MissionPlan& plan, const StatTotals& totals);
    void refreshState();
    void refreshComparison();

    MissionDocument* m_doc;
    PlanController* m_planner;
    QTabWidget* m_pages;
    QLabel* m_state;
    QTableWidget* m_stats;
    QLabel* m_planTime;
    QTableWidget* m_compare;
    QPushButton* m_compareButton;
    QLabel* m_compareState;
    QLabel* m_compareNote;
};

} // namespace pf::ui
