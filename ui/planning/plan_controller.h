// PlanController: plans the document's mission in the background (on demand and after edits) and
// hands finished plans to the document, never replacing hand-edited routes without consent.
#pragma once

#include "core/mission/plan_mission.h"

#include "core/progress.h"

#include <QElapsedTimer>
#include <QFutureWatcherBase>
#include <QObject>
#include <QString>
#include <QStringList>
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
    int noFlyCrossings = 0; // waypoints and legs of its routes within a no-fly margin (the route check)
    QStringList zonesCrossed; // the no-fly zones whose margin its routes enter
};

// Whether two missions give the same plan: everything planning reads (the name and the path
// colours do not count).
bool samePlanInput(const mission::Mission& a, const mission::Mission& b);

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
    // Cancels the running plan: its worker stops within a fraction of a second (the core's cancel
    // token) and its result, if any, is dropped (generation numbers): no outdated plan is shown.
    // Every new plan (an edit's, the Plan button's) cancels the running one the same way; while the
    // cancelled one winds down the newest request waits (never more than one), so a worker slot is
    // never held by work nobody wants.
    void cancel();
    bool isBusy() const { return m_busy; }
    // Whether a worker still computes (a cancelled one until it has stopped), and the plan request
    // waiting for it.
    bool isWorking() const { return m_worker != nullptr; }
    bool hasQueuedPlan() const { return m_queued.has_value(); }
    // Replanning a short while after every edit of the mission.
    void setAutoPlan(bool on);
    bool autoPlan() const { return m_auto; }
    static constexpr int kDebounceMs = 800;

    // The last plan applied to the document (its routes may since have been edited).
    const std::optional<mission::MissionPlan>& plan() const { return m_plan; }
    // True when there is a plan and the mission has changed since it was computed: what the map,
    // the statistics and the export show is then not what the mission asks for. It stays so until a
    // plan of the current mission is applied (a cancelled or failed plan leaves it outdated).
    bool isOutdated() const;
    // Whether the comparison was run on another mission than the current one.
    bool isComparisonOutdated() const;
    // The last planning error, in the core's words; empty after a success. A mission that fails
    // validation gives one line per error.
    QString lastError() const { return m_error; }
    double lastWallMs() const { return m_wallMs; }

    // A plan that finished while routes were edited by hand waits here until the user decides.
    bool hasPendingPlan() const { return m_pending.has_value(); }
    // Replace edited paths: the pending plan replaces every route.
    void acceptPendingPlan();
    // Keep edits: the pending plan is applied, but the routes edited by hand stay in place of the
    // new plan's routes of their aircraft, so every route shown is the one that will be exported.
    void keepEditsWithPendingPlan();
    // Drops the pending plan (the plan shown stays, outdated).
    void discardPendingPlan();

    // Runs every planner kind (mission::plannerKinds()) on the current mission in the background.
    void compare();
    bool isComparing() const { return m_comparing > 0; }
    const std::vector<PlannerComparisonRow>& comparison() const { return m_comparison; }
    // Why `kind` is not offered as the mission's planner, or empty when it is. A planner that does
    // not keep out of no-fly zones (the lawnmower) is not, where the mission has zones, unless the
    // current comparison shows that its routes cross none of them; the reason names those it
    // crosses.
    QString plannerRefusal(mission::PlannerKind kind) const;

    // Processes events until no plan or comparison runs (tests, screenshots). False on timeout.
    bool waitForIdle(int timeoutMs);

signals:
    void busyChanged(bool busy);
    // The running plan's progress: fraction of the whole in [0, 1] and the stage in words.
    void progressChanged(double fraction, const QString& stage);
    // A plan was applied (plan() changed) or planning failed (lastError() not empty).
    void planChanged();
    void pendingPlanChanged(bool pending);
    void comparisonChanged();
    void message(const QString& text);

private:
    struct Outcome;
    void start(bool userAsked, bool replaceEdited = false);
    void finished(const std::shared_ptr<const Outcome>& outcome);
    void apply(mission::MissionPlan plan, mission::Mission input, double wallMs, bool keepEdits = false);
    void setBusy(bool on);

    struct Request {
        bool userAsked = false;
        bool replaceEdited = false;
    };
    void launch(const Request& request);
    void cancelWorker();

    MissionDocument* m_doc;
    // The running plan's worker and cancel token (null when none runs), the request waiting for it.
    QFutureWatcherBase* m_worker = nullptr;
    std::shared_ptr<Progress> m_token;
    std::optional<Request> m_queued;
    // Comparison runs, cancelled when the window closes.
    std::vector<std::shared_ptr<Progress>> m_compareTokens;
    std::vector<QFutureWatcherBase*> m_compareWorkers;
    QTimer m_debounce;
    bool m_auto = true;
    bool m_busy = false;
    int m_generation = 0;
    int m_replaceGeneration = -1; // the generation allowed to replace edited routes
    int m_compareGeneration = 0;
    int m_comparing = 0;
    std::optional<mission::MissionPlan> m_plan;
    std::optional<mission::Mission> m_planInput; // what m_plan was computed from
    std::optional<mission::MissionPlan> m_pending;
    std::optional<mission::Mission> m_pendingInput;
    std::optional<mission::Mission> m_compareInput;
    double m_pendingMs = 0.0;
    QString m_error;
    double m_wallMs = 0.0;
    std::vector<PlannerComparisonRow> m_comparison;
};

} // namespace pf::ui
