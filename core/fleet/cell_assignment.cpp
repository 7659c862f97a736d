// The fleet stage's working state: connectivity-keeping removal, boundary transfers, adjacency.
#include "core/fleet/cell_assignment.h"

#include "core/geo/types.h"
#include "core/job_scope.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>

namespace pf::fleet {

geo::Vec2 baseCellCenter(const grid::Grid& g, int i) {
    const double a = g.angleDeg() * M_PI / 180.0;
    const geo::Vec2 u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    return g.origin() + ((i % g.cols()) + 0.5) * g.cellSize() * u + ((i / g.cols()) + 0.5) * g.cellSize() * v;
}

geo::Ring baseCellSquare(const grid::Grid& g, int i) {
    const double a = g.angleDeg() * M_PI / 180.0;
    const geo::Vec2 u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    const geo::Vec2 p = g.origin() + (i % g.cols()) * g.cellSize() * u + (i / g.cols()) * g.cellSize() * v;
    return {p, p + g.cellSize() * u, p + g.cellSize() * (u + v), p + g.cellSize() * v};
}

bool CellAssignment::removable(int c) const {
    const int k = owner(c);
    if (k < 0 || size(k) <= 1)
        return false;
    // Fast local test: if the subarea's move-neighbours of c are linked to each other around
    // the 3x3 ring (consecutive ring cells, allowed moves), any path through c can detour.
    static constexpr int ringDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
    static constexpr int ringDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
    const int cx = c % m_g.cols(), cy = c / m_g.cols();
    int ring[8];
    for (int r = 0; r < 8; ++r) {
        const int x = cx + ringDx[r], y = cy + ringDy[r];
        ring[r] = (x >= 0 && y >= 0 && x < m_g.cols() && y < m_g.rows()) ? y * m_g.cols() + x : -1;
        if (ring[r] >= 0 && owner(ring[r]) != k)
            ring[r] = -1;
    }
    // Label ring runs: consecutive owned ring cells joined by an allowed move.
    int label[8];
    int next = 0;
    for (int r = 0; r < 8; ++r)
        label[r] = ring[r] >= 0 ? next++ : -1;
    auto linked = [&](int a, int b) {
        if (ring[a] < 0 || ring[b] < 0)
            return false;
        for (int d = 0; d < 4; ++d)
            if (m_g.neighbour(ring[a], grid::kDirs[d]) == ring[b])
                return m_g.canMove(ring[a], grid::kDirs[d]);
        return false;
    };
    for (int pass = 0; pass < 2; ++pass)
        for (int r = 0; r < 8; ++r) {
            const int s = (r + 1) % 8;
            if (linked(r, s)) {
                const int lo = std::min(label[r], label[s]);
                label[r] = label[s] = lo;
            }
        }
    int common = -2;
    bool local = true;
    for (int d = 0; d < 4; ++d) {
        if (!m_g.canMove(c, grid::kDirs[d]))
            continue;
        const int n = m_g.neighbour(c, grid::kDirs[d]);
        if (owner(n) != k)
            continue;
        const int r = 2 * d; // E, N, W, S sit at ring positions 0, 2, 4, 6
        if (common == -2)
            common = label[r];
        else if (label[r] != common)
            local = false;
    }
    if (common == -2)
        return true; // c has no move-neighbour in its subarea: it is already apart
    if (local)
        return true;
    // Exact test: BFS through the subarea without c.
    int start = -1;
    for (int d = 0; d < 4 && start < 0; ++d)
        if (m_g.canMove(c, grid::kDirs[d]) && owner(m_g.neighbour(c, grid::kDirs[d])) == k)
            start = m_g.neighbour(c, grid::kDirs[d]);
    const auto dist = moveDistances(m_g, {start}, [&](int n) { return n != c && owner(n) == k; });
    int reached = 0;
    for (std::size_t i = 0; i < dist.size(); ++i)
        if (dist[i] >= 0)
            ++reached;
    return reached == size(k) - 1;
}

std::vector<int> CellAssignment::transfer(int from, int to, int count, bool sweep) {
    std::vector<int> moved;
    if (count <= 0)
        return moved;
    geo::Vec2 dir(0, 0);
    if (sweep) {
        geo::Vec2 cf(0, 0), ct(0, 0);
        int nf = 0, nt = 0;
        for (int c = 0; c < m_g.cellCount(); ++c) {
            const geo::Vec2 xy(c % m_g.cols(), c / m_g.cols());
            if (owner(c) == from) {
                cf += xy;
                ++nf;
            } else if (owner(c) == to) {
                ct += xy;
                ++nt;
            }
        }
        if (nf > 0 && nt > 0)
            dir = ct / nt - cf / nf;
    }
    // Cells found to hold `from` together (removable() false), remembered until a move-neighbour of
    // theirs leaves `from`. Moving a removable cell keeps `from` connected, so the piece that only
    // a cut cell joins to the rest can only vanish one cell at a time, its last cell beside the cut
    // cell: until one of its neighbours goes, a cut cell stays one. Without this, every pick tested
    // the same cut cells again, each by a search through the whole subarea (a zone beside the
    // shared boundary leaves a row of them: 900,000 searches in one split of the demo).
    const std::size_t cells = static_cast<std::size_t>(m_g.cellCount());
    std::vector<std::uint8_t> cut(cells, 0);
    // The candidates (cells of `from` beside `to`, not cut), best first. A cell's score and whether
    // it is a candidate change only when a neighbour changes hands, so only the picked cell's
    // neighbours are scored again (re-scoring and sorting every candidate per pick was most of a
    // transfer's time).
    std::set<std::pair<double, int>> queue;
    std::vector<double> key(cells, 0.0);
    std::vector<std::uint8_t> queued(cells, 0);
    const auto refresh = [&](int c) {
        const std::size_t i = static_cast<std::size_t>(c);
        if (queued[i])
            queue.erase({key[i], c});
        queued[i] = !cut[i] && owner(c) == from && neighboursIn(c, to) > 0;
        if (!queued[i])
            return;
        const double compact = 2 * neighboursIn(c, to) - neighboursIn(c, from);
        const double along = dir.x() * (c % m_g.cols()) + dir.y() * (c / m_g.cols());
        key[i] = sweep ? -(along + 1e-3 * compact) : -compact;
        queue.emplace(key[i], c);
    };
    for (int c = 0; c < m_g.cellCount(); ++c)
        refresh(c);
    // A cancelled job stops between two moves: its caller then sees fewer cells moved and returns
    // at its own next check.
    while (static_cast<int>(moved.size()) < count && !stopRequested()) {
        // The best candidate whose move leaves `from` in one piece.
        int pick = -1;
        for (auto it = queue.begin(); it != queue.end();) {
            const int c = it->second;
            if (removable(c)) {
                pick = c;
                break;
            }
            cut[static_cast<std::size_t>(c)] = 1;
            queued[static_cast<std::size_t>(c)] = 0;
            it = queue.erase(it);
        }
        if (pick < 0)
            break;
        assign(pick, to);
        moved.push_back(pick);
        refresh(pick);
        for (int d = 0; d < 4; ++d) {
            const int n = m_g.neighbour(pick, grid::kDirs[d]);
            if (n < 0)
                continue;
            cut[static_cast<std::size_t>(n)] = 0;
            refresh(n);
        }
    }
    return moved;
}

std::vector<std::vector<int>> CellAssignment::adjacency() const {
    std::vector<std::vector<int>> adj(m_size.size(), std::vector<int>(m_size.size(), 0));
    for (int c = 0; c < m_g.cellCount(); ++c) {
        const int a = owner(c);
        if (a < 0)
            continue;
        for (int d = 0; d < 4; ++d) {
            if (!m_g.canMove(c, grid::kDirs[d]))
                continue;
            const int b = owner(m_g.neighbour(c, grid::kDirs[d]));
            if (b >= 0 && b != a)
                ++adj[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
        }
    }
    return adj;
}

Partition CellAssignment::toPartition(const std::vector<int>& targets) const {
    Partition p;
    p.owner = m_owner;
    p.targets = targets;
    p.cells.assign(m_size.size(), {});
    for (int c = 0; c < m_g.cellCount(); ++c)
        if (owner(c) >= 0)
            p.cells[static_cast<std::size_t>(owner(c))].push_back(c);
    for (const auto& cells : p.cells)
        if (!cells.empty() && !isConnected(m_g, cells))
            ++p.disconnectedSubareas;
    return p;
}

} // namespace pf::fleet
