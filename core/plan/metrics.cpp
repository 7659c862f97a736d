#include "core/plan/metrics.h"

#include "core/plan/planner.h"

#include <cmath>
#include <limits>
#include <vector>

namespace pf::plan {

using grid::Dir;

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
    m.estimatedTimeS = (opt.speedMps > 0 ? m.pathLengthM / opt.speedMps : 0.0) +
                       (opt.turnRateDegS > 0 ? m.turnAngleDeg / opt.turnRateDegS : 0.0);
    if (opt.turnLowerBound) {
        const int runs = minStraightRuns(g);
        m.turnLowerBound = runs > 0 ? runs - 1 : 0;
        m.turnRatio = m.turnLowerBound > 0 ? static_cast<double>(m.turns) / m.turnLowerBound
                                           : (m.turns == 0 ? 1.0 : static_cast<double>(m.turns));
    }
    return m;
}

int minStraightRuns(const grid::Grid& g) {
    const int n = g.cellCount();
    // Segment ids: a cell starts a row segment unless it can move West; same for columns and South.
    std::vector<int> rowSeg(static_cast<std::size_t>(n), -1), colSeg(static_cast<std::size_t>(n), -1);
    int rows = 0, cols = 0;
    for (int i = 0; i < n; ++i) {
        if (!g.needsVisit(i))
            continue;
        rowSeg[i] = g.canMove(i, Dir::West) ? rowSeg[i - 1] : rows++;
    }
    const int w = g.cols();
    for (int i = 0; i < n; ++i) {
        if (!g.needsVisit(i))
            continue;
        colSeg[i] = g.canMove(i, Dir::South) ? colSeg[i - w] : cols++;
    }
    if (rows == 0)
        return 0;
    // Adjacency of row segments (CSR): cells in index order list each row segment's cells together.
    std::vector<int> start(static_cast<std::size_t>(rows) + 1, 0), adj;
    adj.reserve(static_cast<std::size_t>(g.visitCount()));
    for (int i = 0; i < n; ++i)
        if (rowSeg[i] >= 0)
            ++start[rowSeg[i] + 1];
    for (int r = 0; r < rows; ++r)
        start[r + 1] += start[r];
    adj.resize(static_cast<std::size_t>(start[rows]));
    {
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (int i = 0; i < n; ++i)
            if (rowSeg[i] >= 0)
                adj[fill[rowSeg[i]]++] = colSeg[i];
    }
    rowSeg.clear();
    rowSeg.shrink_to_fit();
    colSeg.clear();
    colSeg.shrink_to_fit();

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

} // namespace pf::plan
