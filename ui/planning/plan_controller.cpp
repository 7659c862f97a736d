#include "ui/planning/plan_controller.h"

#include "core/mission/planner_kinds.h"
#include "core/mission/route_check.h"
#include "core/mission/validation.h"
#include "ui/mission_document.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFutureWatcher>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace pf::ui {

QString plannerName(mission::PlannerKind kind) {
    return QCoreApplication::translate("Planner", mission::plannerKindInfo(kind).label);
}

bool samePlanInput(const mission::Mission& a, const mission::Mission& b) {
    auto strip = [](mission::Mission m) {
        m.name.clear();
        m.editedRoutes.clear();
        for (auto& ac : m.aircraft)
            ac.colour.clear();
        return m;
    };
    return strip(a) == strip(b);
}

struct PlanController::Outcome {
    int generation = 0;
    mission::Mission input;
    std::optional<mission::MissionPlan> plan;
    QString error;
    double wallMs = 0.0;
};

PlanController::PlanController(MissionDocument* doc, QObject* parent)
    : QObject(parent), m_doc(doc) {
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(kDebounceMs);
    connect(&m_debounce, &QTimer::timeout, this, [this] { start(false); });
    connect(m_doc, &MissionDocument::changed, this, [this] {
        if (m_auto)
            m_debounce.start();
    });
    connect(m_doc, &MissionDocument::missionReset, this, [this] {
        // A different mission: nothing of the old one's plans may appear, and none goes on computing.
        ++m_generation;
        m_queued.reset();
        cancelWorker();
        for (auto& t : m_compareTokens)
            t->cancel();
        ++m_compareGeneration;
        m_comparing = 0;
        m_plan.reset();
        m_planInput.reset();
        m_pending.reset();
        m_pendingInput.reset();
        m_compareInput.reset();
        m_comparison.clear();
        m_error.clear();
        setBusy(false);
        emit pendingPlanChanged(false);
        emit comparisonChanged();
        emit planChanged();
    });
}

// Quit (the window and its controller go): every worker is told to stop and waited for, a fraction of
// a second, so that no computation outlives the window or keeps the process busy.
PlanController::~PlanController() {
    m_queued.reset();
    if (m_token)
        m_token->cancel();
    for (auto& t : m_compareTokens)
        t->cancel();
    if (m_worker)
        m_worker->waitForFinished();
    for (auto* w : m_compareWorkers)
        w->waitForFinished();
}

void PlanController::setAutoPlan(bool on) {
    m_auto = on;
    if (!on)
        m_debounce.stop();
}

void PlanController::planNow(bool replaceEdited) {
    m_debounce.stop();
    start(true, replaceEdited);
}

void PlanController::cancel() {
    m_debounce.stop();
    m_queued.reset();
    if (!m_busy)
        return;
    ++m_generation;
    cancelWorker();
    setBusy(false);
    emit message(tr("Planning cancelled."));
}

void PlanController::cancelWorker() {
    if (m_token)
        m_token->cancel();
}

void PlanController::setBusy(bool on) {
    if (m_busy == on)
        return;
    m_busy = on;
    emit busyChanged(on);
}

void PlanController::start(bool userAsked, bool replaceEdited) {
    if (m_worker) {
        // The running plan is for an older mission: it stops, and this request waits for its slot
        // (replacing any request waiting already: only the newest counts).
        ++m_generation;
        cancelWorker();
        const bool replace = replaceEdited || (m_queued && m_queued->replaceEdited);
        m_queued = Request{userAsked || (m_queued && m_queued->userAsked), replace};
        setBusy(true);
        return;
    }
    launch(Request{userAsked, replaceEdited});
}

void PlanController::launch(const Request& request) {
    const bool userAsked = request.userAsked;
    const int generation = ++m_generation;
    if (request.replaceEdited)
        m_replaceGeneration = generation;
    mission::Mission m = m_doc->mission();
    // A corridor without ground yet (an invalid one) goes to the planner, which says what is wrong.
    const bool noArea = !m.corridor && m.area.outer.size() < 3;
    if (noArea || m.aircraft.empty()) {
        // Nothing to plan yet: say what is missing instead of a planner error.
        setBusy(false);
        m_error = noArea ? tr("No plan: draw or import the area of interest (or a corridor).")
                         : tr("No plan: add an aircraft.");
        emit planChanged();
        return;
    }
    setBusy(true);
    if (userAsked)
        emit message(tr("Planning…"));
    auto* watcher = new QFutureWatcher<std::shared_ptr<const Outcome>>(this);
    m_worker = watcher;
    // Reports come from the worker thread and are queued to this one; the destructor waits for the
    // worker, so none arrives after it.
    m_token = std::make_shared<Progress>([this, generation](double f, const std::string& stage) {
        QMetaObject::invokeMethod(
            this,
            [this, generation, f, stage = QString::fromStdString(stage)] {
                if (generation == m_generation && m_busy)
                    emit progressChanged(f, stage);
            },
            Qt::QueuedConnection);
    });
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        m_worker = nullptr;
        m_token.reset();
        finished(watcher->result());
        watcher->deleteLater();
        if (m_queued) {
            const Request next = *m_queued;
            m_queued.reset();
            launch(next);
        }
    });
    watcher->setFuture(QtConcurrent::run([generation, m = std::move(m), token = m_token] {
        auto out = std::make_shared<Outcome>();
        out->generation = generation;
        out->input = m;
        QElapsedTimer t;
        t.start();
        // The checks the command line makes before planning: an altitude above the maximum, a
        // footprint below the minimum or a grid beyond the cell budget is never planned.
        const auto report = mission::validateMission(m);
        if (report.hasErrors()) {
            QStringList lines;
            for (const auto& p : report.problems)
                if (p.severity == geo::Severity::Error)
                    lines << QString::fromStdString(p.message);
            out->error = lines.join(QLatin1Char('\n'));
            return std::shared_ptr<const Outcome>(std::move(out));
        }
        auto r = mission::planMission(m, token.get());
        out->wallMs = double(t.nsecsElapsed()) / 1e6;
        if (r)
            out->plan = std::move(r).value();
        else
            out->error = QString::fromStdString(r.error().message);
        return std::shared_ptr<const Outcome>(std::move(out));
    }));
}

void PlanController::finished(const std::shared_ptr<const Outcome>& outcome) {
    if (!outcome || outcome->generation != m_generation)
        return; // superseded or cancelled (a queued request keeps the busy state)
    setBusy(false);
    m_wallMs = outcome->wallMs;
    if (!outcome->plan) {
        m_error = outcome->error;
        emit message(tr("Not planned: %1").arg(m_error.section(QLatin1Char('\n'), 0, 0)));
        emit planChanged();
        return;
    }
    m_error.clear();
    if (m_doc->anyRouteEdited() && outcome->generation != m_replaceGeneration) {
        // Hand edits are never discarded silently: the plan waits for the user's word.
        m_pending = *outcome->plan;
        m_pendingInput = outcome->input;
        m_pendingMs = outcome->wallMs;
        emit pendingPlanChanged(true);
        emit message(tr("A new plan is ready; your edited paths are kept until you replace them."));
        return;
    }
    apply(*outcome->plan, outcome->input, outcome->wallMs);
}

void PlanController::apply(mission::MissionPlan plan, mission::Mission input, double wallMs, bool keepEdits) {
    if (m_pending) {
        m_pending.reset();
        m_pendingInput.reset();
        emit pendingPlanChanged(false);
    }
    std::vector<route::Route> routes;
    for (const auto& a : plan.aircraft)
        routes.push_back(a.route);
    m_plan = std::move(plan);
    m_planInput = std::move(input);
    m_wallMs = wallMs;
    if (keepEdits)
        m_doc->mergePlannedRoutes(std::move(routes));
    else
        m_doc->setPlannedRoutes(std::move(routes));
    emit planChanged();
    emit message(tr("Planned in %1 s.").arg(wallMs / 1000.0, 0, 'f', 2));
}

bool PlanController::isOutdated() const {
    return m_plan && m_planInput && !samePlanInput(*m_planInput, m_doc->mission());
}

bool PlanController::isComparisonOutdated() const {
    if (!m_compareInput)
        return false;
    // The comparison tries every planner: choosing one of them does not make it outdated.
    mission::Mission now = m_doc->mission();
    now.options.planner = m_compareInput->options.planner;
    return !samePlanInput(*m_compareInput, now);
}

void PlanController::acceptPendingPlan() {
    if (!m_pending)
        return;
    auto p = std::move(*m_pending);
    auto input = std::move(*m_pendingInput);
    apply(std::move(p), std::move(input), m_pendingMs);
}

void PlanController::keepEditsWithPendingPlan() {
    if (!m_pending)
        return;
    auto p = std::move(*m_pending);
    auto input = std::move(*m_pendingInput);
    apply(std::move(p), std::move(input), m_pendingMs, /*keepEdits=*/true);
}

void PlanController::discardPendingPlan() {
    if (!m_pending)
        return;
    m_pending.reset();
    m_pendingInput.reset();
    emit pendingPlanChanged(false);
}

void PlanController::compare() {
    for (auto& t : m_compareTokens)
        t->cancel(); // an older comparison's rows would be dropped anyway
    const int generation = ++m_compareGeneration;
    const mission::Mission base = m_doc->mission();
    m_compareInput = base;
    m_comparison.clear();
    m_comparing = 0;
    emit comparisonChanged();
    for (const auto& info : mission::plannerKinds()) {
        const auto kind = info.kind;
        mission::Mission m = base;
        m.options.planner = kind;
        ++m_comparing;
        auto* watcher = new QFutureWatcher<PlannerComparisonRow>(this);
        auto token = std::make_shared<Progress>();
        m_compareTokens.push_back(token);
        m_compareWorkers.push_back(watcher);
        connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, generation, token] {
            watcher->deleteLater();
            m_compareWorkers.erase(std::remove(m_compareWorkers.begin(), m_compareWorkers.end(), watcher),
                                   m_compareWorkers.end());
            m_compareTokens.erase(std::remove(m_compareTokens.begin(), m_compareTokens.end(), token),
                                  m_compareTokens.end());
            if (generation != m_compareGeneration)
                return;
            --m_comparing;
            m_comparison.push_back(watcher->result());
            // In the order of the table of planner kinds.
            auto order = [](mission::PlannerKind k) {
                const auto& kinds = mission::plannerKinds();
                for (std::size_t i = 0; i < kinds.size(); ++i)
                    if (kinds[i].kind == k)
                        return i;
                return kinds.size();
            };
            std::sort(m_comparison.begin(), m_comparison.end(),
                      [&](const auto& a, const auto& b) { return order(a.planner) < order(b.planner); });
            emit comparisonChanged();
        });
        watcher->setFuture(QtConcurrent::run([kind, m = std::move(m), token] {
            PlannerComparisonRow row;
            row.planner = kind;
            QElapsedTimer t;
            t.start();
            const auto report = mission::validateMission(m);
            if (report.hasErrors()) {
                row.error = QString::fromStdString(report.errorSummary());
                return row;
            }
            auto r = mission::planMission(m, token.get());
            row.wallMs = double(t.nsecsElapsed()) / 1e6;
            if (!r) {
                row.error = QString::fromStdString(r.error().message);
                return row;
            }
            row.ok = true;
            row.totals = r->totals;
            row.coveragePercent = r->coverageRatio > 0 ? 100.0 * r->coverageRatio
                                  : r->totals.visitable > 0
                                      ? 100.0 * r->totals.cells / r->totals.visitable
                                      : 0.0;
            // Time: the makespan of the whole flight (transit and sorties included) when known.
            if (r->makespanS > 0)
                row.totals.estimatedTimeS = r->makespanS;
            double flown = 0;
            std::vector<bool> entered(m.noFlyZones.size(), false);
            for (const auto& ap : r->aircraft) {
                flown += ap.flightDistanceM;
                const auto check = mission::checkRoute(ap.route, mission::routeLimits(m, ap.route));
                row.noFlyCrossings += check.noFly;
                for (std::size_t z : check.zonesEntered)
                    entered[z] = true;
            }
            for (std::size_t z = 0; z < entered.size(); ++z)
                if (entered[z])
                    row.zonesCrossed << (m.noFlyZones[z].name.empty()
                                             ? QStringLiteral("no-fly zone %1").arg(z + 1)
                                             : QString::fromStdString(m.noFlyZones[z].name));
            if (flown > 0)
                row.totals.pathLengthM = flown; // home to home, as the statistics show it
            return row;
        }));
    }
}

QString PlanController::plannerRefusal(mission::PlannerKind kind) const {
    const auto& info = mission::plannerKindInfo(kind);
    const auto& zones = m_doc->mission().noFlyZones;
    if (info.avoidsNoFly || zones.empty())
        return {};
    const QString name = plannerName(kind);
    if (!isComparisonOutdated())
        for (const auto& row : m_comparison)
            if (row.planner == kind && row.ok) {
                if (row.zonesCrossed.isEmpty())
                    return {}; // its routes keep clear of every zone: nothing to fear
                return tr("%1 flies straight over no-fly zones: its routes cross %2 (%n "
                          "waypoint(s) or leg(s) in a margin). It is the yardstick the other "
                          "planners are compared with, not offered as the planner of this mission.",
                          nullptr, row.noFlyCrossings)
                    .arg(name, row.zonesCrossed.join(QStringLiteral(", ")));
            }
    return tr("%1 flies straight over no-fly zones, and this mission has %n: it is the yardstick "
              "the other planners are compared with, offered as the mission's planner only where "
              "Compare planners shows that its routes cross none of them.",
              nullptr, int(zones.size()))
        .arg(name);
}

bool PlanController::waitForIdle(int timeoutMs) {
    QElapsedTimer t;
    t.start();
    while (m_busy || m_worker || m_comparing > 0 || m_debounce.isActive()) {
        if (t.elapsed() > timeoutMs)
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(5);
    }
    return true;
}

} // namespace pf::ui
