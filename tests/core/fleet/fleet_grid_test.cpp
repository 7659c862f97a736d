// The fleet stages on real grids of the demo site: base grid, partition, per-aircraft grids.
#include "core/fleet/aircraft_grids.h"
#include "core/fleet/capability.h"
#include "core/fleet/partition.h"
#include "core/geo/polygon_ops.h"
#include "core/grid/grid.h"
#include "core/plan/coverage_check.h"

#include "tests/core/fleet/demo_site.h"

#include <gtest/gtest.h>

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

} // namespace

TEST(FleetOnGrid, BaseGridCellsMatchTheGridsOwnCorners) {
    const auto site = test::demoSite();
    grid::GridOptions opt;
    opt.cellSize = 15.0;
    opt.angleDeg = 27.0;
    auto g = grid::Grid::build(site.area, site.noFly, opt);
    ASSERT_TRUE(g.ok()) << g.error().message;
    const auto b = BaseGrid::fromGrid(*g);
    for (int i = 0; i < g->cellCount(); i += 7) {
        const auto mine = b.cellSquare(i);
        const auto theirs = g->cellCorners(i);
        ASSERT_EQ(theirs.size(), 4u);
        for (int k = 0; k < 4; ++k)
            EXPECT_NEAR((mine[static_cast<std::size_t>(k)] - theirs[static_cast<std::size_t>(k)]).norm(), 0.0, 1e-6);
        EXPECT_NEAR((b.cellCenter(i) - g->cellCenter(i)).norm(), 0.0, 1e-6);
        EXPECT_EQ(b.active[static_cast<std::size_t>(i)] != 0, g->needsVisit(i));
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
        const auto b = BaseGrid::fromGrid(*g);
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
    EXPECT_EQ(grids.error().message.rfind("Aircraft \"Falcon 8 #1\": ", 0), 0u) << grids.error().message;
    auto empty = buildAircraftGrids({{}}, site.noFly, {grid::GridOptions{}}, {"Phantom"});
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().message, "Aircraft \"Phantom\" received no part of the area.");
}
