// Benchmarks of the geo stage: frame transformations and polygon queries.
#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

void BM_LocalFrameRing(benchmark::State& state) {
    auto frame = pf::geo::LocalFrame::create({8.4, 49.0});
    pf::geo::GeoRing ring;
    for (int i = 0; i < state.range(0); ++i) {
        const double a = 2 * M_PI * i / state.range(0);
        ring.push_back({8.4 + 0.01 * std::cos(a), 49.0 + 0.01 * std::sin(a)});
    }
    for (auto _ : state)
        benchmark::DoNotOptimize(frame->toLocal(ring));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_LocalFrameRing)->Arg(1000)->Arg(100000);

void BM_Contains(benchmark::State& state) {
    pf::geo::Polygon p;
    for (int i = 0; i < state.range(0); ++i) {
        const double a = 2 * M_PI * i / state.range(0);
        p.outer.emplace_back(100 * std::cos(a), 100 * std::sin(a));
    }
    double x = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(pf::geo::contains(p, pf::geo::Vec2(x, 10)));
        x = x > 100 ? -100 : x + 0.37;
    }
}
BENCHMARK(BM_Contains)->Arg(16)->Arg(1024);

} // namespace
