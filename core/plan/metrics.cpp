#include "core/plan/metrics.h"

#include "core/plan/planner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace pf::plan {

using grid::Dir;

// Why computeTurnBound is a lower bound on turns.
// Take a path over allowed 4-connected moves that visits every visitable cell (steps that stay on a cell
// are ignored, as computeMetrics does). Split it into maximal straight segments: consecutive segments
// differ in direction, so turns = segments - 1 (a U-turn counts once). Merge consecutive segments on the
// same axis into super-segments: two such segments are a U-turn on one line sharing a cell, so a
// horizontal super-segment lies in a single row run (cells joined by allowed East-West moves; moves are
// symmetric) and a vertical one in a single column run. By maximality super-segments alternate between
// horizontal and vertical, so with h horizontal and v vertical ones, |h - v| <= 1 and
// turns >= h + v - 1. Every visitable cell is on some segment, hence its row run is the run of some
// horizontal super-segment or its column run that of a vertical one: the runs used, A (rows) and B
// (columns), cover every cell, with |A| <= h and |B| <= v. Let M be the least max(|A|, |B|) over all
// covers. Then max(h, v) >= M and turns >= h + v - 1 >= 2 max(h, v) - 2 >= 2M - 2. If moreover no cover
// has M runs on one side and M - 1 on the other, then h = v (so turns >= 2M - 1) or the larger side
// exceeds M (so turns >= 2M). As every cover has at least minStraightRuns runs, the bound is never below
// minStraightRuns - 1, and on an R x C rectangle (covers: all rows or all columns) it is 2 min(R, C) - 2,
// which a boustrophedon flies.
// Finding M is a vertex cover with a budget on each side of a bipartite graph (NP-hard in general), so
// computeTurnBound searches with a work budget: it proves "no cover with t runs per side" for
// t = ceil(minStraightRuns / 2), t + 1, ...; M is the first t with a cover, and if the budget runs out
// first, the t reached is still a proven lower bound on M.

namespace {

// The bipartite graph of straight runs: vertices [0, rows) are row runs, [rows, rows + cols) column runs,
// one edge per visitable cell (a row run and a column run share at most one cell).
struct RunGraph {
    int rows = 0;
    int cols = 0;
    std::vector<int> start; // CSR offsets, rows + cols + 1 entries
    std::vector<int> adj;   // neighbours (vertex ids)
    int vertices() const { return rows + cols; }
    int edges() const { return static_cast<int>(adj.size() / 2); }
};

RunGraph buildRunGraph(const grid::Grid& g) {
    const int n = g.cellCount(), w = g.cols();
    std::vector<int> rowRun(static_cast<std::size_t>(n), -1), colRun(static_cast<std::size_t>(n), -1);
    RunGraph rg;
    // A cell starts a row run unless it can move West, a column run unless it can move South.
    for (int i = 0; i < n; ++i)
        if (g.needsVisit(i))
            rowRun[i] = g.canMove(i, Dir::West) ? rowRun[i - 1] : rg.rows++;
    for (int i = 0; i < n; ++i)
        if (g.needsVisit(i))
            colRun[i] = g.canMove(i, Dir::South) ? colRun[i - w] : rg.cols++;
    rg.start.assign(static_cast<std::size_t>(rg.vertices()) + 1, 0);
    for (int i = 0; i < n; ++i)
        if (rowRun[i] >= 0) {
            ++rg.start[rowRun[i] + 1];
            ++rg.start[rg.rows + colRun[i] + 1];
        }
    for (int v = 0; v < rg.vertices(); ++v)
        rg.start[v + 1] += rg.start[v];
    rg.adj.resize(static_cast<std::size_t>(rg.start.back()));
    std::vector<int> fill(rg.start.begin(), rg.start.end() - 1);
    for (int i = 0; i < n; ++i)
        if (rowRun[i] >= 0) {
            const int r = rowRun[i], c = rg.rows + colRun[i];
            rg.adj[fill[r]++] = c;
            rg.adj[fill[c]++] = r;
        }
    return rg;
}

// Decides whether the runs graph has a vertex cover with at most `ta` row runs and at most `tb` column
// runs (NP-hard in general bipartite graphs, so this is a bounded branch-and-bound). Reductions: a run
// with more uncovered cells than the other side's budget must be in the cover (otherwise all the runs
// crossing it would be); pruning: a matching of uncovered cells larger than the budgets, or more uncovered
// cells than the budgets' runs can hold. Branching: the run crossing the most uncovered cells is in the
// cover, or all the runs crossing it are.
class BalancedCover {
public:
    enum Answer { No = 0, Yes = 1, Unknown = 2 };

    BalancedCover(const RunGraph& g, long long workBudget)
        : m_g(g), m_work(workBudget), m_status(static_cast<std::size_t>(g.vertices()), kOpen),
          m_deg(static_cast<std::size_t>(g.vertices())), m_mate(static_cast<std::size_t>(g.vertices()), -1),
          m_seen(static_cast<std::size_t>(g.vertices()), 0), m_from(static_cast<std::size_t>(g.vertices()), -1) {
        for (int v = 0; v < g.vertices(); ++v)
            m_deg[v] = g.start[v + 1] - g.start[v];
        m_open = g.edges();
    }

    Answer decide(int ta, int tb) {
        if (ta < 0 || tb < 0)
            return No;
        return search(ta, tb);
    }

private:
    static constexpr std::uint8_t kOpen = 0, kTaken = 1, kDropped = 2;

    bool isRow(int v) const { return v < m_g.rows; }

    // Marks v taken (in the cover) or dropped (no uncovered cells left), updating the degrees.
    void set(int v, std::uint8_t s) {
        m_status[v] = s;
        m_trail.push_back(v);
        if (s == kTaken) {
            for (int k = m_g.start[v]; k < m_g.start[v + 1]; ++k) {
                const int u = m_g.adj[k];
                if (m_status[u] == kOpen) {
                    --m_deg[u];
                    --m_open;
                }
            }
            m_work -= m_g.start[v + 1] - m_g.start[v];
        }
    }
    void undoTo(std::size_t mark) {
        while (m_trail.size() > mark) {
            const int v = m_trail.back();
            m_trail.pop_back();
            if (m_status[v] == kTaken)
                for (int k = m_g.start[v]; k < m_g.start[v + 1]; ++k) {
                    const int u = m_g.adj[k];
                    if (m_status[u] == kOpen) {
                        ++m_deg[u];
                        ++m_open;
                    }
                }
            m_status[v] = kOpen;
        }
    }

    // Size of a maximum matching among the uncovered cells, stopping once it exceeds `limit` or the work
    // budget runs out (then the size of the matching found, a lower bound, is returned). The matching
    // is kept between calls (pairs with a run no longer open are dropped), so a search node only repairs
    // what its parent's choices broke.
    int matching(int limit) {
        int size = 0;
        for (int r = 0; r < m_g.rows; ++r) {
            const int c = m_mate[r];
            if (c < 0)
                continue;
            if (m_status[r] != kOpen || m_status[c] != kOpen) {
                m_mate[r] = -1;
                m_mate[c] = -1;
            } else {
                ++size;
            }
        }
        m_work -= m_g.rows;
        // Greedy pairs first, then augmenting paths (breadth-first) from the rows left single.
        for (int r = 0; r < m_g.rows; ++r) {
            if (m_status[r] != kOpen || m_mate[r] >= 0)
                continue;
            for (int k = m_g.start[r]; k < m_g.start[r + 1]; ++k) {
                const int c = m_g.adj[k];
                if (m_status[c] == kOpen && m_mate[c] < 0) {
                    m_mate[r] = c;
                    m_mate[c] = r;
                    ++size;
                    break;
                }
            }
            m_work -= m_g.start[r + 1] - m_g.start[r];
        }
        std::vector<int>& queue = m_queue;
        // Out of budget: the matching so far is smaller than the maximum, so it only prunes if it is
        // already too large.
        for (int r = 0; r < m_g.rows && size <= limit && m_work >= 0; ++r) {
            if (m_status[r] != kOpen || m_mate[r] >= 0 || m_deg[r] == 0)
                continue;
            ++m_stamp;
            queue.assign(1, r);
            int end = -1;
            for (std::size_t h = 0; h < queue.size() && end < 0; ++h) {
                const int u = queue[h];
                for (int k = m_g.start[u]; k < m_g.start[u + 1]; ++k) {
                    const int c = m_g.adj[k];
                    if (m_status[c] != kOpen || m_seen[c] == m_stamp)
                        continue;
                    m_seen[c] = m_stamp;
                    m_from[c] = u;
                    if (m_mate[c] < 0) {
                        end = c;
                        break;
                    }
                    queue.push_back(m_mate[c]);
                }
                m_work -= m_g.start[u + 1] - m_g.start[u];
            }
            if (end < 0)
                continue;
            for (int c = end; c >= 0;) {
                const int u = m_from[c];
                const int next = m_mate[u];
                m_mate[c] = u;
                m_mate[u] = c;
                c = next;
            }
            ++size;
        }
        return size;
    }

    Answer search(int ta, int tb) {
        const std::size_t mark = m_trail.size();
        const Answer a = searchHere(ta, tb);
        undoTo(mark);
        return a;
    }

    Answer searchHere(int ta, int tb) {
        // Reductions until nothing changes.
        for (bool changed = true; changed;) {
            changed = false;
            for (int v = 0; v < m_g.vertices(); ++v) {
                if (m_status[v] != kOpen)
                    continue;
                if (m_deg[v] == 0) {
                    set(v, kDropped);
                } else if (isRow(v) ? m_deg[v] > tb : m_deg[v] > ta) {
                    set(v, kTaken);
                    (isRow(v) ? ta : tb) -= 1;
                    if (ta < 0 || tb < 0)
                        return No;
                    changed = true;
                }
            }
            m_work -= m_g.vertices();
        }
        if (m_open == 0)
            return Yes;
        if (m_work < 0)
            return Unknown;
        int best = -1, rowMax = 0, colMax = 0;
        for (int v = 0; v < m_g.vertices(); ++v) {
            if (m_status[v] != kOpen)
                continue;
            int& mx = isRow(v) ? rowMax : colMax;
            mx = std::max(mx, m_deg[v]);
            if (best < 0 || m_deg[v] > m_deg[best])
                best = v;
        }
        m_work -= m_g.vertices();
        // Each row run of the cover holds at most rowMax uncovered cells, each column run colMax.
        if (static_cast<long long>(m_open) > static_cast<long long>(ta) * rowMax + static_cast<long long>(tb) * colMax)
            return No;
        const int nu = matching(ta + tb);
        if (nu > ta + tb)
            return No;
        if (m_deg[best] == 1)
            return Yes; // disjoint cells: one run each, from either side, and the matching fits the budgets
        if (m_work < 0)
            return Unknown;
        // Branch 1: the busiest run is in the cover.
        const std::size_t mark = m_trail.size();
        set(best, kTaken);
        const Answer first = search(isRow(best) ? ta - 1 : ta, isRow(best) ? tb : tb - 1);
        undoTo(mark);
        if (first == Yes)
            return Yes;
        // Branch 2: it is not, so every open run crossing it is.
        int na = ta, nb = tb;
        for (int k = m_g.start[best]; k < m_g.start[best + 1]; ++k) {
            const int u = m_g.adj[k];
            if (m_status[u] == kOpen) {
                set(u, kTaken);
                (isRow(u) ? na : nb) -= 1;
            }
        }
        const Answer second = na < 0 || nb < 0 ? No : search(na, nb);
        undoTo(mark);
        if (second == Yes)
            return Yes;
        return first == Unknown || second == Unknown ? Unknown : No;
    }

    const RunGraph& m_g;
    long long m_work;
    std::vector<std::uint8_t> m_status;
    std::vector<int> m_deg;
    int m_open = 0; // uncovered cells (edges between two open runs)
    std::vector<int> m_trail;
    std::vector<int> m_mate, m_seen, m_from, m_queue;
    int m_stamp = 0;
};

} // namespace

PathMetrics computeMetrics(const grid::Grid& g, const CellPath& path, const MetricsOptions& opt) {
    PathMetrics m;
    m.visitable = g.visitCount();
    const std::size_t n = path.cells.size();
    m.occurrences = static_cast<int>(n);
    std::vector<std::uint8_t> seen(static_cast<std::size_t>(g.cellCount()), 0);
    for (std::size_t i = 0; i < n; ++i) {
        const int c = path.cells[i];
        const bool transit = i < path.revisit.size() && path.revisit[i];
        if (transit) {
            ++m.revisits;
        } else if (c >= 0 && c < g.cellCount() && g.needsVisit(c) && !seen[c]) {
            seen[c] = 1;
            ++m.cells;
        }
    }
    int pdc = 0, pdr = 0; // previous step, 0/0 before the first
    for (std::size_t i = 1; i < n; ++i) {
        const int a = path.cells[i - 1], b = path.cells[i];
        m.pathLengthM += (g.flightPosition(b) - g.flightPosition(a)).norm();
        if (!isAllowedStep(g, a, b, opt.diagonalSteps))
            ++m.jumps;
        const int dc = g.col(b) - g.col(a), dr = g.row(b) - g.row(a);
        if (dc == 0 && dr == 0)
            continue;
        if (pdc != 0 || pdr != 0) {
            const long cross = static_cast<long>(pdc) * dr - static_cast<long>(pdr) * dc;
            const long dot = static_cast<long>(pdc) * dc + static_cast<long>(pdr) * dr;
            if (cross != 0 || dot < 0) {
                ++m.turns;
                m.turnAngleDeg += std::atan2(std::abs(static_cast<double>(cross)), static_cast<double>(dot)) *
                                  180.0 / M_PI;
            }
        }
        pdc = dc;
        pdr = dr;
    }
    m.distanceM = m.pathLengthM;
    if (n >= 2)
        m.distanceM += (g.flightPosition(path.cells.front()) - g.flightPosition(path.cells.back())).norm();
    // The one time model, with the turns counted on the grid steps (the offsets of shifted flight
    // positions are not turns the planner chose).
    m.estimatedTimeS = (opt.time.speedMps > 0 ? m.pathLengthM / opt.time.speedMps : 0.0) +
                       (opt.time.turnRateDegS > 0 ? m.turnAngleDeg / opt.time.turnRateDegS : 0.0) +
                       (m.pathLengthM > 0 ? (m.turns + 1) * opt.time.stopCostS() : 0.0);
    // The bound counts 4-connected moves only: a diagonal step is not on a row or column run.
    if (opt.turnLowerBound && !opt.diagonalSteps) {
        m.turnLowerBound = computeTurnBound(g).turns;
        m.turnRatio = m.turnLowerBound > 0 ? static_cast<double>(m.turns) / m.turnLowerBound
                                           : (m.turns == 0 ? 1.0 : static_cast<double>(m.turns));
    }
    return m;
}

namespace {

// Maximum matching between row runs and column runs (= the fewest runs covering every cell).
int maxRunMatching(const RunGraph& rg) {
    const int rows = rg.rows, cols = rg.cols;
    if (rows == 0)
        return 0;
    // Row runs come first in the graph: their neighbours, shifted to column numbers 0..cols-1.
    const std::vector<int> start(rg.start.begin(), rg.start.begin() + rows + 1);
    std::vector<int> adj(rg.adj.begin(), rg.adj.begin() + start[rows]);
    for (int& c : adj)
        c -= rows;

    // Hopcroft-Karp with an iterative depth-first search (augmenting paths can be long on big grids).
    const int kInf = std::numeric_limits<int>::max();
    std::vector<int> matchU(static_cast<std::size_t>(rows), -1), matchV(static_cast<std::size_t>(cols), -1);
    std::vector<int> dist(static_cast<std::size_t>(rows)), queue, it(static_cast<std::size_t>(rows));
    std::vector<int> stack;
    int matching = 0;
    // Greedy start: most edges match immediately.
    for (int u = 0; u < rows; ++u)
        for (int k = start[u]; k < start[u + 1]; ++k)
            if (matchV[adj[k]] < 0) {
                matchU[u] = adj[k];
                matchV[adj[k]] = u;
                ++matching;
                break;
            }
    for (;;) {
        queue.clear();
        for (int u = 0; u < rows; ++u) {
            if (matchU[u] < 0) {
                dist[u] = 0;
                queue.push_back(u);
            } else {
                dist[u] = kInf;
            }
        }
        bool found = false;
        for (std::size_t h = 0; h < queue.size(); ++h) {
            const int u = queue[h];
            for (int k = start[u]; k < start[u + 1]; ++k) {
                const int u2 = matchV[adj[k]];
                if (u2 < 0)
                    found = true;
                else if (dist[u2] == kInf) {
                    dist[u2] = dist[u] + 1;
                    queue.push_back(u2);
                }
            }
        }
        if (!found)
            break;
        for (int u = 0; u < rows; ++u)
            it[u] = start[u];
        for (int root = 0; root < rows; ++root) {
            if (matchU[root] >= 0)
                continue;
            stack.assign(1, root);
            bool augmented = false;
            while (!stack.empty() && !augmented) {
                const int u = stack.back();
                bool advanced = false;
                for (; it[u] < start[u + 1]; ++it[u]) {
                    const int v = adj[it[u]];
                    const int u2 = matchV[v];
                    if (u2 < 0) {
                        // Augment along the stack.
                        for (std::size_t s = stack.size(); s-- > 0;) {
                            const int su = stack[s];
                            const int sv = adj[it[su]];
                            matchU[su] = sv;
                            matchV[sv] = su;
                        }
                        augmented = true;
                        break;
                    }
                    if (dist[u2] == dist[u] + 1) {
                        stack.push_back(u2);
                        advanced = true;
                        break;
                    }
                }
                if (augmented)
                    break;
                if (!advanced) {
                    dist[u] = kInf; // dead end in this phase
                    stack.pop_back();
                    if (!stack.empty())
                        ++it[stack.back()];
                }
            }
            if (augmented)
                ++matching;
        }
    }
    return matching;
}

} // namespace

int minStraightRuns(const grid::Grid& g) { return maxRunMatching(buildRunGraph(g)); }

TurnBound computeTurnBound(const grid::Grid& g, long long workBudget) {
    TurnBound tb;
    const RunGraph rg = buildRunGraph(g);
    tb.straightRuns = maxRunMatching(rg);
    if (tb.straightRuns == 0) {
        tb.exact = true;
        return tb;
    }
    BalancedCover search(rg, workBudget);
    // Every cover has at least straightRuns runs, so one side holds at least half of them; all rows, or
    // all columns, always make a cover.
    const int cap = std::min(rg.rows, rg.cols);
    // A "No" is a proof and a "Yes" a cover found, whatever the budget left; "Unknown" stops the climb.
    int t = (tb.straightRuns + 1) / 2;
    tb.exact = true;
    for (; t < cap; ++t) {
        const auto answer = search.decide(t, t);
        if (answer == BalancedCover::Yes)
            break;
        if (answer == BalancedCover::Unknown) {
            tb.exact = false;
            break;
        }
    }
    tb.balancedRuns = t;
    int turns = 2 * t - 2;
    if (tb.exact && search.decide(t, t - 1) == BalancedCover::No && search.decide(t - 1, t) == BalancedCover::No)
        turns = 2 * t - 1;
    tb.turns = std::max({turns, tb.straightRuns - 1, 0});
    return tb;
}

} // namespace pf::plan
