#include "core/plan/grid/stride_planner.h"

#include "core/plan/metrics.h"
#include "tests/core/plan/plan_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace pf::plan {
namespace {

using grid::Dir;
using test::drawGrid;

// The paper's figure 2, rebuilt: c0 ('A') sits on the bottom edge of a strip. To the west the edge
// continues for three cells (stride A, 4 cells, ends at the area limit); northwards the second cell has
// free cells on both sides (stride B, 2 cells, L(cn) = 0); eastwards the edge changes side after two
// cells (stride C, 3 cells, the limit of cn is above while c0's is below).
const std::vector<std::string> kFigure2 = {
    "########", //
    "........", // row 3
    "......#.", // row 2
    "...A....", // row 1
    "######..", // row 0
};

TEST(StrideRules, PaperFigure2) {
    const grid::Grid g = drawGrid(kFigure2);
    const int c0 = test::cellOf(kFigure2, 'A');
    std::vector<std::uint8_t> visited(static_cast<std::size_t>(g.cellCount()), 0);
    visited[c0] = 1;

    const Stride a = buildStride(g, visited, c0, Dir::West);
    EXPECT_EQ(a.length(), 4);
    EXPECT_EQ(a.stop, StrideStop::AreaLimit);
    EXPECT_EQ(a.cells, (std::vector<int>{c0 - 1, c0 - 2, c0 - 3}));

    const Stride b = buildStride(g, visited, c0, Dir::North);
    EXPECT_EQ(b.length(), 2);
    EXPECT_EQ(b.stop, StrideStop::NoLimit);

    const Stride c = buildStride(g, visited, c0, Dir::East);
    EXPECT_EQ(c.length(), 3);
    EXPECT_EQ(c.stop, StrideStop::LimitOppositeSide);
    // L(c0) = L(cn) = 1 on opposite sides.
    EXPECT_EQ(strideLimits(g, visited, c0, Dir::East), kRightLimit);
    EXPECT_EQ(strideLimits(g, visited, c0 + 3, Dir::East), kLeftLimit);

    const Stride d = buildStride(g, visited, c0, Dir::South);
    EXPECT_EQ(d.length(), 0);
    EXPECT_EQ(d.stop, StrideStop::None);

    // The planner takes the longest: stride A first.
    CoverageRequest req;
    req.start = c0;
    auto path = planStride(g, req);
    ASSERT_TRUE(path.ok());
    ASSERT_GE(path->cells.size(), 4u);
    EXPECT_EQ(std::vector<int>(path->cells.begin(), path->cells.begin() + 4),
              (std::vector<int>{c0, c0 - 1, c0 - 2, c0 - 3}));
}

TEST(StrideRules, VisitedCellsCountAsLimits) {
    // A corridor between a visited row and the area edge: L = 2 all along, so the stride runs to its end.
    const std::vector<std::string> pic = {
        "######",
        "A.....",
        "......",
    };
    const grid::Grid g = drawGrid(pic);
    std::vector<std::uint8_t> visited(static_cast<std::size_t>(g.cellCount()), 0);
    for (int c = 0; c < 6; ++c)
        visited[g.index(c, 0)] = 1;
    const int c0 = test::cellOf(pic, 'A');
    visited[c0] = 1;
    const Stride s = buildStride(g, visited, c0, Dir::East);
    EXPECT_EQ(s.length(), 6);
    EXPECT_EQ(s.stop, StrideStop::AreaLimit);
    EXPECT_EQ(strideLimits(g, visited, c0 + 2, Dir::East), kLeftLimit | kRightLimit);
}

TEST(StrideRules, LimitCountChangeStopsTheStride) {
    // c0 has one limit (the south edge); the second cell east has two (a notch above it): rule (2).
    const std::vector<std::string> pic = {
        "....",
        "..#.",
        "A...",
    };
    const grid::Grid g = drawGrid(pic);
    std::vector<std::uint8_t> visited(static_cast<std::size_t>(g.cellCount()), 0);
    const int c0 = test::cellOf(pic, 'A');
    visited[c0] = 1;
    const Stride e = buildStride(g, visited, c0, Dir::East);
    EXPECT_EQ(e.length(), 2);
    EXPECT_EQ(e.stop, StrideStop::LimitCountDiffers);
    // Northwards along the west edge: one limit (left) on every cell, up to the grid's edge.
    const Stride n = buildStride(g, visited, c0, Dir::North);
    EXPECT_EQ(n.length(), 3);
    EXPECT_EQ(n.stop, StrideStop::AreaLimit);
}

TEST(StrideRules, TwoLimitsAlwaysAdmitTheNextCell) {
    // With the bottom row visited, (1, 1) is boxed in by the notch above and the visited cell below:
    // L(cl) = 2, so (2, 1) is added although its limits (visited below only) differ from c0's.
    const std::vector<std::string> pic = {
        ".#..",
        "A...",
        "....",
    };
    const grid::Grid g = drawGrid(pic);
    std::vector<std::uint8_t> visited(static_cast<std::size_t>(g.cellCount()), 0);
    for (int c = 0; c < 4; ++c)
        visited[g.index(c, 0)] = 1;
    const int c0 = test::cellOf(pic, 'A');
    visited[c0] = 1;
    // c0 = (0, 1): one limit, below (visited). (1, 1): two limits. (2, 1): one (below), admitted because
    // L((1, 1)) = 2. (3, 1): one below, the same side as c0's. Then the grid's edge.
    EXPECT_EQ(strideLimits(g, visited, g.index(1, 1), Dir::East), kLeftLimit | kRightLimit);
    const Stride s = buildStride(g, visited, c0, Dir::East);
    EXPECT_EQ(s.length(), 4);
    EXPECT_EQ(s.stop, StrideStop::AreaLimit);
    // Without the visited row, L(c0) = 0 and (2, 1) has no limit: rule (1) stops after the neighbour.
    std::fill(visited.begin(), visited.end(), 0);
    visited[c0] = 1;
    const Stride s2 = buildStride(g, visited, c0, Dir::East);
    EXPECT_EQ(s2.length(), 2);
    EXPECT_EQ(s2.stop, StrideStop::NoLimit);
}

TEST(StrideRules, NotVisitableNeighboursAreLimits) {
    const std::vector<std::string> pic = {
        ".#.",
        "A..",
    };
    const grid::Grid g = drawGrid(pic);
    std::vector<std::uint8_t> visited(static_cast<std::size_t>(g.cellCount()), 0);
    // (1, 0): above is not visitable, below is past the grid's edge.
    EXPECT_EQ(strideLimits(g, visited, g.index(1, 0), Dir::East), kLeftLimit | kRightLimit);
    EXPECT_EQ(strideLimits(g, visited, g.index(1, 0), Dir::West), kLeftLimit | kRightLimit);
    // (2, 0) going north: the grid's east edge is on its right.
    EXPECT_EQ(strideLimits(g, visited, g.index(2, 0), Dir::North), kRightLimit);
}

TEST(StrideRules, DisallowedMovesAreLimits) {
    // A thin no-fly strip on the border between the first two cells of the bottom row: both cells stay
    // visitable (their centres are clear) but the move between them crosses the strip.
    geo::Polygon area{{{0, 0}, {40, 0}, {40, 20}, {0, 20}}, {}};
    geo::Polygon strip{{{9.95, -1}, {10.05, -1}, {10.05, 9}, {9.95, 9}}, {}};
    grid::GridOptions opt;
    opt.cellSize = 10;
    auto g = grid::Grid::build(area, {strip}, opt);
    ASSERT_TRUE(g.ok()) << g.error().message;
    ASSERT_EQ(g->cols(), 4);
    ASSERT_EQ(g->rows(), 2);
    const int a = g->index(0, 0), b = g->index(1, 0);
    ASSERT_TRUE(g->needsVisit(a));
    ASSERT_TRUE(g->needsVisit(b));
    ASSERT_FALSE(g->canMove(a, Dir::East));
    std::vector<std::uint8_t> visited(static_cast<std::size_t>(g->cellCount()), 0);
    // Going north from a: the right side (towards b) is a limit, the left side is the grid's edge.
    EXPECT_EQ(strideLimits(*g, visited, a, Dir::North), kLeftLimit | kRightLimit);
    // Coverage never crosses the strip.
    auto path = planStride(*g, {});
    ASSERT_TRUE(path.ok());
    test::expectValidCoverage(*g, *path, false, 0, "strip");
    for (std::size_t i = 1; i < path->cells.size(); ++i) {
        const int p = path->cells[i - 1], q = path->cells[i];
        EXPECT_FALSE((p == a && q == b) || (p == b && q == a));
    }
}

TEST(StridePlanner, CoversRectangleWithFewTurns) {
    std::vector<std::uint8_t> mask(20 * 10, 1);
    const grid::Grid g = grid::Grid::fromMask(20, 10, mask, 10.0);
    auto path = planStride(g, {});
    ASSERT_TRUE(path.ok());
    test::expectValidCoverage(g, *path, false, 0, "rectangle");
    const PathMetrics m = computeMetrics(g, *path);
    EXPECT_EQ(m.revisits, 0);
    EXPECT_EQ(m.cells, 200);
    // The lower bound is 9 turns (10 rows); a spiral or boustrophedon needs at most 2 per row.
    EXPECT_LE(m.turns, 19);
}

// The invariants of a stride path: complete coverage with only allowed moves, no jump inside a connected
// area, nothing left for the clean-up to remove, and the partition rule (smallest part first) replayed
// stride by stride from the trace.
void expectStrideInvariants(const grid::Grid& g, const CellPath& path, const StrideTrace& trace, int parts,
                            const std::string& what) {
    test::expectValidCoverage(g, path, false, parts - 1, what);
    if (parts == 1) {
        EXPECT_EQ(path.jumps, 0) << what;
    }

    // Clean-up left nothing removable: no run of transits joins two equal or adjacent cells.
    const auto& c = path.cells;
    for (std::size_t i = 0; i + 2 < c.size(); ++i) {
        for (std::size_t j = i + 2; j < c.size(); ++j) {
            if (!path.revisit[j - 1])
                break;
            const bool joined = c[i] == c[j] || isAllowedStep(g, c[i], c[j], false);
            EXPECT_FALSE(joined) << what << ": transits " << i + 1 << ".." << j - 1
                                 << " could be removed";
        }
    }

    // Partition rule: replay the photographed cells stride by stride; whenever a stride splits
    // a free part, the next cell photographed lies in a smallest piece of it.
    std::vector<int> order;
    for (std::size_t i = 0; i < c.size(); ++i)
        if (!path.revisit[i])
            order.push_back(c[i]);
    std::vector<std::uint8_t> visited(static_cast<std::size_t>(g.cellCount()), 0);
    std::vector<int> prevSizes, curSizes;
    std::vector<int> prevComp = test::freeComponents(g, visited, &prevSizes);
    std::size_t done = 0;
    int splits = 0;
    for (int end : trace.segmentEnds) {
        for (; done < static_cast<std::size_t>(end); ++done)
            visited[order[done]] = 1;
        std::vector<int> comp = test::freeComponents(g, visited, &curSizes);
        if (done < order.size()) {
            // Pieces per previous component.
            std::vector<std::set<int>> pieces(prevSizes.size());
            for (int i = 0; i < g.cellCount(); ++i)
                if (comp[i] >= 0)
                    pieces[prevComp[i]].insert(comp[i]);
            for (const auto& ps : pieces) {
                if (ps.size() < 2)
                    continue;
                ++splits;
                int smallest = g.cellCount();
                for (int p : ps)
                    smallest = std::min(smallest, curSizes[p]);
                const int next = comp[order[done]];
                EXPECT_TRUE(ps.count(next) && curSizes[next] == smallest)
                    << what << ": after " << done << " cells a part was split into " << ps.size()
                    << " pieces, but the next cell is in a piece of "
                    << (next >= 0 ? curSizes[next] : -1) << " cells instead of " << smallest;
            }
        }
        prevComp = std::move(comp);
        prevSizes = curSizes;
    }
    EXPECT_EQ(static_cast<int>(trace.partitions.size()), splits) << what;
}

class StrideInvariants : public ::testing::TestWithParam<test::Shape> {};

TEST_P(StrideInvariants, ManySeededShapes) {
    for (unsigned seed = 1; seed <= 40; ++seed) {
        const grid::Grid g = test::randomShape(GetParam(), seed);
        if (g.visitCount() == 0)
            continue;
        const std::string what = std::string(test::shapeName(GetParam())) + " seed " + std::to_string(seed);
        // Start from several contour cells.
        std::vector<int> starts;
        for (int i = 0; i < g.cellCount() && starts.size() < 4; i += 37)
            if (g.onContour(i))
                starts.push_back(i);
        starts.push_back(-1);
        // Each connected part needs at most one jump to reach it.
        std::vector<int> sizes;
        test::freeComponents(g, std::vector<std::uint8_t>(static_cast<std::size_t>(g.cellCount()), 0), &sizes);
        const int parts = static_cast<int>(sizes.size());
        for (int start : starts) {
            CoverageRequest req;
            req.start = start;
            StrideTrace trace;
            auto path = planStride(g, req, &trace);
            ASSERT_TRUE(path.ok()) << what;
            expectStrideInvariants(g, *path, trace, parts, what);
            // Every variant on its own keeps the same rules (the best one is kept above).
            if (seed > 12)
                continue;
            const PathMetrics best = computeMetrics(g, *path);
            const auto variants = strideVariants(g, *resolveStart(g, req));
            for (std::size_t v = 0; v < variants.size(); ++v) {
                StrideTrace vt;
                auto vp = planStrideVariant(g, req, variants[v], &vt);
                ASSERT_TRUE(vp.ok()) << what;
                const std::string vwhat = what + " start " + std::to_string(start) + " variant " + std::to_string(v);
                expectStrideInvariants(g, *vp, vt, parts, vwhat);
                EXPECT_LE(best.turns, computeMetrics(g, *vp).turns) << vwhat;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, StrideInvariants,
                         ::testing::Values(test::Shape::Holes, test::Shape::Concave, test::Shape::Teeth,
                                           test::Shape::LShape),
                         [](const auto& info) { return std::string(test::shapeName(info.param)) == "L"
                                                           ? std::string("LShape")
                                                           : std::string(test::shapeName(info.param)); });

TEST(StridePlanner, SmallestPartFirst) {
    // Starting at 'S' going east along the bottom, the first stride reaches the neck; the cells
    // above split into a small pocket (west, 2 cells) and a large room (east). The pocket comes first.
    const std::vector<std::string> pic = {
        "##......",
        "..#.....",
        "S.......",
    };
    const grid::Grid g = drawGrid(pic);
    CoverageRequest req;
    req.start = test::cellOf(pic, 'S');
    StrideTrace trace;
    auto path = planStride(g, req, &trace);
    ASSERT_TRUE(path.ok());
    test::expectValidCoverage(g, *path, false, 0, "pocket");
    ASSERT_FALSE(trace.partitions.empty());
    EXPECT_EQ(trace.partitions.front().chosenSize, 2);
}

TEST(StridePlanner, DeadEndUsesShortestSafePath) {
    // Two rooms joined by a one-cell corridor: coverage needs transits back through visited cells, and
    // all of them are allowed moves.
    const std::vector<std::string> pic = {
        "...#...",
        "...#...",
        ".......",
        "...#...",
    };
    const grid::Grid g = drawGrid(pic);
    for (int start = 0; start < g.cellCount(); ++start) {
        if (!g.needsVisit(start))
            continue;
        CoverageRequest req;
        req.start = start;
        auto path = planStride(g, req);
        ASSERT_TRUE(path.ok());
        test::expectValidCoverage(g, *path, false, 0, "rooms from " + std::to_string(start));
    }
}

TEST(StridePlanner, TakeoffAndLandingTransits) {
    std::vector<std::uint8_t> mask(8 * 6, 1);
    const grid::Grid g = grid::Grid::fromMask(8, 6, mask);
    CoverageRequest req;
    req.takeoff = g.index(7, 5);
    req.start = g.index(0, 0);
    req.landing = g.index(7, 5);
    auto path = planStride(g, req);
    ASSERT_TRUE(path.ok());
    test::expectValidCoverage(g, *path, false, 0, "take-off");
    EXPECT_EQ(path->cells.front(), req.takeoff);
    EXPECT_EQ(path->cells.back(), req.landing);
    // The take-off cell is the corner where lanes begin best: the variants fly no way to the start and
    // back but photograph from the take-off cell on.
    EXPECT_FALSE(path->revisit.front());
    // With the paper's rules the first photographed cell is the start.
    auto paper = planStrideVariant(g, req, StrideVariant{});
    ASSERT_TRUE(paper.ok());
    test::expectValidCoverage(g, *paper, false, 0, "take-off, paper rules");
    EXPECT_EQ(paper->cells.front(), req.takeoff);
    EXPECT_EQ(paper->cells.back(), req.landing);
    const auto first = std::find(paper->revisit.begin(), paper->revisit.end(), false) - paper->revisit.begin();
    EXPECT_EQ(paper->cells[first], req.start);
}

TEST(StridePlanner, CleanUpRemovesTransitsBetweenAdjacentCells) {
    const grid::Grid g = drawGrid({"....", "...."});
    // Cells 0 1 2 3 on the bottom row, 4 5 6 7 above them.
    CellPath p;
    p.cells = {0, 1, 2, 1, 0, 4, 5, 6, 7, 3};
    p.revisit = {false, false, false, true, true, false, false, false, false, false};
    cleanUpRevisits(g, p);
    // 2 -> (1, 0) -> 4: neither 2 and 0, nor 2 and 4, nor 1 and 4 are adjacent: nothing to remove.
    EXPECT_EQ(p.cells, (std::vector<int>{0, 1, 2, 1, 0, 4, 5, 6, 7, 3}));

    CellPath q;
    q.cells = {0, 1, 2, 6, 2, 1, 5, 4};
    q.revisit = {false, false, false, false, true, true, false, false};
    // 6 -> (2, 1) -> 5: 6 and 5 are adjacent: both transits go.
    cleanUpRevisits(g, q);
    EXPECT_EQ(q.cells, (std::vector<int>{0, 1, 2, 6, 5, 4}));

    CellPath r;
    r.cells = {0, 1, 2, 1, 2, 3};
    r.revisit = {false, false, false, true, true, false};
    // 2 -> (1, 2) -> 3: 2 and 3 are adjacent, both transits go.
    cleanUpRevisits(g, r);
    EXPECT_EQ(r.cells, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(r.revisit, (std::vector<bool>{false, false, false, false}));

    // A transit loop from a cell back to it, where the coverage then photographs it: the loop goes
    // and the cell stays photographed once (a take-off cell that is also where coverage begins).
    CellPath t;
    t.cells = {3, 2, 1, 2, 3, 7, 6};
    t.revisit = {true, true, true, true, false, false, false};
    cleanUpRevisits(g, t);
    EXPECT_EQ(t.cells, (std::vector<int>{3, 7, 6}));
    EXPECT_EQ(t.revisit, (std::vector<bool>{false, false, false}));
}

TEST(StridePlanner, BadRequestsAreErrors) {
    const grid::Grid g = drawGrid({"..#", "..."});
    CoverageRequest req;
    req.start = g.index(2, 1);
    auto r = planStride(g, req);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "the start cell (column 2, row 1) is not part of the area to photograph");
    req.start = 99;
    r = planStride(g, req);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "the start cell 99 is outside the grid of 6 cells");
    const grid::Grid empty = drawGrid({"##", "##"});
    r = planStride(empty, {});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(r.error().message.find("no cell to photograph"), std::string::npos);
}

// A staircase started in the middle of its long bottom edge: the paper's rules climb the steps in short
// column strides and leave half of the bottom edge behind; the lane and lead-in variants fly long rows.
TEST(StrideVariants, StaircaseFromMidEdgeNeedsFarFewerTurnsThanThePaperRules) {
    std::vector<std::string> pic;
    for (int step = 0; step < 6; ++step) {
        const std::string row = std::string(static_cast<std::size_t>(4 * step), '#') +
                                std::string(static_cast<std::size_t>(40 - 4 * step), '.');
        pic.push_back(row);
        pic.push_back(row);
    }
    std::reverse(pic.begin(), pic.end()); // drawGrid's first line is the top row
    const grid::Grid g = drawGrid(pic);
    CoverageRequest req;
    req.start = g.index(10, 0);
    auto paper = planStrideVariant(g, req, StrideVariant{});
    auto best = planStride(g, req);
    ASSERT_TRUE(paper.ok());
    ASSERT_TRUE(best.ok());
    test::expectValidCoverage(g, *best, false, 0, "staircase");
    const int paperTurns = computeMetrics(g, *paper).turns, bestTurns = computeMetrics(g, *best).turns;
    // 12 rows: a boustrophedon needs 22 turns, plus the way back to the bottom edge's other half.
    EXPECT_LE(bestTurns, 26);
    EXPECT_LT(bestTurns * 10, paperTurns * 8) << "paper " << paperTurns << ", variants " << bestTurns;
}

// Choosing by time keeps the variant the aircraft flies soonest; choosing by turns the one with the fewest
// turns: each is at least as good as the other on its own measure.
TEST(StrideVariants, ChoiceByTimeOrByTurns) {
    MetricsOptions mo;
    mo.time.speedMps = 10.0;
    mo.time.turnRateDegS = 150.0;
    int differ = 0;
    for (unsigned seed = 1; seed <= 15; ++seed) {
        const grid::Grid g = test::randomShape(test::Shape::Concave, seed);
        if (g.visitCount() == 0)
            continue;
        CoverageRequest req;
        auto byTurns = planStride(g, req);
        auto byTime = planStride(g, req, nullptr, StrideChoice{true, mo.time});
        ASSERT_TRUE(byTurns.ok() && byTime.ok());
        std::vector<int> sizes;
        test::freeComponents(g, std::vector<std::uint8_t>(static_cast<std::size_t>(g.cellCount()), 0), &sizes);
        test::expectValidCoverage(g, *byTime, false, static_cast<int>(sizes.size()) - 1,
                                  "by time, seed " + std::to_string(seed));
        const PathMetrics a = computeMetrics(g, *byTurns, mo), b = computeMetrics(g, *byTime, mo);
        EXPECT_LE(a.turns, b.turns) << "seed " << seed;
        EXPECT_LE(b.estimatedTimeS, a.estimatedTimeS + 1e-9) << "seed " << seed;
        differ += a.turns != b.turns;
    }
    EXPECT_GT(differ, 0) << "the two choices should differ somewhere";
}

TEST(StrideVariants, LargeGridsCompareFewerVariants) {
    std::vector<std::uint8_t> small(50 * 50, 1), large(600 * 500, 1);
    const grid::Grid gs = grid::Grid::fromMask(50, 50, small);
    const grid::Grid gl = grid::Grid::fromMask(600, 500, large);
    const auto vs = strideVariants(gs, gs.index(25, 0));
    const auto vl = strideVariants(gl, gl.index(300, 0));
    // Paper rules, 3 lane variants, and 3 lane variants after a lead-in to each of the 4 corners.
    EXPECT_EQ(vs.size(), 16u);
    EXPECT_EQ(vs.front().laneWeight, 0.0); // the paper's rules come first
    EXPECT_EQ(vl.size(), 2u);
}

TEST(StridePlanner, DisconnectedPartsAreJoinedByDeclaredJumps) {
    const grid::Grid g = drawGrid({"..#..", "..#.."});
    auto path = planStride(g, {});
    ASSERT_TRUE(path.ok());
    test::expectValidCoverage(g, *path, false, 1, "two islands");
    EXPECT_EQ(path->jumps, 1);
}

} // namespace
} // namespace pf::plan
