// Benchmarks of planning for planes: a 2 km2 square (1414 m side) with 10 round no-fly zones at
// 3 cm/px (a 5472 px camera of 73 degrees at 110 m) for one fixed-wing, and the same site for a
// fleet of a fixed-wing, a VTOL and a multirotor (named "Big": left out of CI's smoke run). Run:
//   build/tests/bench/pf_bench --benchmark_filter=Plane
#include "core/geo/local_frame.h"
#include "core/mission/plan_mission.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

namespace {

using namespace pf;

mission::AircraftConfig surveyAircraft(const std::string& name, fleet::AircraftKind kind) {
    mission::AircraftConfig a;
    a.name = name;
    a.kind = kind;
    a.camera.name = "5472 px, 73 degrees";
    a.camera.hfovDeg = 73.0;
    a.camera.vfovDeg = 52.0;
    a.camera.imageWidthPx = 5472;
    a.camera.imageHeightPx = 3648;
    a.gsdCm = 3.0;
    a.cruiseSpeedMps = kind == fleet::AircraftKind::Multirotor ? 10.0 : 15.0;
    a.enduranceMin = kind == fleet::AircraftKind::Multirotor ? 30.0 : 90.0;
    a.plane.minTurnRadiusM = 25.0;
    return a;
}

mission::Mission site(std::vector<mission::AircraftConfig> aircraft) {
    const double side = std::sqrt(2.0e6);
    const geo::LocalFrame frame = *geo::LocalFrame::create({8.33, 49.01});
    mission::Mission m;
    m.area = frame.toGeo(geo::Polygon{{{0, 0}, {side, 0}, {side, side}, {0, side}}, {}});
    std::mt19937 rng(37);
    std::uniform_real_distribution<double> at(0.15 * side, 0.85 * side);
    for (int z = 0; z < 10; ++z) {
        const geo::Vec2 c(at(rng), at(rng));
        geo::Polygon p;
        for (int k = 0; k < 16; ++k)
            p.outer.push_back(c + 30.0 * geo::Vec2(std::cos(k * M_PI / 8), std::sin(k * M_PI / 8)));
        m.noFlyZones.push_back({"zone " + std::to_string(z + 1), frame.toGeo(p)});
    }
    m.home = frame.toGeo(geo::Vec2{-40, -40});
    m.aircraft = std::move(aircraft);
    return m;
}

void BM_PlanePlan2km2(benchmark::State& state) {
    const mission::Mission m = site({surveyAircraft("Wing", fleet::AircraftKind::FixedWing)});
    for (auto _ : state) {
        auto p = mission::planMission(m);
        if (!p)
            state.SkipWithError(p.error().message.c_str());
        benchmark::DoNotOptimize(p);
    }
}
BENCHMARK(BM_PlanePlan2km2)->Unit(benchmark::kMillisecond);

void BM_PlaneFleetOf3Big(benchmark::State& state) {
    const mission::Mission m = site({surveyAircraft("Wing", fleet::AircraftKind::FixedWing),
                                     surveyAircraft("Quadplane", fleet::AircraftKind::Vtol),
                                     surveyAircraft("Copter", fleet::AircraftKind::Multirotor)});
    for (auto _ : state) {
        auto p = mission::planMission(m);
        if (!p)
            state.SkipWithError(p.error().message.c_str());
        benchmark::DoNotOptimize(p);
    }
}
BENCHMARK(BM_PlaneFleetOf3Big)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
