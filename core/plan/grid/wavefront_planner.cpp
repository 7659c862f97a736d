#include "core/plan/grid/wavefront_planner.h"

#include "core/plan/best_candidate.h"
#include "core/plan/grid/grid_search.h"
#include "core/plan/grid/nearest_cell.h"
#include "core/plan/grid/stride_planner.h"
#include "core/plan/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace pf::plan {

namespace {

// The moves of one grid: 4-moves from the grid, diagonal moves checked once for safety and cached.
class Moves {
public:
    Moves(const grid::Grid& g, bool moore) : m_g(g), m_count(moore ? 8 : 4) {
        if (!moore)
            return;
        m_diag.assign(static_cast<std::size_t>(g.cellCount()), 0);
        for (int i = 0; i < g.cellCount(); ++i) {
            if (!g.needsVisit(i))
                continue;
            for (int k = 4; k < 8; ++k) {
                const int c = g.col(i) + kMoveDx[k], r = g.row(i) + kMoveDy[k];
                if (!g.inBounds(c, r))
                    continue;
                const int j = g.index(c, r);
                if (j < i) { // symmetric: copy the answer computed from the other cell
                    const int back = k < 6 ? k + 2 : k - 2;
                    if ((m_diag[j] >> (back - 4)) & 1u)
                        m_diag[i] |= static_cast<std::uint8_t>(1u << (k - 4));
                    continue;
                }
                if (isAllowedStep(g, i, j, true))
                    m_diag[i] |= static_cast<std::uint8_t>(1u << (k - 4));
            }
        }
    }
    int count() const { return m_count; }
    // Neighbour reached by move k, or -1 if the move is not allowed.
    int to(int i, int k) const {
        if (k < 4)
            return m_g.canMove(i, static_cast<grid::Dir>(k)) ? i + dirOffset(m_g, k) : -1;
        return ((m_diag[i] >> (k - 4)) & 1u) ? i + dirOffset(m_g, k) : -1;
    }

private:
    const grid::Grid& m_g;
    int m_count;
    std::vector<std::uint8_t> m_diag;
};

double turnBetween(int k1, int k2) {
    if (k1 < 0)
        return 0.0;
    const double a1 = std::atan2(kMoveDy[k1], kMoveDx[k1]), a2 = std::atan2(kMoveDy[k2], kMoveDx[k2]);
    double d = std::fabs(a1 - a2);
    if (d > M_PI)
        d = 2 * M_PI - d;
    return d;
}

struct Branch {
    int tieIndex = -1; // take the second choice at this recorded tie
};

class Ascent {
public:
    Ascent(const grid::Grid& g, const Moves& moves, const std::vector<int>& potential)
        : m_g(g), m_moves(moves), m_pot(potential), m_stamp(static_cast<std::size_t>(g.cellCount()), 0),
          m_from(static_cast<std::size_t>(g.cellCount()), 0) {}

    CellPath run(int start, Branch branch, int* tiesSeen) {
        std::vector<std::uint8_t> visited(static_cast<std::size_t>(m_g.cellCount()), 0);
        CellPath path;
        int remaining = m_g.visitCount();
        int cur = start, heading = -1, ties = 0;
        auto visit = [&](int c, bool transit) {
            path.cells.push_back(c);
            path.revisit.push_back(transit);
            if (!transit) {
                visited[c] = 1;
                --remaining;
            }
        };
        visit(start, false);
        struct Cand {
            int cell, move;
            double turn;
        };
        std::vector<Cand> cands;
        while (remaining > 0) {
            cands.clear();
            int best = std::numeric_limits<int>::min();
            for (int k = 0; k < m_moves.count(); ++k) {
                const int n = m_moves.to(cur, k);
                if (n < 0 || visited[n])
                    continue;
                if (m_pot[n] > best) {
                    best = m_pot[n];
                    cands.clear();
                }
                if (m_pot[n] == best)
                    cands.push_back({n, k, turnBetween(heading, k)});
            }
            if (cands.empty()) {
                // Dead end: shortest safe path to the nearest unvisited cell.
                const std::vector<int> p = pathToUnvisited(cur, visited);
                if (p.empty()) { // a part no move reaches: jump to its nearest cell
                    const int bestCell = nearestCell(m_g, cur, [&](int i) { return !visited[i]; });
                    ++path.jumps;
                    visit(bestCell, false);
                    cur = bestCell;
                } else {
                    for (std::size_t k = 0; k + 1 < p.size(); ++k)
                        visit(p[k], true);
                    visit(p.back(), false);
                    cur = p.back();
                }
                heading = -1;
                continue;
            }
            std::stable_sort(cands.begin(), cands.end(),
                             [](const Cand& a, const Cand& b) { return a.turn < b.turn - 1e-9; });
            std::size_t pick = 0;
            if (cands.size() > 1) {
                if (ties == branch.tieIndex)
                    pick = 1;
                ++ties;
            }
            visit(cands[pick].cell, false);
            cur = cands[pick].cell;
            heading = cands[pick].move;
        }
        if (tiesSeen)
            *tiesSeen = ties;
        return path;
    }

private:
    std::vector<int> pathToUnvisited(int from, const std::vector<std::uint8_t>& visited) {
        if (++m_cur == 0) {
            std::fill(m_stamp.begin(), m_stamp.end(), 0);
            m_cur = 1;
        }
        m_queue.clear();
        m_queue.push_back(from);
        m_stamp[from] = m_cur;
        for (std::size_t h = 0; h < m_queue.size(); ++h) {
            const int c = m_queue[h];
            for (int k = 0; k < m_moves.count(); ++k) {
                const int n = m_moves.to(c, k);
                if (n < 0 || m_stamp[n] == m_cur)
                    continue;
                m_stamp[n] = m_cur;
                m_from[n] = static_cast<std::uint8_t>(k);
                if (!visited[n]) {
                    std::vector<int> p;
                    for (int x = n; x != from; x -= dirOffset(m_g, m_from[x]))
                        p.push_back(x);
                    return std::vector<int>(p.rbegin(), p.rend());
                }
                m_queue.push_back(n);
            }
        }
        return {};
    }

    const grid::Grid& m_g;
    const Moves& m_moves;
    const std::vector<int>& m_pot;
    std::vector<std::uint32_t> m_stamp;
    std::vector<std::uint8_t> m_from;
    std::vector<int> m_queue;
    std::uint32_t m_cur = 0;
};

std::vector<int> propagate(const grid::Grid& g, const Moves& moves, int goal) {
    std::vector<int> pot(static_cast<std::size_t>(g.cellCount()), 0);
    std::vector<int> queue{goal};
    pot[goal] = 1;
    for (std::size_t h = 0; h < queue.size(); ++h) {
        const int c = queue[h];
        for (int k = 0; k < moves.count(); ++k) {
            const int n = moves.to(c, k);
            if (n >= 0 && pot[n] == 0) {
                pot[n] = pot[c] + 1;
                queue.push_back(n);
            }
        }
    }
    return pot;
}

} // namespace

std::vector<int> navigationFunction(const grid::Grid& g, int goal, bool moore) {
    const Moves moves(g, moore);
    return propagate(g, moves, goal);
}

Result<CellPath> planWavefront(const grid::Grid& g, const CoverageRequest& req, const WavefrontOptions& opt,
                               WavefrontTrace* trace) {
    auto start = resolveStart(g, req);
    if (!start)
        return start.error();
    if (opt.maxCandidates < 1)
        return makeError(ErrorCode::InvalidInput, "the wavefront planner needs at least one candidate path (got " +
                                                      std::to_string(opt.maxCandidates) + ")");
    const int goal = req.landing >= 0 ? req.landing : *start;
    const Moves moves(g, opt.moore);
    const std::vector<int> pot = propagate(g, moves, goal);
    Ascent ascent(g, moves, pot);
    MetricsOptions mo;
    mo.time = opt.time;
    mo.diagonalSteps = opt.moore;
    mo.turnLowerBound = false;

    int ties = 0;
    CellPath best = ascent.run(*start, {}, &ties);
    // The path without branching first: on a tie it wins.
    BestCandidate<double, bool (*)(double, double)> keep(&sooner);
    keep.offer(computeMetrics(g, best, mo).estimatedTimeS);
    if (trace) {
        trace->tiePoints = ties;
        trace->candidateTimes.assign(1, keep.score());
        trace->chosen = 0;
    }
    // Further candidates branch at recorded ties spread over the first path (early ties change the
    // whole path, late ones only its end).
    const int extra = std::min(opt.maxCandidates - 1, ties);
    for (int j = 0; j < extra; ++j) {
        const int tie = static_cast<int>(static_cast<long long>(j) * ties / extra);
        CellPath cand = ascent.run(*start, Branch{tie}, nullptr);
        const double t = computeMetrics(g, cand, mo).estimatedTimeS;
        if (trace)
            trace->candidateTimes.push_back(t);
        if (keep.offer(t)) {
            best = std::move(cand);
            if (trace)
                trace->chosen = keep.index();
        }
    }
    return withTakeoffAndLanding(g, req, *start, std::move(best));
}

} // namespace pf::plan
