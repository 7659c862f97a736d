// Benchmarks of the grid decomposition: 10^4 and 10^6 cells over a concave area with 50 no-fly zones.
#include "core/grid/grid.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

namespace {

using pf::geo::Vec2;

// A 2 km concave area (an L with a notched edge) and 50 round no-fly zones (16-gons, radius 20 to
// 60 m) scattered over it, some across its boundary; seeded, so every run builds the same problem.
struct Problem {
    pf::geo::Polygon area;
    std::vector<pf::geo::Polygon> noFly;
};

Problem makeProblem() {
    Problem p;
    p.area.outer = {Vec2(0, 0),       Vec2(2000, 0),    Vec2(2000, 900),  Vec2(1200, 1000),
                    Vec2(1100, 2000), Vec2(600, 1700),  Vec2(0, 2000)};
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> pos(0, 2000), rad(20, 60);
    while (p.noFly.size() < 50) {
        const Vec2 c(pos(rng), pos(rng));
        const double r = rad(rng);
        pf::geo::Polygon z;
        for (int k = 0; k < 16; ++k)
            z.outer.push_back(c + r * Vec2(std::cos(k * M_PI / 8), std::sin(k * M_PI / 8)));
        p.noFly.push_back(z);
    }
    return p;
}

// The cell size giving about `cells` cells over the area's bounding box rotated by angleDeg.
double cellSizeFor(const Problem& p, double angleDeg, long long cells) {
    const auto unit = pf::grid::Grid::sizeFor({p.area}, 1.0, angleDeg);
    return std::sqrt(unit.cells() / static_cast<double>(cells));
}

void BM_GridBuild(benchmark::State& state) {
    const Problem p = makeProblem();
    pf::grid::GridOptions opt;
    opt.angleDeg = 17.0;
    opt.cellSize = cellSizeFor(p, opt.angleDeg, state.range(0));
    opt.safetyMarginM = 5.0;
    int cells = 0, visit = 0;
    std::size_t bytes = 0;
    for (auto _ : state) {
        auto g = pf::grid::Grid::build(p.area, p.noFly, opt);
        if (!g.ok()) {
            state.SkipWithError(g.error().message.c_str());
            return;
        }
        cells = g->cellCount();
        visit = g->visitCount();
        bytes = g->memoryBytes();
        benchmark::DoNotOptimize(g);
    }
    state.counters["cells"] = cells;
    state.counters["to_visit"] = visit;
    state.counters["bytes_per_cell"] = static_cast<double>(bytes) / cells;
    state.SetItemsProcessed(state.iterations() * cells);
}
BENCHMARK(BM_GridBuild)->Arg(10'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// Queries the planners make per move: neighbour, canMove and onContour over every cell.
void BM_GridScan(benchmark::State& state) {
    const Problem p = makeProblem();
    pf::grid::GridOptions opt;
    opt.cellSize = cellSizeFor(p, 0.0, state.range(0));
    opt.safetyMarginM = 5.0;
    auto g = pf::grid::Grid::build(p.area, p.noFly, opt);
    if (!g.ok()) {
        state.SkipWithError(g.error().message.c_str());
        return;
    }
    for (auto _ : state) {
        long long n = 0;
        for (int i = 0; i < g->cellCount(); ++i) {
            if (!g->needsVisit(i))
                continue;
            n += g->onContour(i);
            for (auto d : pf::grid::kDirs)
                n += g->canMove(i, d) && g->neighbour(i, d) >= 0;
        }
        benchmark::DoNotOptimize(n);
    }
    state.SetItemsProcessed(state.iterations() * g->cellCount());
}
BENCHMARK(BM_GridScan)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

} // namespace
