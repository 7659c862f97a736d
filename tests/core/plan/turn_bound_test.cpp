// The lower bound on turns (computeTurnBound): exact on rectangles, equal to a brute-force cover search,
// and never above the turns of a planned path or of the best path found by exhaustive search.
#include "core/mission/planner_kinds.h"
#include "core/plan/metrics.h"

#include "tests/core/plan/plan_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <deque>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace pf::plan {
namespace {

using grid::Dir;

// Fewest turns of any path over allowed 4-moves visiting every visitable cell (any start and end,
// revisits allowed): a 0-1 breadth-first search over (cell, last direction, cells seen). -1 if the cells
// are not connected. Small grids only (about 14 visitable cells).
int optimalTurns(const grid::Grid& g) {
    std::vector<int> id(static_cast<std::size_t>(g.cellCount()), -1), cells;
    for (int i = 0; i < g.cellCount(); ++i)
        if (g.needsVisit(i)) {
            id[i] = static_cast<int>(cells.size());
            cells.push_back(i);
        }
    const int k = static_cast<int>(cells.size());
    if (k == 0)
        return 0;
    const unsigned full = (1u << k) - 1;
    auto key = [&](int c, int d, unsigned mask) { return (static_cast<std::size_t>(mask) * k + c) * 5 + d; };
    std::vector<int> dist(static_cast<std::size_t>(1u << k) * k * 5, std::numeric_limits<int>::max());
    struct State {
        int c, d;
        unsigned mask;
    };
    std::deque<State> q;
    for (int c = 0; c < k; ++c) {
        dist[key(c, 4, 1u << c)] = 0;
        q.push_back({c, 4, 1u << c});
    }
    while (!q.empty()) {
        const State s = q.front();
        q.pop_front();
        const int here = dist[key(s.c, s.d, s.mask)];
        if (s.mask == full)
            return here; // 0-1 BFS pops states in order of cost
        for (int d = 0; d < 4; ++d) {
            if (!g.canMove(cells[s.c], grid::kDirs[d]))
                continue;
            const int n = id[g.neighbour(cells[s.c], grid::kDirs[d])];
            const int cost = (s.d != 4 && s.d != d) ? 1 : 0;
            const unsigned mask = s.mask | (1u << n);
            int& nd = dist[key(n, d, mask)];
            if (here + cost < nd) {
                nd = here + cost;
                if (cost)
                    q.push_back({n, d, mask});
                else
                    q.push_front({n, d, mask});
            }
        }
    }
    return -1;
}

// Row and column run of each visitable cell (-1 elsewhere), written independently of metrics.cpp.
struct Runs {
    std::vector<int> row, col;
    int rows = 0, cols = 0;
};
Runs runsOf(const grid::Grid& g) {
    Runs r;
    r.row.assign(static_cast<std::size_t>(g.cellCount()), -1);
    r.col = r.row;
    for (int i = 0; i < g.cellCount(); ++i) {
        if (!g.needsVisit(i))
            continue;
        const int w = g.neighbour(i, Dir::West), s = g.neighbour(i, Dir::South);
        r.row[i] = g.canMove(i, Dir::West) ? r.row[w] : r.rows++;
        r.col[i] = g.canMove(i, Dir::South) ? r.col[s] : r.cols++;
    }
    return r;
}

// Brute force over every set A of row runs (the column runs are then forced: those of the cells A
// misses): M = min max(|A|, |B|) and the bound min (2 max - 1 - [|A| != |B|]).
struct Brute {
    int m = 0;
    int turns = 0;
};
Brute bruteForce(const grid::Grid& g) {
    const Runs r = runsOf(g);
    Brute best{std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
    std::vector<char> inB(static_cast<std::size_t>(r.cols));
    for (unsigned a = 0; a < (1u << r.rows); ++a) {
        std::fill(inB.begin(), inB.end(), 0);
        int b = 0;
        for (int i = 0; i < g.cellCount(); ++i)
            if (r.row[i] >= 0 && !((a >> r.row[i]) & 1u) && !inB[r.col[i]]) {
                inB[r.col[i]] = 1;
                ++b;
            }
        const int na = __builtin_popcount(a), mx = std::max(na, b);
        best.m = std::min(best.m, mx);
        best.turns = std::min(best.turns, std::max(0, 2 * mx - 1 - (na != b ? 1 : 0)));
    }
    return best;
}

grid::Grid randomMask(std::mt19937& rng, int w, int h, double fill) {
    std::bernoulli_distribution on(fill);
    std::vector<std::uint8_t> m(static_cast<std::size_t>(w * h));
    for (auto& x : m)
        x = on(rng) ? 1 : 0;
    return grid::Grid::fromMask(w, h, m, 1.0);
}

TEST(TurnBound, RectanglesNeedTwoTurnsPerExtraLane) {
    for (int r = 1; r <= 12; ++r)
        for (int c = 1; c <= 12; ++c) {
            const grid::Grid g = grid::Grid::fromMask(c, r, std::vector<std::uint8_t>(static_cast<std::size_t>(r * c), 1));
            const TurnBound tb = computeTurnBound(g);
            EXPECT_EQ(tb.turns, 2 * std::min(r, c) - 2) << r << " x " << c;
            EXPECT_EQ(tb.balancedRuns, std::min(r, c)) << r << " x " << c;
            EXPECT_EQ(tb.straightRuns, std::min(r, c)) << r << " x " << c;
            EXPECT_TRUE(tb.exact);
            if (r * c <= 12) {
                EXPECT_EQ(optimalTurns(g), tb.turns) << r << " x " << c; // and a boustrophedon reaches it
            }
        }
}

TEST(TurnBound, HandDrawnShapes) {
    // An L: one row run and one column run, a single turn.
    TurnBound tb = computeTurnBound(test::drawGrid({".##", ".##", "..."}));
    EXPECT_EQ(tb.balancedRuns, 1);
    EXPECT_EQ(tb.turns, 1);
    // A plus: its row and column form the only cover with one run per side, so h = v = 1 at least.
    tb = computeTurnBound(test::drawGrid({"#.#", "...", "#.#"}));
    EXPECT_EQ(tb.balancedRuns, 1);
    EXPECT_EQ(tb.turns, 1);
    EXPECT_EQ(optimalTurns(test::drawGrid({"#.#", "...", "#.#"})), 3);
    // A 3 x 3 square: the matching bound says 2, every path needs 4.
    tb = computeTurnBound(test::drawGrid({"...", "...", "..."}));
    EXPECT_EQ(tb.straightRuns, 3);
    EXPECT_EQ(tb.turns, 4);
    // No visitable cell, one cell, one straight line.
    EXPECT_EQ(computeTurnBound(test::drawGrid({"##", "##"})).turns, 0);
    EXPECT_EQ(computeTurnBound(test::drawGrid({"#.", "##"})).turns, 0);
    EXPECT_EQ(computeTurnBound(test::drawGrid({"....."})).turns, 0);
    // A single column and a 2-wide column: lanes along the long side.
    EXPECT_EQ(computeTurnBound(test::drawGrid({".", ".", ".", "."})).turns, 0);
    EXPECT_EQ(computeTurnBound(test::drawGrid({"..", "..", "..", ".."})).turns, 2);
}

TEST(TurnBound, NeverAboveTheBestPathOnSmallShapes) {
    std::mt19937 rng(7);
    int checked = 0, stronger = 0;
    for (int k = 0; k < 400; ++k) {
        const int w = 2 + static_cast<int>(rng() % 3), h = 2 + static_cast<int>(rng() % 3); // up to 4 x 4
        const grid::Grid g = randomMask(rng, w, h, 0.75);
        if (g.visitCount() > 13)
            continue;
        const int best = optimalTurns(g);
        if (best < 0)
            continue; // cells not connected: no complete path
        const TurnBound tb = computeTurnBound(g);
        ASSERT_TRUE(tb.exact);
        EXPECT_LE(tb.turns, best) << "shape " << k;
        EXPECT_GE(tb.turns, tb.straightRuns - 1) << "shape " << k;
        ++checked;
        stronger += tb.turns > tb.straightRuns - 1 ? 1 : 0;
    }
    EXPECT_GT(checked, 150);
    EXPECT_GT(stronger, 20); // the new bound does better than the matching bound on many of them
}

TEST(TurnBound, EqualsBruteForceCoverSearch) {
    std::mt19937 rng(11);
    int checked = 0;
    for (int k = 0; k < 300; ++k) {
        const int w = 3 + static_cast<int>(rng() % 5), h = 3 + static_cast<int>(rng() % 4); // up to 7 x 6
        const grid::Grid g = randomMask(rng, w, h, 0.55 + 0.4 * (k % 5) / 4.0);
        if (runsOf(g).rows > 13)
            continue;
        const Brute b = bruteForce(g);
        const TurnBound tb = computeTurnBound(g);
        ASSERT_TRUE(tb.exact);
        EXPECT_EQ(tb.balancedRuns, b.m) << "shape " << k;
        EXPECT_EQ(tb.turns, b.turns) << "shape " << k;
        EXPECT_GE(tb.turns, tb.straightRuns - 1);
        EXPECT_EQ(tb.straightRuns, minStraightRuns(g));
        ++checked;
    }
    EXPECT_GT(checked, 200);
}

// Checks the bound against the stride, raster and (4-connected) wavefront paths from a few contour
// cells; returns how many complete jump-free paths each planner gave (the bound speaks of those only).
std::array<int, 3> checkPlannedPaths(const grid::Grid& g, const std::string& what) {
    std::array<int, 3> counted{0, 0, 0};
    const TurnBound tb = computeTurnBound(g);
    EXPECT_TRUE(tb.exact) << what;
    EXPECT_GE(tb.turns, tb.straightRuns - 1) << what;
    std::vector<int> contour;
    for (int i = 0; i < g.cellCount(); ++i)
        if (g.onContour(i))
            contour.push_back(i);
    for (int s = 0; s < 3 && !contour.empty(); ++s) {
        CoverageRequest req;
        req.start = contour[contour.size() * static_cast<std::size_t>(s) / 3];
        int k = 0;
        for (PlannerKind kind : {PlannerKind::Stride, PlannerKind::Raster, PlannerKind::Wavefront}) {
            PlanOptions po;
            po.kind = kind;
            po.wavefront.moore = false; // the bound is for 4-connected moves
            po.wavefront.maxCandidates = 2;
            auto path = planCoverage(g, req, po);
            EXPECT_TRUE(path.ok()) << what;
            if (path.ok()) {
                const PathMetrics m = computeMetrics(g, *path);
                if (m.complete() && m.jumps == 0) {
                    EXPECT_EQ(m.turnLowerBound, tb.turns) << what;
                    EXPECT_LE(tb.turns, m.turns) << what << " " << mission::plannerKindInfo(kind).id << " from " << req.start;
                    ++counted[k];
                }
            }
            ++k;
        }
    }
    return counted;
}

TEST(TurnBound, NeverAbovePlannedPaths) {
    const test::Shape shapes[] = {test::Shape::Holes, test::Shape::Concave, test::Shape::Teeth, test::Shape::LShape};
    std::array<int, 3> total{0, 0, 0};
    for (test::Shape shape : shapes)
        for (unsigned seed = 1; seed <= 8; ++seed) {
            const auto c = checkPlannedPaths(test::randomShape(shape, seed),
                                             std::string(test::shapeName(shape)) + " seed " + std::to_string(seed));
            for (int k = 0; k < 3; ++k)
                total[k] += c[k];
        }
    // Simple shapes where the raster paths fly without jumps too: rectangles and staircases (each row
    // one interval, its ends moving by at most one cell from row to row).
    std::mt19937 rng(5);
    for (int n = 0; n < 30; ++n) {
        const int w = 3 + static_cast<int>(rng() % 18), h = 3 + static_cast<int>(rng() % 14);
        std::vector<std::uint8_t> m(static_cast<std::size_t>(w * h), 0);
        int lo = 0, hi = w - 1;
        for (int r = 0; r < h; ++r) {
            if (n % 2) {
                lo = std::clamp(lo + static_cast<int>(rng() % 3) - 1, 0, w / 2 - 1);
                hi = std::clamp(hi + static_cast<int>(rng() % 3) - 1, w / 2, w - 1);
            }
            for (int c = lo; c <= hi; ++c)
                m[static_cast<std::size_t>(r * w + c)] = 1;
        }
        const auto c = checkPlannedPaths(grid::Grid::fromMask(w, h, m), "simple shape " + std::to_string(n));
        for (int k = 0; k < 3; ++k)
            total[k] += c[k];
    }
    // Stride and wavefront fly every connected shape without jumps (one random shape is not connected).
    EXPECT_GE(total[0], 170);
    EXPECT_GE(total[2], 170);
    EXPECT_GE(total[1], 15);
}

TEST(TurnBound, SmallBudgetStillGivesAValidBound) {
    int cutShort = 0;
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const grid::Grid g = test::randomShape(test::Shape::Holes, seed, 40, 30);
        const TurnBound full = computeTurnBound(g);
        ASSERT_TRUE(full.exact);
        for (long long budget : {0LL, 100LL, 2000LL}) {
            const TurnBound cut = computeTurnBound(g, budget);
            EXPECT_GE(cut.turns, cut.straightRuns - 1) << seed << " " << budget;
            EXPECT_LE(cut.turns, full.turns) << seed << " " << budget;
            EXPECT_LE(cut.balancedRuns, full.balancedRuns) << seed << " " << budget;
            if (cut.exact) {
                EXPECT_EQ(cut.turns, full.turns) << seed << " " << budget;
            }
            cutShort += cut.exact ? 0 : 1;
        }
    }
    EXPECT_GT(cutShort, 0); // the fallback was exercised
}

TEST(TurnBound, NotComputedForDiagonalSteps) {
    const grid::Grid g = test::drawGrid({"...", "...", "..."});
    CellPath p;
    p.cells = {g.index(0, 0), g.index(1, 1), g.index(2, 2)};
    p.revisit = {false, false, false};
    MetricsOptions opt;
    opt.diagonalSteps = true;
    EXPECT_EQ(computeMetrics(g, p, opt).turnLowerBound, -1); // a diagonal is on no row or column run
    opt.diagonalSteps = false;
    EXPECT_EQ(computeMetrics(g, p, opt).turnLowerBound, 4);
}

} // namespace
} // namespace pf::plan
