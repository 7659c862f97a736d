// Benchmarks of corridors and double grids: a 20 km corridor 100 m wide with bends, planned by the
// corridor planner alone and as a whole mission (transit, sorties, the coverage check on its
// ground); the demo as a double grid, nadir and oblique.
#include "core/geo/local_frame.h"
#include "core/io/mission_file.h"
#include "core/mission/corridor.h"
#include "core/mission/plan_mission.h"
#include "core/plan/corridor/corridor_planner.h"
#include "tests/sample_missions.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

namespace {

using pf::geo::Vec2;

// A seeded line of `km` kilometres: legs of 300-800 m turning by 10-60 degrees either way.
std::vector<Vec2> windingLine(double km, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> leg(300, 800), turn(10, 60);
    std::vector<Vec2> line{Vec2(0, 0)};
    double a = 0.3, done = 0.0;
    int side = 1;
    while (done < km * 1000.0) {
        const double l = std::min(leg(rng), km * 1000.0 - done);
        line.push_back(line.back() + l * Vec2(std::cos(a), std::sin(a)));
        done += l;
        a += side * turn(rng) * M_PI / 180.0;
        side = -side;
    }
    return line;
}

// A 60 x 45 degree camera at 40 m with a mapping overlap (75 % front, 60 % side): 8 lanes over 100
// m.
pf::plan::CorridorOptions options(double widthM) {
    pf::plan::CorridorOptions o;
    const double across = 2 * 40 * std::tan(30 * M_PI / 180),
                 along = 2 * 40 * std::tan(22.5 * M_PI / 180);
    o.widthM = widthM;
    o.trackSpacingM = 0.4 * across;
    o.photoSpacingM = 0.25 * along;
    o.home = Vec2(-50, -50);
    return o;
}

void BM_CorridorPlanner(benchmark::State& state) {
    const auto line = windingLine(static_cast<double>(state.range(0)), 7);
    const auto o = options(100.0);
    int photos = 0;
    for (auto _ : state) {
        auto p = pf::plan::planCorridor(line, {}, o);
        photos = p ? p->stats.photos : -1;
        benchmark::DoNotOptimize(photos);
    }
    state.counters["photos"] = photos;
}
BENCHMARK(BM_CorridorPlanner)->Arg(2)->Arg(20)->Unit(benchmark::kMillisecond);

// The whole mission: the corridor's ground, the lanes, safety, sorties and the coverage check.
void BM_CorridorMission(benchmark::State& state) {
    auto frame = pf::geo::LocalFrame::create({8.33, 49.01});
    pf::mission::Mission m;
    pf::mission::applyCorridor(
        m, pf::mission::Corridor{frame->toGeo(windingLine(static_cast<double>(state.range(0)), 7)),
                                 100.0});
    m.home = frame->toGeo(Vec2(-50, -50));
    pf::mission::AircraftConfig a = pf::test::bigSiteAircraft(40.0);
    a.overlap = {0.75, 0.6};
    a.enduranceMin = 1000; // one flight: the planning, not the batteries, is measured
    m.aircraft.push_back(a);
    int photos = 0;
    for (auto _ : state) {
        auto p = pf::mission::planMission(m);
        if (!p)
            state.SkipWithError(p.error().message.c_str());
        photos = p ? p->totals.photos : -1;
        benchmark::DoNotOptimize(photos);
    }
    state.counters["photos"] = photos;
}
BENCHMARK(BM_CorridorMission)->Arg(2)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);

// The demo mission as a double grid with the cameras tilted forward by the argument (0: nadir, 30:
// oblique photos): what the tilt costs the planning (photos moved back, lead-ins, the no-fly stage
// and the coverage check on the tilted footprints). Counters: photos and makespan.
void BM_DoubleGridDemoTilt(benchmark::State& state) {
    auto m = pf::io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    if (!m) {
        state.SkipWithError(m.error().message.c_str());
        return;
    }
    m->options.doubleGrid = true;
    m->options.cameraTiltDeg = static_cast<double>(state.range(0));
    int photos = 0;
    double makespan = 0.0;
    for (auto _ : state) {
        auto p = pf::mission::planMission(*m);
        if (!p) {
            state.SkipWithError(p.error().message.c_str());
            return;
        }
        photos = p->totals.photos;
        makespan = p->makespanS;
    }
    state.counters["photos"] = photos;
    state.counters["makespan_s"] = makespan;
}
BENCHMARK(BM_DoubleGridDemoTilt)->Arg(0)->Arg(30)->Unit(benchmark::kMillisecond)->Iterations(2);

} // namespace
