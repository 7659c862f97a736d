// Benchmarks of the coverage planners: time per grid size (near-linear growth), 50 no-fly zones at 10^6
// cells, and the memory the planner holds per cell.
#include "core/grid/grid.h"
#include "core/plan/grid/raster_planner.h"
#include "core/plan/grid/stride_planner.h"
#include "core/plan/grid/wavefront_planner.h"
#include "core/plan/metrics.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>

namespace {

using pf::geo::Vec2;

// A square mask of about `cells` cells with seeded rectangular holes covering ~8 % of it (one hole per
// ~400 cells) and a notched border, as a synthetic grid.
pf::grid::Grid holedMask(long long cells) {
    const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(cells))));
    std::vector<std::uint8_t> m(static_cast<std::size_t>(side) * side, 1);
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> pos(1, side - 8), len(1, 6);
    const long long holes = static_cast<long long>(side) * side / 400;
    for (long long h = 0; h < holes; ++h) {
        const int x = pos(rng), y = pos(rng), w = len(rng), hh = len(rng);
        for (int yy = y; yy < y + hh && yy < side; ++yy)
            for (int xx = x; xx < x + w && xx < side; ++xx)
                m[static_cast<std::size_t>(yy) * side + xx] = 0;
    }
    for (int x = 0; x < side; x += 9) // notches along the south edge
        m[static_cast<std::size_t>(x)] = 0;
    return pf::grid::Grid::fromMask(side, side, m, 1.0);
}

// The grid benchmark's problem: a 2 km concave area with 50 round no-fly zones, gridded to ~cells.
const pf::grid::Grid& noFlyGrid(long long cells) {
    static std::map<long long, std::unique_ptr<pf::grid::Grid>> cache;
    auto& slot = cache[cells];
    if (!slot) {
        pf::geo::Polygon area;
        area.outer = {Vec2(0, 0), Vec2(2000, 0), Vec2(2000, 900), Vec2(1200, 1000), Vec2(1100, 2000), Vec2(600, 1700),
                      Vec2(0, 2000)};
        std::vector<pf::geo::Polygon> zones;
        std::mt19937 rng(42);
        std::uniform_real_distribution<double> pos(0, 2000), rad(20, 60);
        while (zones.size() < 50) {
            const Vec2 c(pos(rng), pos(rng));
            const double r = rad(rng);
            pf::geo::Polygon z;
            for (int k = 0; k < 16; ++k)
                z.outer.push_back(c + r * Vec2(std::cos(k * M_PI / 8), std::sin(k * M_PI / 8)));
            zones.push_back(z);
        }
        pf::grid::GridOptions opt;
        const auto unit = pf::grid::Grid::sizeFor({area}, 1.0, 0.0);
        opt.cellSize = std::sqrt(unit.cells() / static_cast<double>(cells));
        opt.safetyMarginM = 5.0;
        auto g = pf::grid::Grid::build(area, zones, opt);
        slot = std::make_unique<pf::grid::Grid>(g.ok() ? std::move(*g) : pf::grid::Grid::fromMask(1, 1, {1}));
    }
    return *slot;
}

// Bytes the stride planner holds per grid cell: its per-cell working arrays, the path, and the grid.
void reportStride(benchmark::State& state, const pf::grid::Grid& g, const pf::plan::CellPath& path,
                  const pf::plan::StrideTrace& trace) {
    const double cells = g.cellCount();
    const double pathBytes = static_cast<double>(path.cells.capacity()) * sizeof(int) + path.revisit.capacity() / 8.0;
    const double searchQueue = static_cast<double>(g.cellCount()) * sizeof(int); // worst case of a search queue
    state.counters["cells"] = cells;
    state.counters["to_visit"] = g.visitCount();
    state.counters["bytes_per_cell"] =
        (static_cast<double>(trace.scratchBytes) + pathBytes + searchQueue + static_cast<double>(g.memoryBytes())) /
        cells;
    state.counters["searches"] = trace.partitionSearches;
    state.counters["dead_ends"] = trace.deadEnds;
    state.SetItemsProcessed(state.iterations() * g.cellCount());
}

// Plans the whole grid with the stride planner once per iteration and reports the last plan.
void runStride(benchmark::State& state, const pf::grid::Grid& g) {
    pf::plan::CellPath path;
    pf::plan::StrideTrace trace;
    for (auto _ : state) {
        trace = {};
        auto p = pf::plan::planStride(g, {}, &trace);
        path = std::move(*p);
        benchmark::DoNotOptimize(path);
    }
    reportStride(state, g, path, trace);
}

void BM_StrideHoledMask(benchmark::State& state) { runStride(state, holedMask(state.range(0))); }
BENCHMARK(BM_StrideHoledMask)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void BM_StrideNoFly(benchmark::State& state) { runStride(state, noFlyGrid(state.range(0))); }
BENCHMARK(BM_StrideNoFly)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void BM_RasterNoFly(benchmark::State& state) {
    const pf::grid::Grid& g = noFlyGrid(state.range(0));
    for (auto _ : state) {
        auto p = pf::plan::planRaster(g, {});
        benchmark::DoNotOptimize(p);
    }
    state.counters["cells"] = g.cellCount();
    state.SetItemsProcessed(state.iterations() * g.cellCount());
}
BENCHMARK(BM_RasterNoFly)->Arg(10'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void BM_WavefrontNoFly(benchmark::State& state) {
    const pf::grid::Grid& g = noFlyGrid(state.range(0));
    pf::plan::WavefrontOptions opt;
    opt.maxCandidates = 4;
    for (auto _ : state) {
        auto p = pf::plan::planWavefront(g, {}, opt);
        benchmark::DoNotOptimize(p);
    }
    state.counters["cells"] = g.cellCount();
    state.SetItemsProcessed(state.iterations() * g.cellCount());
}
BENCHMARK(BM_WavefrontNoFly)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

void BM_TurnLowerBound(benchmark::State& state) {
    const pf::grid::Grid& g = noFlyGrid(state.range(0));
    int runs = 0;
    for (auto _ : state)
        benchmark::DoNotOptimize(runs = pf::plan::minStraightRuns(g));
    state.counters["runs"] = runs;
}
BENCHMARK(BM_TurnLowerBound)->Arg(10'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

} // namespace
