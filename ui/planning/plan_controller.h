// PlanController: plans the document's mission in the background (on demand and after edits) and
// hands finished plans to the document, never replacing hand-edited routes without consent.
#pragma once

#include "core/mission/plan_mission.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace pf::ui {

class MissionDocument;

// One planner's figures on the current mission, for the side-by-side comparison.
struct PlannerComparisonRow {
    mission::PlannerKind planner = mission::PlannerKind::Stride;
    bool ok = false;
    QString error;
    mission::PlanTotals totals;
    double coveragePercent = 0.0;
    double wallMs = 0.0;
};

QString plannerName(mission::PlannerKind kind);

class PlanController : public QObject {
    Q_OBJECT
public:
    explicit PlanController(MissionDocument* doc, QObject* parent = nullptr);
    ~PlanController() override;

    // Starts a plan now (Plan button, F5). A running plan is superseded: its result will be
    // dropped. `replaceEdited`: the user agreed that this plan replaces routes edited by hand;
    // otherwise a plan finishing while routes are edited waits as the pending plan.
    void planNow(bool replaceEdited = false);
    // Stops waiting for the running plan. The core has no cancel hook, so the computation finishes
    // on its worker thread, but its result is dropped (generation numbers): no outdated plan is
    // shown.
    void cancel();
    bool isBusy() const { return m_busy; }
    // Replanning a short while after every edit of the mission.
    void setAutoPlan(bool on);
    bool autoPlan() const { return m_auto; }
    static constexpr int kDebounceMs = 800;

    // The last plan applied to the document (its routes may since have been edited).
    const std::optional<mission::MissionPlan>& plan() const { return m_plan; }
    // The last planning error, in the core's words; empty after a success.
    QString lastError() const { return m_error; }
    double lastWallMs() const { return m_wallMs; }

    // A plan that finished while routes were edited by hand waits here until the user decides.
    bool hasPendingPlan() const { return m_pending.has_value(); }
    void acceptPendingPlan();
    void discardPendingPlan();

    // Runs stride, raster and wavefront on the current mission in the background.
    void compare();
    bool isComparing() const { return m_comparing > 0; }
    const std::vector<PlannerComparisonRow>& comparison() const { return m_comparison; }

    // Processes events until no plan or comparison runs (tests, screenshots). False on timeout.
    bool waitForIdle(int timeoutMs);

signals:
    void busyChanged(bool busy);
    // A plan was applied (plan() changed) or planning failed (lastError() not empty).
    void planChanged();
    void pendingPlanChanged(bool pending);
    void comparisonChanged();
    void message(const QString& text);

private:
    struct Outcome;
    void start(bool userAsked, bool replaceEdited = false);
    void finished(const std::shared_ptr<const Outcome>& outcome);
    void apply(mission::MissionPlan plan, double wallMs);
    void setBusy(bool on);

    MissionDocument* m_doc;
    QTimer m_debounce;
    bool m_auto = true;
    bool m_busy = false;
    int m_generation = 0;
    int m_replaceGeneration = -1; // the generation allowed to replace edited routes
    int m_compareGeneration = 0;
    int m_comparing = 0;
    std::optional<mission::MissionPlan> m_plan;
    std::optional<mission::MissionPlan> m_pending;
    double m_pendingMs = 0.0;
    QString m_error;
    double m_wallMs = 0.0;
    std::vector<PlannerComparisonRow> m_comparison;
};

} // namespace pf::ui
