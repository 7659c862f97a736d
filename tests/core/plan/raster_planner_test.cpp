#include "core/plan/raster_planner.h"

#include "core/plan/metrics.h"
#include "tests/core/plan/plan_test_util.h"

#include <gtest/gtest.h>

namespace pf::plan {
namespace {

TEST(RasterPlanner, PicksRowsForAWideArea) {
    std::vector<std::uint8_t> mask(10 * 3, 1);
    const grid::Grid g = grid::Grid::fromMask(10, 3, mask, 1.0);
    auto p = planRaster(g, {});
    ASSERT_TRUE(p.ok());
    test::expectValidCoverage(g, *p, false, 0, "wide");
    const PathMetrics m = computeMetrics(g, *p);
    EXPECT_EQ(m.turns, 4); // three rows
    EXPECT_EQ(m.jumps, 0);
}

TEST(RasterPlanner, PicksColumnsForATallArea) {
    std::vector<std::uint8_t> mask(3 * 10, 1);
    const grid::Grid g = grid::Grid::fromMask(3, 10, mask, 1.0);
    auto p = planRaster(g, {});
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(computeMetrics(g, *p).turns, 4);
    // Column by column: the first moves go north.
    EXPECT_EQ(p->cells[1], g.index(0, 1));
}

TEST(RasterPlanner, CountsJumpsOverHoles) {
    // The hole splits rows 1 and 2; each of those rows jumps once over it, in both sweep directions.
    const grid::Grid g = test::drawGrid({
        ".....",
        ".#.#.",
        ".#.#.",
        ".....",
    });
    const CellPath rows = rasterSweep(g, 0, false);
    test::expectValidCoverage(g, rows, false, 100, "rows");
    EXPECT_EQ(rows.jumps, 4);
    const CellPath cols = rasterSweep(g, 0, true);
    test::expectValidCoverage(g, cols, false, 100, "columns");
    auto best = planRaster(g, {});
    ASSERT_TRUE(best.ok());
    EXPECT_EQ(best->jumps, computeMetrics(g, *best).jumps);
}

TEST(RasterPlanner, StartsAtTheStartCell) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const grid::Grid g = test::randomShape(test::Shape::Holes, seed);
        for (int start = 0; start < g.cellCount(); start += 53) {
            if (!g.onContour(start))
                continue;
            CoverageRequest req;
            req.start = start;
            auto p = planRaster(g, req);
            ASSERT_TRUE(p.ok());
            EXPECT_EQ(p->cells.front(), start);
            test::expectValidCoverage(g, *p, false, g.cellCount(), "raster seed " + std::to_string(seed));
        }
    }
}

} // namespace
} // namespace pf::plan
