// Benchmarks of the whole plan (what photoflight-cli plan does, without the files) on square sites with
// 30 round no-fly zones at 5 m altitude (the big-area case): time and peak memory per site size, and
// the latency of a cancel at several stages. Sites of 1.25 km and more are named "Big" and left out of
// CI's smoke run (--benchmark_filter=-Big); run them by hand:
//   build/tests/bench/pf_bench --benchmark_filter=Mission
// and the cancel latencies with --benchmark_filter='Cancel.*Big'.
#include "core/geo/local_frame.h"
#include "core/mission/plan_mission.h"
#include "core/progress.h"
#include "tests/sample_missions.h"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <random>
#include <thread>

namespace {

using namespace pf;

// A square site of `sideM` metres with 30 seeded round zones (radius 2 % of the side), home at the
// south-west corner, one Falcon 8 at 5 m (60 x 45 degree camera, 70 % / 60 % overlap).
mission::Mission squareSite(double sideM, mission::PlannerKind kind) {
    const geo::LocalFrame frame = *geo::LocalFrame::create({8.33, 49.01});
    mission::Mission m;
    m.area = frame.toGeo(geo::Polygon{{{0, 0}, {sideM, 0}, {sideM, sideM}, {0, sideM}}, {}});
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> at(0.1 * sideM, 0.9 * sideM);
    const double r = 0.02 * sideM;
    for (int z = 0; z < 30; ++z) {
        const geo::Vec2 c(at(rng), at(rng));
        geo::Polygon p;
        for (int k = 0; k < 16; ++k)
            p.outer.push_back(c + r * geo::Vec2(std::cos(k * M_PI / 8), std::sin(k * M_PI / 8)));
        m.noFlyZones.push_back({"zone " + std::to_string(z + 1), frame.toGeo(p)});
    }
    m.home = frame.toGeo(geo::Vec2{-30, -30});
    mission::AircraftConfig a = pf::test::bigSiteAircraft(5.0, "Falcon 8 camera");
    a.cruiseSpeedMps = 8;
    a.turnRateDegS = 60;
    a.enduranceMin = 40; // the far corner of a 5 km site and back within a battery
    m.aircraft.push_back(a);
    m.options.planner = kind;
    m.options.gridAngleDeg = 0.0;
    m.options.maxCells = 6'000'000;
    return m;
}

double peakRssMb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

void planSite(benchmark::State& state, mission::PlannerKind kind) {
    const mission::Mission m = squareSite(static_cast<double>(state.range(0)), kind);
    int photos = 0, cells = 0;
    for (auto _ : state) {
        auto plan = mission::planMission(m);
        if (!plan) {
            state.SkipWithError(plan.error().message.c_str());
            return;
        }
        photos = plan->totals.photos;
        cells = plan->totals.visitable;
        benchmark::DoNotOptimize(plan->makespanS);
    }
    state.counters["cells"] = cells;
    state.counters["photos"] = photos;
    // The process's peak so far: run one size per process for a clean figure.
    state.counters["peak_rss_mb"] = peakRssMb();
}

void BM_MissionStride(benchmark::State& state) { planSite(state, mission::PlannerKind::Stride); }
void BM_MissionAuto(benchmark::State& state) { planSite(state, mission::PlannerKind::Auto); }
BENCHMARK(BM_MissionStride)->Arg(250)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_MissionAuto)->Arg(250)->Unit(benchmark::kMillisecond)->Iterations(1);
// 10^5 and 10^6 cells (790 m and 2.5 km): the growth target is at most 12 x in time and memory.
void BM_MissionStrideBig(benchmark::State& state) { planSite(state, mission::PlannerKind::Stride); }
void BM_MissionAutoBig(benchmark::State& state) { planSite(state, mission::PlannerKind::Auto); }
BENCHMARK(BM_MissionStrideBig)->Arg(790)->Arg(1250)->Arg(2500)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_MissionAutoBig)->Arg(790)->Arg(1250)->Arg(2500)->Unit(benchmark::kMillisecond)->Iterations(1);

// Cancel latency: the plan runs on a thread; when its progress passes range(1) % it is cancelled, and
// the time from cancel() to planMission's return is measured (manual time). The stage it was in is
// the label.
// One cancelled run: skipped with the reason unless it was cancelled and returned Cancelled; else its
// latency (cancel to return) is the iteration's time and the worst so far is kept.
bool recordCancel(benchmark::State& state, bool cancelled, const Result<mission::MissionPlan>& plan,
                  std::chrono::steady_clock::time_point cancelledAt, std::chrono::steady_clock::time_point end,
                  double& worst) {
    if (!cancelled) {
        state.SkipWithError("the plan finished before the cancel point");
        return false;
    }
    if (plan || plan.error().code != ErrorCode::Cancelled) {
        state.SkipWithError("a cancelled plan did not return Cancelled");
        return false;
    }
    const double s = std::chrono::duration<double>(end - cancelledAt).count();
    worst = std::max(worst, s);
    state.SetIterationTime(s);
    return true;
}

void cancelAt(benchmark::State& state, mission::PlannerKind kind) {
    const mission::Mission m = squareSite(static_cast<double>(state.range(0)), kind);
    const double at = static_cast<double>(state.range(1)) / 100.0;
    double worst = 0.0;
    std::string stageSeen;
    for (auto _ : state) {
        std::atomic<bool> fired{false};
        std::chrono::steady_clock::time_point cancelledAt;
        std::string stage;
        Progress* self = nullptr;
        Progress progress([&](double f, const std::string& s) {
            if (f >= at && !fired.exchange(true)) {
                stage = s;
                cancelledAt = std::chrono::steady_clock::now();
                self->cancel();
            }
        });
        self = &progress;
        auto plan = mission::planMission(m, &progress);
        const auto end = std::chrono::steady_clock::now();
        if (!recordCancel(state, fired, plan, cancelledAt, end, worst))
            return;
        stageSeen = stage;
    }
    state.SetLabel(stageSeen);
    state.counters["worst_latency_ms"] = 1000.0 * worst;
}

void BM_CancelStride(benchmark::State& state) { cancelAt(state, mission::PlannerKind::Stride); }
void BM_CancelAuto(benchmark::State& state) { cancelAt(state, mission::PlannerKind::Auto); }
BENCHMARK(BM_CancelStride)->Args({250, 10})->Args({250, 70})->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CancelAuto)->Args({250, 30})->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);
void BM_CancelStrideBig(benchmark::State& state) { cancelAt(state, mission::PlannerKind::Stride); }
void BM_CancelAutoBig(benchmark::State& state) { cancelAt(state, mission::PlannerKind::Auto); }
BENCHMARK(BM_CancelStrideBig)
    ->ArgsProduct({{2500}, {1, 10, 30, 50, 60, 70, 86, 95}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_CancelAutoBig)
    ->ArgsProduct({{2500}, {1, 20, 40, 70, 90}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// Cancel latency inside a named stage: the cancel comes range(2) ms after the stage began (stages the
// percentage points above jump over, such as "detours and sorties", get measured too). The label is
// the stage running when the cancel came.
const char* const kStages[] = {"grid", "cell path", "photo waypoints", "detours and sorties", "coverage check"};

void cancelInStage(benchmark::State& state, mission::PlannerKind kind) {
    const mission::Mission m = squareSite(static_cast<double>(state.range(0)), kind);
    const std::string wanted = kStages[state.range(1)];
    double worst = 0.0;
    std::string stageSeen;
    for (auto _ : state) {
        std::mutex mutex;
        std::string stage;
        std::optional<std::chrono::steady_clock::time_point> entered;
        Progress progress([&](double, const std::string& s) {
            std::lock_guard<std::mutex> lock(mutex);
            stage = s;
            if (s == wanted && !entered)
                entered = std::chrono::steady_clock::now();
        });
        std::atomic<bool> done{false};
        std::chrono::steady_clock::time_point cancelledAt;
        std::string stageAtCancel;
        std::thread watcher([&] {
            while (!done) {
                std::this_thread::sleep_for(std::chrono::milliseconds(2));
                std::lock_guard<std::mutex> lock(mutex);
                if (entered && std::chrono::steady_clock::now() - *entered >= std::chrono::milliseconds(state.range(2))) {
                    stageAtCancel = stage;
                    cancelledAt = std::chrono::steady_clock::now();
                    progress.cancel();
                    return;
                }
            }
        });
        auto plan = mission::planMission(m, &progress);
        const auto end = std::chrono::steady_clock::now();
        done = true;
        watcher.join();
        if (!recordCancel(state, progress.cancelled(), plan, cancelledAt, end, worst))
            return;
        stageSeen = stageAtCancel;
    }
    state.SetLabel(stageSeen);
    state.counters["worst_latency_ms"] = 1000.0 * worst;
}

void BM_CancelInStageStrideBig(benchmark::State& state) { cancelInStage(state, mission::PlannerKind::Stride); }
BENCHMARK(BM_CancelInStageStrideBig)
    ->ArgsProduct({{2500}, {0, 1, 2, 3, 4}, {200, 1500}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

} // namespace
