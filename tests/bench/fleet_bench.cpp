// Fleet stages: partition speed, time balancing with the real planner, planMission end to end with
// several aircraft (time and makespan), coverage check, detours.
#include "core/fleet/area_split.h"
#include "core/fleet/capability.h"
#include "core/fleet/partition.h"
#include "core/fleet/subarea_polygons.h"
#include "core/fleet/time_balance.h"
#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/grid/grid.h"
#include "core/io/catalog.h"
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mission/validation.h"
#include "core/plan/coverage_check.h"
#include "core/plan/evaluation.h"
#include "core/route/safety.h"
#include "tests/sample_missions.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

using namespace pf;

namespace {

// A square mask with notches and holes, reduced to nothing fancy: big enough to time the partition.
grid::Grid bigMask(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(n * n), 1);
    auto cut = [&](int x0, int y0, int w, int h) {
        for (int y = std::max(0, y0); y < std::min(n, y0 + h); ++y)
            for (int x = std::max(0, x0); x < std::min(n, x0 + w); ++x)
                mask[static_cast<std::size_t>(y * n + x)] = 0;
    };
    cut(0, 0, n / 3, n / 3);           // concave corner
    cut(n / 2, n - n / 4, n / 6, n);   // notch from the top
    std::uniform_int_distribution<int> pos(n / 8, n - n / 4);
    for (int i = 0; i < 6; ++i)        // holes
        cut(pos(rng), pos(rng), n / 16 + 1, n / 12 + 1);
    return grid::Grid::fromMask(n, n, mask, 10.0);
}

void BM_PartitionCells(benchmark::State& state) {
    const auto g = bigMask(static_cast<int>(state.range(0)), 7);
    const std::vector<double> shares{1.0, 1.7, 0.8, 1.3};
    for (auto _ : state) {
        auto p = fleet::partitionCells(g, shares);
        benchmark::DoNotOptimize(p);
    }
    state.counters["cells"] = static_cast<double>(g.visitCount());
}
BENCHMARK(BM_PartitionCells)->Arg(40)->Arg(120)->Arg(300)->Unit(benchmark::kMillisecond);

struct Demo {
    geo::LocalFrame frame;
    geo::Polygon area;
    std::vector<geo::Polygon> noFly;
    geo::Vec2 home;
};

Demo demo() {
    const geo::GeoPolygon area{{{8.3272608, 49.0109209}, {8.3324653, 49.0108309}, {8.3327392, 49.0123597},
                                {8.3308218, 49.0125396}, {8.3305478, 49.0133489}, {8.3273978, 49.013259}},
                               {}};
    auto frame = geo::LocalFrame::forArea(area);
    Demo d{*frame, frame->toLocal(area), {}, frame->toLocal(geo::LonLat{8.3270554, 49.010741})};
    d.noFly.push_back(frame->toLocal(geo::GeoPolygon{
        {{8.3291782, 49.0118201}, {8.3297261, 49.0118201}, {8.3297261, 49.0121799}, {8.3291782, 49.0121799}}, {}}));
    const geo::Vec2 mast = frame->toLocal(geo::LonLat{8.3316435, 49.0115504});
    geo::Polygon zone;
    for (int i = 0; i < 16; ++i)
        zone.outer.push_back(mast + 20.0 * geo::Vec2(std::cos(i * M_PI / 8), std::sin(i * M_PI / 8)));
    d.noFly.push_back(zone);
    return d;
}

// A mixed fleet: the same 1" camera at different altitudes, speeds and turn rates.
std::vector<mission::AircraftConfig> mixedFleet(int n) {
    sensor::Camera cam;
    cam.name = "1-inch 20 MP";
    cam.sensorWidthMm = 13.2;
    cam.sensorHeightMm = 8.8;
    cam.focalLengthMm = 8.8;
    cam.imageWidthPx = 5472;
    cam.imageHeightPx = 3648;
    const double alt[4] = {40, 70, 55, 30};
    const double speed[4] = {8, 12, 6, 10};
    const double turn[4] = {90, 60, 120, 45};
    std::vector<mission::AircraftConfig> out;
    for (int k = 0; k < n; ++k) {
        mission::AircraftConfig a;
        a.name = "A" + std::to_string(k + 1);
        a.camera = cam;
        a.altitudeM = alt[k];
        a.cruiseSpeedMps = speed[k];
        a.turnRateDegS = turn[k];
        out.push_back(a);
    }
    return out;
}

// Partition of the demo site for n aircraft, then balancing with planRegion as the estimator;
// counters: makespan / ideal before and after, estimator calls.
void BM_BalanceDemoWithStridePlanner(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const auto d = demo();
    const auto fleetCfg = mixedFleet(n);
    std::vector<fleet::Capability> caps;
    std::vector<double> sizes;
    for (const auto& a : fleetCfg) {
        auto fp = sensor::effectiveFootprint(a.camera, *a.altitudeM, a.overlap);
        caps.push_back({a.name, *fp, mission::flightModel(a)});
        sizes.push_back(fleet::aircraftCellSize(*fp));
    }
    const double areaM2 = geo::area(d.area);
    const double base = *fleet::baseCellSize(sizes, areaM2);
    grid::GridOptions go;
    go.cellSize = base;
    go.safetyMarginM = 5;
    auto g = grid::Grid::build(d.area, d.noFly, go);
    const grid::Grid& b = *g;
    mission::PlannerOptions po;
    po.gridAngleDeg = 0.0;
    po.safetyMarginM = 5;
    auto estimate = [&](int k, const std::vector<int>& cells) -> Result<double> {
        const auto region = fleet::cellsPolygon(b, cells, g->admissible());
        auto ap =
            mission::planRegion(region, d.noFly, fleetCfg[static_cast<std::size_t>(k)], po, d.home);
        if (!ap)
            return ap.error();
        return ap->metrics.estimatedTimeS;
    };
    double before = 0, after = 0, calls = 0;
    for (auto _ : state) {
        auto p = fleet::partitionCells(b, *fleet::capabilityShares(caps, areaM2));
        std::vector<double> t;
        for (int k = 0; k < n; ++k)
            t.push_back(*estimate(k, p->cells[static_cast<std::size_t>(k)]));
        before = *std::max_element(t.begin(), t.end()) / (std::accumulate(t.begin(), t.end(), 0.0) / n);
        auto rep = fleet::balanceByTime(b, *p, estimate);
        if (!rep) {
            state.SkipWithError(rep.error().message.c_str());
            return;
        }
        after = rep->makespan / rep->ideal;
        calls = rep->estimatorCalls;
    }
    state.counters["makespan_over_ideal_before"] = before;
    state.counters["makespan_over_ideal_after"] = after;
    state.counters["estimator_calls"] = calls;
}
BENCHMARK(BM_BalanceDemoWithStridePlanner)->Arg(2)->Arg(3)->Arg(4)->Unit(benchmark::kMillisecond)->Iterations(1);

// splitArea on the demo at 3.5 m with the extra zone (50,000 base cells), balanced on an analytic
// time (the cells' area over the aircraft's sweep rate, plus a turn per grid row; the first
// aircraft's scaled by 1.4 as a correction round scales an estimate, so that thousands of cells
// move), so that the time is the partition's and the cell moves' own: the cost of moving cells past
// the zone.
void BM_SplitDemoLowWithZone(benchmark::State& state) {
    auto m = test::lowDemoWithZone(PF_RESOURCES_DIR);
    if (!m) {
        state.SkipWithError(m.error().message.c_str());
        return;
    }
    auto geom = mission::localGeometry(*m);
    if (!geom) {
        state.SkipWithError(geom.error().message.c_str());
        return;
    }
    std::vector<fleet::Capability> caps;
    for (const auto& a : m->aircraft)
        caps.push_back({a.name, *sensor::effectiveFootprint(a.camera, *a.altitudeM, a.overlap),
                        mission::flightModel(a)});
    fleet::AreaSplitOptions so;
    so.safetyMarginM = m->options.safetyMarginM;
    so.balance.tolerance = 0.03;
    const fleet::CellsTimeEstimator estimate = [&](int k, const std::vector<int>& cells,
                                                   const grid::Grid& g) {
        std::vector<int> rows;
        for (int c : cells)
            rows.push_back(c / g.cols());
        std::sort(rows.begin(), rows.end());
        rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
        const auto& c = caps[static_cast<std::size_t>(k)];
        const double sweep = static_cast<double>(cells.size()) * g.cellSize() * g.cellSize() /
                             (c.footprint.acrossM * c.time.speedMps);
        return Result<double>((k == 0 ? 1.4 : 1.0) *
                              (sweep + 3.0 * static_cast<double>(rows.size())));
    };
    double calls = 0, ratio = 0;
    for (auto _ : state) {
        auto split = fleet::splitArea(geom->area, geom->noFly, caps, so, estimate);
        if (!split) {
            state.SkipWithError(split.error().message.c_str());
            return;
        }
        calls = split->balance->estimatorCalls;
        ratio = split->balance->makespan / split->balance->ideal;
    }
    state.counters["estimator_calls"] = calls;
    state.counters["makespan_over_ideal"] = ratio;
}
BENCHMARK(BM_SplitDemoLowWithZone)->Unit(benchmark::kMillisecond)->Iterations(1);

// planMission end to end on the demo mission (two aircraft, grid angle searched): the time-balanced
// split with its correction rounds, then every stage after it. Counters: the makespan and its ratio
// to the ideal (total time / aircraft).
void BM_PlanMissionDemo(benchmark::State& state) {
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    if (!m) {
        state.SkipWithError(m.error().message.c_str());
        return;
    }
    double makespan = 0, ideal = 0;
    for (auto _ : state) {
        auto plan = mission::planMission(*m);
        if (!plan) {
            state.SkipWithError(plan.error().message.c_str());
            return;
        }
        makespan = plan->makespanS;
        ideal = plan->idealS;
    }
    state.counters["makespan_s"] = makespan;
    state.counters["makespan_over_ideal"] = makespan / ideal;
}
BENCHMARK(BM_PlanMissionDemo)->Unit(benchmark::kMillisecond)->Iterations(3);

// planMission on the sample area c_l_shape with 2 to 4 mixed catalog aircraft (as the fleet target
// test flies them: grid angle 0, home 30 m south of the southernmost vertex).
void BM_PlanMissionLShapeFleet(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    auto ea = plan::loadEvalArea(std::string(PF_RESOURCES_DIR) + "/areas/c_l_shape.geojson");
    auto cat = io::loadCatalog(std::string(PF_RESOURCES_DIR) + "/catalog.json");
    if (!ea || !cat) {
        state.SkipWithError("the sample area or the catalog cannot be read");
        return;
    }
    mission::Mission m = test::sampleAreaMission(*ea);
    const std::pair<const char*, double> fleet[4] = {
        {"Falcon 8", 50.0}, {"DJI Phantom 4 Pro", 60.0}, {"DJI Mavic 3 Enterprise", 70.0}, {"DJI Matrice 300 RTK", 80.0}};
    for (int k = 0; k < n; ++k) {
        auto a = test::catalogAircraft(*cat, fleet[k].first, fleet[k].second);
        if (!a) {
            state.SkipWithError("a fleet aircraft is missing from the catalog");
            return;
        }
        m.aircraft.push_back(*a);
    }
    double makespan = 0, ideal = 0;
    for (auto _ : state) {
        auto plan = mission::planMission(m);
        if (!plan) {
            state.SkipWithError(plan.error().message.c_str());
            return;
        }
        makespan = plan->makespanS;
        ideal = plan->idealS;
    }
    state.counters["makespan_s"] = makespan;
    state.counters["makespan_over_ideal"] = makespan / ideal;
}
BENCHMARK(BM_PlanMissionLShapeFleet)->Arg(2)->Arg(3)->Arg(4)->Unit(benchmark::kMillisecond)->Iterations(3);

// Coverage check of the demo site tiled by 30 x 20 m footprints at 0.5 m pixels.
void BM_CoverageCheckDemo(benchmark::State& state) {
    const auto d = demo();
    const auto admissible = geo::difference(d.area, geo::MultiPolygon(d.noFly.begin(), d.noFly.end()));
    const auto box = geo::bounds(admissible);
    std::vector<plan::PhotoFootprint> photos;
    for (double y = box.min.y() + 6; y < box.max.y(); y += 12)
        for (double x = box.min.x() + 4; x < box.max.x(); x += 8)
            photos.push_back({geo::Vec2(x, y), 90.0, 30.0, 20.0});
    for (auto _ : state) {
        auto rep = plan::checkCoverage(admissible, photos);
        benchmark::DoNotOptimize(rep);
    }
    state.counters["photos"] = static_cast<double>(photos.size());
}
BENCHMARK(BM_CoverageCheckDemo)->Unit(benchmark::kMillisecond);

// Shortest safe detour across the demo site, between the two no-fly zones.
void BM_SafeDetourDemo(benchmark::State& state) {
    const auto d = demo();
    for (auto _ : state) {
        const route::SafePathFinder finder(route::NoFlyField(d.noFly, 5.0));
        auto path = finder.detour(d.home, d.home + geo::Vec2(300, 130));
        benchmark::DoNotOptimize(path);
    }
}
BENCHMARK(BM_SafeDetourDemo)->Unit(benchmark::kMicrosecond);

} // namespace
