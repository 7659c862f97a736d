// The fleet stages on real grids of the demo site: base grid, partition, per-aircraft grids.
#include "core/fleet/aircraft_grids.h"
#include "core/fleet/area_split.h"
#include "core/fleet/capability.h"
#include "core/fleet/partition.h"
#include "core/fleet/subarea_polygons.h"
#include "core/fleet/time_balance.h"
#include "core/geo/polygon_ops.h"
#include "core/grid/grid.h"
#include "core/mission/plan_mission.h"
#include "core/fleet/photo_dedup.h"
#include "core/plan/coverage_check.h"
#include "core/route/safety.h"
#include "core/route/sorties.h"
#include "core/route/transit.h"

#include "tests/core/fleet/demo_site.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

using namespace pf;
using namespace pf::fleet;

namespace {

std::vector<Capability> demoFleet() {
    // Effective footprints of three different camera/altitude pairs, speeds and turn rates.
    std::vector<Capability> f(3);
    f[0] = {"Falcon 8 #1", {24.0, 12.0, {60.0, 40.0}}, 8.0, 90.0};
    f[1] = {"Phantom", {36.0, 21.0, {90.0, 60.0}}, 10.0, 120.0};
    f[2] = {"Hexa", {30.0, 15.0, {75.0, 50.0}}, 6.0, 60.0};
    return f;
}

// Aircraft configs with the same 1" camera at different altitudes, speeds and turn rates.
std::vector<mission::AircraftConfig> mixedConfigs(int n, std::mt19937& rng) {
    sensor::Camera cam;
    cam.name = "1-inch 20 MP";
    cam.sensorWidthMm = 13.2;
    cam.sensorHeightMm = 8.8;
    cam.focalLengthMm = 8.8;
    cam.imageWidthPx = 5472;
    cam.imageHeightPx = 3648;
    std::uniform_real_distribution<double> alt(30, 80), speed(5, 14), turn(45, 120);
    std::vector<mission::AircraftConfig> out;
    for (int k = 0; k < n; ++k) {
        mission::AircraftConfig a;
        a.name = "A" + std::to_string(k + 1);
        a.camera = cam;
        a.altitudeM = alt(rng);
        a.cruiseSpeedMps = speed(rng);
        a.turnRateDegS = turn(rng);
        out.push_back(a);
    }
    return out;
}

// A concave outline (an L or a U) of a few hectares with one or two square no-fly zones inside.
std::pair<geo::Polygon, std::vector<geo::Polygon>> generatedSite(std::mt19937& rng) {
    std::uniform_real_distribution<double> side(250, 450), frac(0.3, 0.6);
    const double w = side(rng), h = side(rng), cw = frac(rng) * w, ch = frac(rng) * h;
    geo::Polygon area;
    if (rng() % 2)
        area.outer = {geo::Vec2(0, 0), geo::Vec2(w, 0), geo::Vec2(w, h - ch), geo::Vec2(w - cw, h - ch),
                      geo::Vec2(w - cw, h), geo::Vec2(0, h)}; // L
    else
        area.outer = {geo::Vec2(0, 0), geo::Vec2(w, 0), geo::Vec2(w, h), geo::Vec2(0.5 * (w + cw), h),
                      geo::Vec2(0.5 * (w + cw), h - ch), geo::Vec2(0.5 * (w - cw), h - ch), geo::Vec2(0.5 * (w - cw), h),
                      geo::Vec2(0, h)}; // U
    std::vector<geo::Polygon> noFly;
    const int zones = 1 + static_cast<int>(rng() % 2);
    for (int i = 0; i < zones; ++i) {
        const double s = 20 + 20 * (i + 1), x = 30 + (w - 2 * s) * 0.2 * (i + 1), y = 40 + 0.15 * h * (i + 1);
        noFly.push_back(geo::Polygon{{geo::Vec2(x, y), geo::Vec2(x + s, y), geo::Vec2(x + s, y + s), geo::Vec2(x, y + s)}, {}});
    }
    return {area, noFly};
}

} // namespace

TEST(FleetOnGrid, SubareaCellsAreTheGridsOwnCells) {
    const auto site = test::demoSite();
    grid::GridOptions opt;
    opt.cellSize = 15.0;
    opt.angleDeg = 27.0;
    auto g = grid::Grid::build(site.area, site.noFly, opt);
    ASSERT_TRUE(g.ok()) << g.error().message;
    for (int i = 0; i < g->cellCount(); i += 7) {
        if (!g->needsVisit(i))
            continue;
        const auto poly = cellsPolygon(*g, {i}, {});
        ASSERT_EQ(poly.size(), 1u);
        EXPECT_NEAR(geo::area(poly), 15.0 * 15.0, 1e-6);
        for (const auto& corner : g->cellCorners(i)) {
            double nearest = 1e9;
            for (const auto& v : poly.front().outer)
                nearest = std::min(nearest, (v - corner).norm());
            EXPECT_NEAR(nearest, 0.0, 1e-6);
        }
    }
}

// Demo site, three mixed aircraft, several grid angles: connected subareas that tile the
// admissible area, and per-aircraft grids whose cells together cover all of it.
TEST(FleetOnGrid, DemoSitePartitionAndAircraftGridsCoverTheArea) {
    const auto site = test::demoSite();
    const auto fleet = demoFleet();
    std::vector<double> sizes;
    for (const auto& c : fleet)
        sizes.push_back(aircraftCellSize(c.footprint));
    const double areaM2 = geo::area(site.area);
    auto base = baseCellSize(sizes, areaM2);
    ASSERT_TRUE(base.ok());
    EXPECT_DOUBLE_EQ(*base, 24.0);
    auto shares = capabilityShares(fleet, areaM2);
    ASSERT_TRUE(shares.ok());
    for (double angle : {0.0, 15.0, 60.0}) {
        grid::GridOptions opt;
        opt.cellSize = *base;
        opt.angleDeg = angle;
        opt.safetyMarginM = 5.0;
        auto g = grid::Grid::build(site.area, site.noFly, opt);
        ASSERT_TRUE(g.ok()) << g.error().message;
        const grid::Grid& b = *g;
        auto p = partitionCells(b, *shares);
        ASSERT_TRUE(p.ok()) << p.error().message;
        EXPECT_EQ(p->disconnectedSubareas, 0) << "angle " << angle;
        for (std::size_t k = 0; k < fleet.size(); ++k) {
            EXPECT_TRUE(isConnected(b, p->cells[k])) << "angle " << angle << " aircraft " << k;
            EXPECT_LE(std::abs(static_cast<int>(p->cells[k].size()) - p->targets[k]), 1);
        }
        const auto subareas = subareaPolygons(b, *p, g->admissible());
        double sum = 0;
        for (const auto& s : subareas)
            sum += geo::area(s);
        EXPECT_NEAR(sum, geo::area(g->admissible()), 1e-3 * geo::area(g->admissible())) << "angle " << angle;

        std::vector<grid::GridOptions> opts;
        std::vector<std::string> names;
        for (std::size_t k = 0; k < fleet.size(); ++k) {
            grid::GridOptions o = opt;
            o.cellSize = sizes[k];
            opts.push_back(o);
            names.push_back(fleet[k].name);
        }
        auto grids = buildAircraftGrids(subareas, site.noFly, opts, names);
        ASSERT_TRUE(grids.ok()) << grids.error().message;
        // Every cell to visit is a square the aircraft photographs: together they cover the area.
        std::vector<plan::PhotoFootprint> squares;
        for (const auto& ag : *grids)
            for (int i = 0; i < ag.cellCount(); ++i)
                if (ag.needsVisit(i))
                    squares.push_back(plan::PhotoFootprint{ag.cellCenter(i), 90.0 - ag.angleDeg(), ag.cellSize(), ag.cellSize()});
        auto cov = plan::checkCoverage(g->admissible(), squares);
        ASSERT_TRUE(cov.ok());
        EXPECT_GE(cov->coveredFraction, 0.995) << "angle " << angle;
    }
}

TEST(FleetOnGrid, AircraftGridErrorsNameTheAircraft) {
    const auto site = test::demoSite();
    grid::GridOptions bad;
    bad.cellSize = -1;
    auto grids = buildAircraftGrids({{site.area}}, site.noFly, {bad}, {"Falcon 8 #1"});
    ASSERT_FALSE(grids.ok());
    EXPECT_EQ(grids.error().message.rfind("Falcon 8 #1: ", 0), 0u) << grids.error().message;
    auto empty = buildAircraftGrids({{}}, site.noFly, {grid::GridOptions{}}, {"Phantom"});
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().message, "Phantom received no part of the area.");
}

// Beyond the paper: balancing on the times the real stride planner gives (the facade's planRegion as
// the estimator, grid angle fixed) on concave sites with no-fly zones and 2 to 4 mixed aircraft.
// Planned times jump when a single cell moves, so the target makespan <= 1.10 x ideal is reached on
// most sites, not all (measured: 7 of 9, the others at 1.103 and 1.125, mean 1.048).
TEST(FleetOnGrid, BalanceWithTheStridePlannerWithinTenPercent) {
    auto frame = geo::LocalFrame::create({8.33, 49.01});
    ASSERT_TRUE(frame.ok());
    int within = 0;
    double sum = 0;
    for (unsigned seed = 1; seed <= 9; ++seed) {
        std::mt19937 rng(seed);
        const auto [area, noFly] = generatedSite(rng);
        const int n = 2 + static_cast<int>(seed % 3);
        const auto cfg = mixedConfigs(n, rng);
        std::vector<Capability> caps;
        std::vector<double> sizes;
        for (const auto& a : cfg) {
            auto fp = sensor::effectiveFootprint(a.camera, *a.altitudeM, a.overlap);
            ASSERT_TRUE(fp.ok());
            caps.push_back({a.name, *fp, mission::flightModel(a)});
            sizes.push_back(aircraftCellSize(*fp));
        }
        const double areaM2 = geo::area(area);
        grid::GridOptions go;
        go.cellSize = *baseCellSize(sizes, areaM2);
        go.safetyMarginM = 5;
        auto g = grid::Grid::build(area, noFly, go);
        ASSERT_TRUE(g.ok()) << g.error().message;
        const grid::Grid& b = *g;
        auto p = partitionCells(b, *capabilityShares(caps, areaM2));
        ASSERT_TRUE(p.ok()) << p.error().message;
        mission::PlannerOptions po;
        po.planner = mission::PlannerKind::Stride;
        po.gridAngleDeg = 0.0;
        po.safetyMarginM = 5;
        const geo::Vec2 home(-20, -20);
        auto estimate = [&](int k, const std::vector<int>& cells) -> Result<double> {
            auto ap = mission::planRegion(cellsPolygon(b, cells, g->admissible()), noFly,
                                          cfg[static_cast<std::size_t>(k)], po, home);
            if (!ap)
                return ap.error();
            return ap->metrics.estimatedTimeS;
        };
        auto rep = balanceByTime(b, *p, estimate);
        ASSERT_TRUE(rep.ok()) << rep.error().message;
        for (int k = 0; k < n; ++k)
            EXPECT_TRUE(isConnected(b, p->cells[static_cast<std::size_t>(k)])) << "seed " << seed;
        const double ratio = rep->makespan / rep->ideal;
        EXPECT_LE(ratio, 1.15) << "seed " << seed << ", " << n << " aircraft, " << rep->rounds << " rounds";
        within += ratio <= 1.10;
        sum += ratio;
    }
    EXPECT_GE(within, 7);
    EXPECT_LE(sum / 9, 1.06);
}

// The whole fleet chain on the demo site with the real planner and photo waypoints: partition,
// one plan per subarea, photos saved across aircraft, no-fly detours, transit from home, sorties.
// The independent checker then finds the admissible area covered and no margin breached.
TEST(FleetOnGrid, DemoSiteEndToEndCoveredAndSafe) {
    const auto site = test::demoSite();
    auto frame = geo::LocalFrame::create({8.33, 49.01});
    ASSERT_TRUE(frame.ok());
    std::mt19937 rng(11);
    const auto cfg = mixedConfigs(3, rng);
    std::vector<Capability> caps;
    std::vector<double> sizes;
    for (const auto& a : cfg) {
        auto fp = sensor::effectiveFootprint(a.camera, *a.altitudeM, a.overlap);
        ASSERT_TRUE(fp.ok());
        caps.push_back({a.name, *fp, mission::flightModel(a)});
        sizes.push_back(aircraftCellSize(*fp));
    }
    const double areaM2 = geo::area(site.area);
    const double margin = 5.0;
    grid::GridOptions go;
    go.cellSize = *baseCellSize(sizes, areaM2);
    go.safetyMarginM = margin;
    auto g = grid::Grid::build(site.area, site.noFly, go);
    ASSERT_TRUE(g.ok());
    const grid::Grid& b = *g;
    auto p = partitionCells(b, *capabilityShares(caps, areaM2));
    ASSERT_TRUE(p.ok());
    const auto subareas = subareaPolygons(b, *p, g->admissible());
    mission::PlannerOptions po;
    po.gridAngleDeg = 0.0;
    po.safetyMarginM = margin;
    std::vector<AircraftPhotos> photos;
    for (std::size_t k = 0; k < cfg.size(); ++k) {
        auto ap = mission::planRegion(subareas[k], site.noFly, cfg[k], po, site.home);
        ASSERT_TRUE(ap.ok()) << ap.error().message;
        AircraftPhotos a;
        a.waypoints = ap->localWaypoints;
        a.effectiveAcrossM = ap->footprint.acrossM;
        a.effectiveAlongM = ap->footprint.alongM;
        a.realAcrossM = ap->footprint.real.longSideM;
        a.realAlongM = ap->footprint.real.shortSideM;
        photos.push_back(std::move(a));
    }
    auto saved = dropDuplicatePhotos(photos);
    ASSERT_TRUE(saved.ok()) << saved.error().message;
    EXPECT_GT(saved->totalSaved, 0);

    const route::SafePathFinder finder(route::NoFlyField(site.noFly, margin));
    std::vector<plan::PhotoFootprint> footprints;
    std::vector<std::vector<geo::Vec2>> paths;
    for (std::size_t k = 0; k < photos.size(); ++k) {
        auto safe = route::enforceNoFly(photos[k].waypoints, finder);
        ASSERT_TRUE(safe.ok()) << safe.error().message;
        auto flown = route::withTransit(*safe, site.home, finder);
        ASSERT_TRUE(flown.ok()) << flown.error().message;
        std::vector<geo::Vec2> path{site.home};
        for (const auto& w : *flown) {
            path.push_back(w.pos);
            if (w.kind == route::WaypointKind::Photo)
                footprints.push_back({w.pos, w.headingDeg, photos[k].realAcrossM, photos[k].realAlongM});
        }
        path.push_back(site.home);
        paths.push_back(path);
        auto sorties = route::splitIntoSorties(*safe, site.home, finder,
                                               mission::flightModel(cfg[k]),
                                               route::SortieOptions{3.0, 0.2}, cfg[k].name);
        ASSERT_TRUE(sorties.ok()) << sorties.error().message;
        EXPECT_GE(sorties->batteries(), 1);
        for (const auto& s : sorties->sorties)
            EXPECT_LE(s.timeS, sorties->budgetS + 1e-9);
    }
    auto cov = plan::checkCoverage(g->admissible(), footprints);
    ASSERT_TRUE(cov.ok());
    EXPECT_GE(cov->coveredFraction, 0.995);
    EXPECT_EQ(plan::countNoFlyViolations(paths, site.noFly, margin).total(), 0);
}

// The one-call split the facade uses: shares, base grid, partition and balance on the demo site.
TEST(SplitArea, DemoSiteWithThePlannerAsEstimator) {
    const auto site = test::demoSite();
    auto frame = geo::LocalFrame::create({8.33, 49.01});
    ASSERT_TRUE(frame.ok());
    std::mt19937 rng(5);
    const auto cfg = mixedConfigs(3, rng);
    std::vector<Capability> caps;
    for (const auto& a : cfg)
        caps.push_back({a.name, *sensor::effectiveFootprint(a.camera, *a.altitudeM, a.overlap), mission::flightModel(a)});
    mission::PlannerOptions po;
    po.gridAngleDeg = 0.0;
    po.safetyMarginM = 5;
    AreaSplitOptions opt;
    opt.safetyMarginM = 5;
    auto split = splitArea(site.area, site.noFly, caps, opt,
                           [&](int k, const geo::MultiPolygon& region) -> Result<double> {
                               auto ap = mission::planRegion(region, site.noFly,
                                                             cfg[static_cast<std::size_t>(k)], po,
                                                             site.home);
                               if (!ap)
                                   return ap.error();
                               return ap->metrics.estimatedTimeS;
                           });
    ASSERT_TRUE(split.ok()) << split.error().message;
    ASSERT_EQ(split->subareas.size(), 3u);
    ASSERT_TRUE(split->balance.has_value());
    EXPECT_LE(split->balance->makespan, 1.10 * split->balance->ideal);
    double sum = 0;
    for (const auto& s : split->subareas)
        sum += geo::area(s);
    const double admissible = geo::area(geo::difference(site.area, geo::MultiPolygon(site.noFly.begin(), site.noFly.end())));
    EXPECT_NEAR(sum, admissible, 1e-3 * admissible);
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_TRUE(isConnected(split->base, split->partition.cells[k]));
    // Without an estimator: the paper's cell-count split only.
    auto plain = splitArea(site.area, site.noFly, caps, opt);
    ASSERT_TRUE(plain.ok());
    EXPECT_FALSE(plain->balance.has_value());
    // Too many aircraft for a tiny area.
    const geo::Polygon tiny{{geo::Vec2(0, 0), geo::Vec2(10, 0), geo::Vec2(10, 10), geo::Vec2(0, 10)}, {}};
    auto none = splitArea(tiny, {}, caps, opt);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().message,
              "The area has only 1 cell to photograph, fewer than the 3 aircraft: use fewer aircraft or a smaller "
              "footprint.");
}
