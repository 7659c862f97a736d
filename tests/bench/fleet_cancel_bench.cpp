// Cancel latency of fleet plans: the time from Progress::cancel() to planMission's return (every
// worker thread joined), cancelled at many points of the plan. The smoke run (CI) cancels the demo
// mission twice; the points of the demo at 3.5 m with one more zone (a plan of several seconds,
// most of it sharing the area) are named "Big":
//   build/tests/bench/pf_bench --benchmark_filter='CancelFleet'
#include "core/mission/plan_mission.h"
#include "core/progress.h"
#include "tests/sample_missions.h"

#include <benchmark/benchmark.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace {

using namespace pf;
using Clock = std::chrono::steady_clock;

// 0: the demo mission as shipped (two aircraft at 40 and 60 m, the automatic choice compared with
// each planner alone on worker threads); 1: the demo at 3.5 m with one more zone.
Result<mission::Mission> fleetMission(long which) {
    if (which == 1)
        return test::lowDemoWithZone(PF_RESOURCES_DIR);
    return io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
}

// One plan on this thread, cancelled by `trigger` (called with every report and, every millisecond,
// by a watcher thread with an empty stage); the latency of the cancel is the iteration's time. The
// label is the stage running when the cancel came; the counters the worst latency and how many
// progress reports came after the cancel (the job stops at its next check, so none should).
template <class Trigger>
void cancelledPlan(benchmark::State& state, const mission::Mission& m, Trigger trigger) {
    double worst = 0.0;
    int lateReports = 0;
    std::string stageSeen;
    for (auto _ : state) {
        std::mutex mutex;
        std::string stage;
        double fraction = 0.0;
        std::optional<Clock::time_point> cancelledAt;
        std::string stageAtCancel;
        int after = 0;
        Progress* self = nullptr;
        const Clock::time_point start = Clock::now();
        // Never calls into the Progress: its reports hold its lock while they call in here.
        const auto check = [&](const std::string* reported, double f) {
            std::lock_guard<std::mutex> lock(mutex);
            if (reported) {
                stage = *reported;
                fraction = f;
            }
            if (cancelledAt) {
                after += reported != nullptr;
                return;
            }
            if (trigger(Clock::now() - start, fraction, stage)) {
                stageAtCancel = stage;
                cancelledAt = Clock::now();
                self->cancel();
            }
        };
        Progress progress([&](double f, const std::string& s) { check(&s, f); });
        self = &progress;
        std::atomic<bool> done{false};
        std::thread watcher([&] {
            while (!done) {
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
                check(nullptr, 0.0);
            }
        });
        auto plan = mission::planMission(m, &progress);
        const Clock::time_point end = Clock::now();
        done = true;
        watcher.join();
        if (!cancelledAt) {
            state.SkipWithError("the plan finished before the cancel point");
            return;
        }
        if (plan || plan.error().code != ErrorCode::Cancelled) {
            state.SkipWithError("a cancelled plan did not return Cancelled");
            return;
        }
        const double s = std::chrono::duration<double>(end - *cancelledAt).count();
        worst = std::max(worst, s);
        lateReports = std::max(lateReports, after);
        state.SetIterationTime(s);
        stageSeen = stageAtCancel;
    }
    state.SetLabel(stageSeen);
    state.counters["worst_latency_ms"] = 1000.0 * worst;
    state.counters["reports_after_cancel"] = lateReports;
}

// Cancelled when the progress passes range(1) %.
void BM_CancelFleetAtProgress(benchmark::State& state) {
    auto m = fleetMission(state.range(0));
    if (!m) {
        state.SkipWithError(m.error().message.c_str());
        return;
    }
    const double at = static_cast<double>(state.range(1)) / 100.0;
    cancelledPlan(state, *m, [at](Clock::duration, double fraction, const std::string&) {
        return fraction >= at;
    });
}

// Cancelled range(1) ms after the start (the first seconds of a fleet plan choose the estimates'
// grid angle, with few reports).
void BM_CancelFleetAtMs(benchmark::State& state) {
    auto m = fleetMission(state.range(0));
    if (!m) {
        state.SkipWithError(m.error().message.c_str());
        return;
    }
    const auto at = std::chrono::milliseconds(state.range(1));
    cancelledPlan(state, *m,
                  [at](Clock::duration since, double, const std::string&) { return since >= at; });
}

BENCHMARK(BM_CancelFleetAtProgress)
    ->Args({0, 10})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_CancelFleetAtMs)
    ->Args({0, 100})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_CancelFleetAtProgressBig(benchmark::State& state) {
    BM_CancelFleetAtProgress(state);
}
void BM_CancelFleetAtMsBig(benchmark::State& state) {
    BM_CancelFleetAtMs(state);
}
BENCHMARK(BM_CancelFleetAtProgressBig)
    ->ArgsProduct({{1}, {6,  8,  10, 13, 16, 20, 25, 30, 35, 40, 45, 50, 55,
                         60, 65, 70, 72, 75, 78, 80, 83, 86, 88, 92, 96}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_CancelFleetAtMsBig)
    ->ArgsProduct({{1}, {50, 200, 400, 700, 1000, 1500, 2000, 2500, 3000, 3500, 4000, 4500, 5000}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

} // namespace
