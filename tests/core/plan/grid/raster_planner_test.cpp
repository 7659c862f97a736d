#include "core/plan/grid/raster_planner.h"

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

// The baseline walk (rasterWalk): jumps only out of dead ends, i.e. when every allowed neighbour of
// the current cell has been photographed; every other step is an allowed 4-move.
void expectJumpsOnlyAtDeadEnds(const grid::Grid& g, const CellPath& p, const std::string& what) {
    std::vector<std::uint8_t> done(static_cast<std::size_t>(g.cellCount()), 0);
    for (std::size_t i = 0; i < p.cells.size(); ++i) {
        if (i > 0 && !isAllowedStep(g, p.cells[i - 1], p.cells[i], false)) {
            const int a = p.cells[i - 1];
            for (int d = 0; d < 4; ++d) {
                const auto dir = static_cast<grid::Dir>(d);
                if (g.canMove(a, dir)) {
                    EXPECT_TRUE(done[g.neighbour(a, dir)]) << what << ": jump from (" << g.col(a) << ", " << g.row(a)
                                                           << ") while a neighbour was free";
                }
            }
        }
        done[p.cells[i]] = 1;
    }
}

TEST(RasterPlanner, WalkJumpsOnlyOutOfDeadEnds) {
    for (auto shape : {test::Shape::Holes, test::Shape::Concave, test::Shape::Teeth, test::Shape::LShape}) {
        for (unsigned seed = 1; seed <= 15; ++seed) {
            const grid::Grid g = test::randomShape(shape, seed);
            for (int start = 0; start < g.cellCount(); start += 37) {
                if (!g.needsVisit(start))
                    continue;
                for (bool byColumns : {false, true}) {
                    const std::string what = std::string(test::shapeName(shape)) + " seed " + std::to_string(seed) +
                                             (byColumns ? " columns" : " rows") + " from " + std::to_string(start);
                    const CellPath p = rasterWalk(g, start, byColumns);
                    ASSERT_FALSE(p.cells.empty());
                    EXPECT_EQ(p.cells.front(), start) << what;
                    test::expectValidCoverage(g, p, false, g.cellCount(), what);
                    expectJumpsOnlyAtDeadEnds(g, p, what);
                }
            }
        }
    }
}

TEST(RasterPlanner, WalkDoesNotFlyAcrossGapsWhileANeighbourIsFree) {
    // Row walk from the bottom-left corner: row 0 east, up the east side (the holes end rows 1 and 2
    // there), row 3 west, down the west side, then one jump to the middle column, which no free
    // neighbour leads to. The line sweep (rasterSweep) instead jumps over each hole (4 jumps).
    const grid::Grid g = test::drawGrid({
        ".....",
        ".#.#.",
        ".#.#.",
        ".....",
    });
    const CellPath p = rasterWalk(g, 0, false);
    test::expectValidCoverage(g, p, false, 1, "rows");
    EXPECT_EQ(p.jumps, 1);
    const std::vector<int> expected = {g.index(0, 0), g.index(1, 0), g.index(2, 0), g.index(3, 0), g.index(4, 0),
                                       g.index(4, 1), g.index(4, 2), g.index(4, 3), g.index(3, 3), g.index(2, 3),
                                       g.index(1, 3), g.index(0, 3), g.index(0, 2), g.index(0, 1), g.index(2, 1),
                                       g.index(2, 2)};
    EXPECT_EQ(p.cells, expected);
}

TEST(RasterPlanner, WalkIsABoustrophedonOnARectangle) {
    std::vector<std::uint8_t> mask(7 * 5, 1);
    const grid::Grid g = grid::Grid::fromMask(7, 5, mask, 1.0);
    for (int start : {g.index(0, 0), g.index(6, 4), g.index(3, 0)}) {
        const CellPath rows = rasterWalk(g, start, false);
        test::expectValidCoverage(g, rows, false, 2, "rectangle");
        if (start != g.index(3, 0)) {
            // From a corner: five rows, two turns between each pair, no jump.
            EXPECT_EQ(rows.jumps, 0);
            EXPECT_EQ(computeMetrics(g, rows).turns, 8);
        }
    }
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
