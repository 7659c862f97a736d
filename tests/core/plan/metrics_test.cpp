#include "core/plan/metrics.h"

#include "tests/core/plan/plan_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf::plan {
namespace {

TEST(Metrics, BoustrophedonByHand) {
    std::vector<std::uint8_t> mask(9, 1);
    const grid::Grid g = grid::Grid::fromMask(3, 3, mask, 10.0);
    CellPath p;
    // Row 0 east, row 1 west, row 2 east.
    for (int c : {g.index(0, 0), g.index(1, 0), g.index(2, 0), g.index(2, 1), g.index(1, 1), g.index(0, 1),
                  g.index(0, 2), g.index(1, 2), g.index(2, 2)}) {
        p.cells.push_back(c);
        p.revisit.push_back(false);
    }
    MetricsOptions opt;
    opt.time.speedMps = 10;
    opt.time.turnRateDegS = 90;
    opt.time.accelerationMps2 = 2.5;
    const PathMetrics m = computeMetrics(g, p, opt);
    EXPECT_EQ(m.visitable, 9);
    EXPECT_EQ(m.cells, 9);
    EXPECT_TRUE(m.complete());
    EXPECT_DOUBLE_EQ(m.pathLengthM, 80.0);
    EXPECT_NEAR(m.distanceM, 80.0 + std::sqrt(800.0), 1e-9); // back from (2,2) to (0,0)
    EXPECT_EQ(m.turns, 4);
    EXPECT_NEAR(m.turnAngleDeg, 360.0, 1e-9);
    EXPECT_EQ(m.jumps, 0);
    EXPECT_EQ(m.revisits, 0);
    // Straight legs, turns, and a stop of V / a = 4 s at each of the 4 turns and once for the start and
    // the end at rest.
    EXPECT_NEAR(m.estimatedTimeS, 80.0 / 10 + 360.0 / 90 + 5 * 4.0, 1e-9);
    // Three lanes either way, each lane change a connector with two turns: four at least, as flown here.
    EXPECT_EQ(m.turnLowerBound, 4);
    EXPECT_DOUBLE_EQ(m.turnRatio, 1.0);
}

TEST(Metrics, UTurnJumpAndRevisitByHand) {
    std::vector<std::uint8_t> mask(9, 1);
    const grid::Grid g = grid::Grid::fromMask(3, 3, mask, 10.0);
    CellPath p;
    p.cells = {g.index(0, 0), g.index(1, 0), g.index(0, 0), g.index(2, 1)};
    p.revisit = {false, false, true, false};
    MetricsOptions opt;
    opt.turnLowerBound = false;
    const PathMetrics m = computeMetrics(g, p, opt);
    EXPECT_EQ(m.cells, 3);
    EXPECT_FALSE(m.complete());
    EXPECT_EQ(m.revisits, 1);
    EXPECT_EQ(m.jumps, 1); // (0,0) -> (2,1) is not a move
    EXPECT_NEAR(m.pathLengthM, 10 + 10 + std::sqrt(500.0), 1e-9);
    // East then West: a U-turn (180 deg); West then (2, 1): atan2(1, -2).
    EXPECT_EQ(m.turns, 2);
    EXPECT_NEAR(m.turnAngleDeg, 180.0 + std::atan2(1.0, -2.0) * 180.0 / M_PI, 1e-9);
    EXPECT_EQ(m.turnLowerBound, -1);
}

TEST(Metrics, DiagonalStepsAreMovesOnlyWhenAsked) {
    std::vector<std::uint8_t> mask(4, 1);
    const grid::Grid g = grid::Grid::fromMask(2, 2, mask, 1.0);
    CellPath p;
    p.cells = {g.index(0, 0), g.index(1, 1), g.index(1, 0), g.index(0, 1)};
    p.revisit = {false, false, false, false};
    MetricsOptions opt;
    opt.turnLowerBound = false;
    EXPECT_EQ(computeMetrics(g, p, opt).jumps, 2);
    opt.diagonalSteps = true;
    const PathMetrics m = computeMetrics(g, p, opt);
    EXPECT_EQ(m.jumps, 0);
    // NE, then S (135 deg), then NW (135 deg).
    EXPECT_EQ(m.turns, 2);
    EXPECT_NEAR(m.turnAngleDeg, 270.0, 1e-9);
}

TEST(Metrics, MinimumStraightRuns) {
    // (0,0), (1,1) and (2,2) share no run: three at least, and three suffice.
    EXPECT_EQ(minStraightRuns(test::drawGrid({"#..", "#.#", "..."})), 3);
    EXPECT_EQ(minStraightRuns(test::drawGrid({"..", "..", ".."})), 2);
    EXPECT_EQ(minStraightRuns(test::drawGrid({".##", ".##", "..."})), 2); // an L
    // A plus: its row and its column.
    EXPECT_EQ(minStraightRuns(test::drawGrid({"#.#", "...", "#.#"})), 2);
    // A comb: the spine row plus one column per tooth of length >= 2 (single cells ride on the spine).
    EXPECT_EQ(minStraightRuns(test::drawGrid({".#.#.", ".#.#.", "....."})), 4);
    EXPECT_EQ(minStraightRuns(test::drawGrid({"##", "##"})), 0);
}

TEST(Metrics, BoundHoldsForPlannedPaths) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const grid::Grid g = test::randomShape(test::Shape::Concave, seed);
        CellPath p;
        for (int i = 0; i < g.cellCount(); ++i)
            if (g.needsVisit(i)) {
                p.cells.push_back(i);
                p.revisit.push_back(false);
            }
        const PathMetrics m = computeMetrics(g, p);
        EXPECT_GE(m.turnLowerBound, 0);
        EXPECT_EQ(m.cells, g.visitCount());
    }
}

} // namespace
} // namespace pf::plan
