// The fleet stage's working state: which aircraft owns each cell of the base grid while the area is
// partitioned and balanced, and the move-count search over the grid the stages share.
#pragma once

#include "core/fleet/partition.h"
#include "core/geo/types.h"
#include "core/grid/grid.h"

#include <deque>
#include <vector>

namespace pf::fleet {

// Move counts (BFS over the grid's allowed moves) from `src` through cells accepted by `inSet`; -1 where unreached.
template <class Pred>
std::vector<int> moveDistances(const grid::Grid& g, const std::vector<int>& src, Pred inSet) {
    std::vector<int> dist(static_cast<std::size_t>(g.cellCount()), -1);
    std::deque<int> q;
    for (int s : src) {
        dist[static_cast<std::size_t>(s)] = 0;
        q.push_back(s);
    }
    while (!q.empty()) {
        const int c = q.front();
        q.pop_front();
        for (int d = 0; d < 4; ++d) {
            if (!g.canMove(c, grid::kDirs[d]))
                continue;
            const int n = g.neighbour(c, grid::kDirs[d]);
            if (n < 0 || dist[static_cast<std::size_t>(n)] >= 0 || !inSet(n))
                continue;
            dist[static_cast<std::size_t>(n)] = dist[static_cast<std::size_t>(c)] + 1;
            q.push_back(n);
        }
    }
    return dist;
}

// A cell's centre and square (counter-clockwise) in local metres, with the arithmetic the partition
// has always used: the rotation applied per axis and the corners offset from the first one.
// Grid::cellCenter and Grid::cellCorners agree to about 1e-12 m but round differently, and the plans
// flown over the subareas are sensitive to the last bit (a boundary cell kept or lost changes a
// flight: FleetOnGrid.DemoSiteEndToEndCoveredAndSafe then plans past an aircraft's endurance). So the
// fleet keeps these two until its expectations are re-measured on Grid's own corners.
geo::Vec2 baseCellCenter(const grid::Grid& g, int i);
geo::Ring baseCellSquare(const grid::Grid& g, int i);

// Which aircraft owns each cell while the partition grows, redistributes and balances: the working
// state shared by partitionCells and balanceByTime. Every move it makes keeps a subarea in one piece.
class CellAssignment {
public:
    CellAssignment(const grid::Grid& g, int aircraft) : m_g(g), m_owner(static_cast<std::size_t>(g.cellCount()), -1),
                                                   m_size(static_cast<std::size_t>(aircraft), 0) {}
    CellAssignment(const grid::Grid& g, const Partition& p) : m_g(g), m_owner(p.owner), m_size(p.cells.size(), 0) {
        for (std::size_t k = 0; k < p.cells.size(); ++k)
            m_size[k] = static_cast<int>(p.cells[k].size());
    }

    int owner(int c) const { return m_owner[static_cast<std::size_t>(c)]; }
    int size(int k) const { return m_size[static_cast<std::size_t>(k)]; }
    int aircraft() const { return static_cast<int>(m_size.size()); }
    void assign(int c, int k) {
        const int old = owner(c);
        if (old >= 0)
            --m_size[static_cast<std::size_t>(old)];
        m_owner[static_cast<std::size_t>(c)] = k;
        if (k >= 0)
            ++m_size[static_cast<std::size_t>(k)];
    }

    // Neighbours of c reachable by a move that belong to subarea k.
    int neighboursIn(int c, int k) const {
        int n = 0;
        for (int d = 0; d < 4; ++d)
            if (m_g.canMove(c, grid::kDirs[d]) && owner(m_g.neighbour(c, grid::kDirs[d])) == k)
                ++n;
        return n;
    }

    // True if removing c from its subarea leaves the rest in one piece.
    bool removable(int c) const;

    // Hands up to `count` cells of `from` to `to`, one at a time, each time the best boundary cell:
    // adjacent to `to` by a move, removable from `from` without splitting it, maximising neighbours
    // in `to` minus neighbours in `from` (keeps both compact). Only the shared boundary is scanned
    // per pick, so large grids stay fast. Returns the cells moved, in order.
    // Sweep mode orders the cells by how far they lie towards `to` (along the line between the two
    // subareas' centroids) instead: the boundary then moves as a straight front, which suits
    // planners that fly long straight strides.
    // Stops early when the thread's job is cancelled (stopRequested()).
    std::vector<int> transfer(int from, int to, int count, bool sweep = false);

    // Shared move-edges between subareas: adj[a][b].
    std::vector<std::vector<int>> adjacency() const;

    // The assignment as a Partition (cells ascending), counting the subareas in several pieces.
    Partition toPartition(const std::vector<int>& targets) const;

private:
    const grid::Grid& m_g;
    std::vector<int> m_owner;
    std::vector<int> m_size;
};


} // namespace pf::fleet
