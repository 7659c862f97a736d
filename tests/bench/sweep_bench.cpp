// Benchmarks of the sweep planner: a survey area like the generated ones (20 zones, every direction
// tried), and growth with the number of lanes (a strip 1 km wide, lanes across it, 20 zones), with the
// memory the process peaks at and the plan's own size.
#include "core/geo/polygon_ops.h"
#include "core/plan/sweep/sweep_planner.h"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cmath>
#include <random>

namespace {

using pf::geo::Vec2;

// The camera: 60 x 45 degrees at 30 m, 20 % overlap.
pf::plan::SweepOptions cameraOptions() {
    pf::plan::SweepOptions o;
    o.realAcrossM = 2 * 30 * std::tan(30 * M_PI / 180);
    o.realAlongM = 2 * 30 * std::tan(22.5 * M_PI / 180);
    o.trackSpacingM = 0.8 * o.realAcrossM;
    o.photoSpacingM = 0.8 * o.realAlongM;
    return o;
}

pf::geo::Polygon box(double x0, double y0, double x1, double y1) {
    return pf::geo::Polygon{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}, {}};
}

// `count` zones inside [0, w] x [0, h], 20-80 m across, round or rotated rectangles, 10 m apart.
std::vector<pf::geo::Polygon> zones(double w, double h, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> x(60, w - 60), y(60, h - 60), size(10, 40), ang(0, M_PI);
    std::vector<pf::geo::Polygon> out;
    std::vector<std::pair<Vec2, double>> placed;
    for (int tries = 0; static_cast<int>(out.size()) < count && tries < 10000; ++tries) {
        const Vec2 c(x(rng), y(rng));
        const double r = size(rng);
        bool clash = false;
        for (const auto& [pc, pr] : placed)
            clash = clash || (pc - c).norm() < pr + r + 10;
        if (clash)
            continue;
        placed.emplace_back(c, r * 1.5);
        pf::geo::Polygon z;
        if (out.size() % 2 == 0) {
            for (int k = 0; k < 24; ++k)
                z.outer.push_back(c + r * Vec2(std::cos(k * M_PI / 12), std::sin(k * M_PI / 12)));
        } else {
            const double a = ang(rng), b = size(rng);
            const Vec2 u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
            z.outer = {c - r * u - b * v, c + r * u - b * v, c + r * u + b * v, c - r * u + b * v};
        }
        out.push_back(z);
    }
    return out;
}

void report(benchmark::State& state, const pf::plan::SweepPlan& plan) {
    std::size_t photos = 0;
    for (const auto& l : plan.lanes)
        photos += l.photos.size();
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    state.counters["lanes"] = static_cast<double>(plan.lanes.size());
    state.counters["photos"] = static_cast<double>(photos);
    state.counters["cells"] = plan.stats.cellsAfterMerge;
    state.counters["dirs_planned"] = plan.stats.directionsPlanned;
    state.counters["plan_MB"] =
        static_cast<double>(photos * sizeof(Vec2) + plan.lanes.size() * sizeof(pf::plan::Lane)) / 1e6;
    state.counters["peak_rss_MB"] = static_cast<double>(ru.ru_maxrss) / 1024.0;
}

// A 0.2 km2 site with 20 zones, every candidate direction: what the GUI plans after an edit.
void BM_SweepSite20Zones(benchmark::State& state) {
    const pf::geo::MultiPolygon area{box(0, 0, 560, 360)};
    const auto z = zones(560, 360, 20, 5);
    const auto o = cameraOptions();
    pf::plan::SweepPlan last;
    for (auto _ : state) {
        auto plan = pf::plan::planSweep(area, z, o);
        if (!plan.ok()) {
            state.SkipWithError(plan.error().message.c_str());
            return;
        }
        last = std::move(*plan);
        benchmark::DoNotOptimize(last.time.totalS);
    }
    report(state, last);
}
BENCHMARK(BM_SweepSite20Zones)->Unit(benchmark::kMillisecond);

// Growth: a strip 1 km wide and long enough for about `lanes` lanes across it (the direction fixed
// across the strip, as the fastest would run along it), with 20 zones.
void sweepStrip(benchmark::State& state, bool fixedDirection) {
    const double lanes = static_cast<double>(state.range(0));
    auto o = cameraOptions();
    const double h = lanes * o.trackSpacingM * 0.98;
    const pf::geo::MultiPolygon area{box(0, 0, 1000, h)};
    const auto z = zones(1000, h, 20, 11);
    if (fixedDirection)
        o.anglesDeg = {0.0};
    pf::plan::SweepPlan last;
    for (auto _ : state) {
        auto plan = pf::plan::planSweep(area, z, o);
        if (!plan.ok()) {
            state.SkipWithError(plan.error().message.c_str());
            return;
        }
        last = std::move(*plan);
        benchmark::DoNotOptimize(last.time.totalS);
    }
    report(state, last);
}
void BM_SweepLanes(benchmark::State& state) { sweepStrip(state, true); }
BENCHMARK(BM_SweepLanes)->Arg(1'000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

// The same 10^3-lane strip with every candidate direction planned (it then flies along the strip).
void BM_SweepLanesAllDirections(benchmark::State& state) { sweepStrip(state, false); }
BENCHMARK(BM_SweepLanesAllDirections)->Arg(1'000)->Unit(benchmark::kMillisecond);

} // namespace
