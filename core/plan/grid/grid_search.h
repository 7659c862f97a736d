// Breadth-first searches over a grid's allowed moves (Zelinsky's distance transform), shared by planners.
#pragma once

#include "core/grid/grid.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace pf::plan {

// The planners' moves: 0-3 are the grid's 4-moves (grid::Dir: E, N, W, S), 4-7 the diagonals
// (NE, NW, SW, SE) that 8-connected planners add. Move k + 2 (mod 4 within each half) is k reversed.
constexpr int kMoveDx[8] = {1, 0, -1, 0, 1, -1, -1, 1};
constexpr int kMoveDy[8] = {0, 1, 0, -1, 1, 1, -1, -1};
static_assert(kMoveDx[0] == grid::kDirDx[0] && kMoveDx[1] == grid::kDirDx[1] && kMoveDx[2] == grid::kDirDx[2] &&
                  kMoveDx[3] == grid::kDirDx[3] && kMoveDy[0] == grid::kDirDy[0] && kMoveDy[1] == grid::kDirDy[1] &&
                  kMoveDy[2] == grid::kDirDy[2] && kMoveDy[3] == grid::kDirDy[3],
              "the first four moves are the grid's directions");

// Offset of move d (0-7), as an index difference (valid whenever the move is allowed).
inline int dirOffset(const grid::Grid& g, int d) { return kMoveDx[d] + kMoveDy[d] * g.cols(); }

// Reusable scratch for repeated searches on one grid. Per-cell stamps avoid clearing arrays between
// searches, so a search costs only what it explores: planners run thousands of small searches on
// large grids and must not pay O(cells) for each.
class GridSearch {
public:
    explicit GridSearch(const grid::Grid& g)
        : m_grid(g), m_stamp(static_cast<std::size_t>(g.cellCount()), 0),
          m_from(static_cast<std::size_t>(g.cellCount()), 0) {}

    // Shortest path over allowed 4-moves from `from` to the nearest cell satisfying `target(cell)`,
    // only passing through cells satisfying `passable(cell)` (the target itself need not be passable).
    // Returns the cells after `from` up to and including the target, or empty if none is reachable.
    // Among equally near targets the first found wins (deterministic: neighbours in East, North,
    // West, South order).
    template <class Target, class Passable>
    std::vector<int> pathToNearest(int from, Target target, Passable passable) {
        const std::uint32_t s = nextStamp();
        m_queue.clear();
        m_queue.push_back(from);
        m_stamp[from] = s;
        for (std::size_t head = 0; head < m_queue.size(); ++head) {
            const int c = m_queue[head];
            for (int d = 0; d < 4; ++d) {
                if (!m_grid.canMove(c, static_cast<grid::Dir>(d)))
                    continue;
                const int n = c + dirOffset(m_grid, d);
                if (m_stamp[n] == s)
                    continue;
                m_stamp[n] = s;
                m_from[n] = static_cast<std::uint8_t>(d);
                if (target(n))
                    return trace(from, n);
                if (passable(n))
                    m_queue.push_back(n);
            }
        }
        return {};
    }

    // As pathToNearest, preferring straight paths: among the moves that reach a cell first (all of
    // the same length), the one that continues the move into its predecessor wins, and the first move
    // continues `heading` (the direction the path arrived at `from` in, or -1) when it can. A greedy
    // choice per cell, at the cost of the plain wave; a path flown back through visited cells with
    // fewer turns costs the aircraft less time at the same length.
    template <class Target, class Passable>
    std::vector<int> pathToNearestStraightest(int from, int heading, Target target, Passable passable) {
        const std::uint32_t s = nextStamp();
        if (m_layerOf.empty())
            m_layerOf.assign(m_stamp.size(), 0);
        m_queue.clear();
        m_queue.push_back(from);
        m_stamp[from] = s;
        m_layerOf[from] = 0;
        int found = -1;
        std::size_t layerBegin = 0;
        for (std::uint32_t layer = 1; layerBegin < m_queue.size() && found < 0; ++layer) {
            const std::size_t layerEnd = m_queue.size();
            for (std::size_t head = layerBegin; head < layerEnd; ++head) {
                const int c = m_queue[head];
                const int into = c == from ? heading : m_from[c];
                for (int k = 0; k < 4; ++k) {
                    // The straight continuation first, so that it claims the cells it reaches.
                    const int d = into < 0 ? k : (into + k) % 4;
                    if (!m_grid.canMove(c, static_cast<grid::Dir>(d)))
                        continue;
                    const int n = c + dirOffset(m_grid, d);
                    if (m_stamp[n] == s) {
                        // Reached already in this layer by a move that turns: take this one if straight.
                        if (m_layerOf[n] == layer && d == into && m_from[n] != d)
                            m_from[n] = static_cast<std::uint8_t>(d);
                        continue;
                    }
                    m_stamp[n] = s;
                    m_layerOf[n] = layer;
                    m_from[n] = static_cast<std::uint8_t>(d);
                    if (target(n)) {
                        if (found < 0)
                            found = n;
                    } else if (passable(n)) {
                        m_queue.push_back(n);
                    }
                }
            }
            layerBegin = layerEnd;
        }
        return found < 0 ? std::vector<int>{} : trace(from, found);
    }

    // Shortest path over allowed 4-moves from `from` to `to` (cells after `from`, ending with `to`);
    // empty if `to` cannot be reached or equals `from`.
    std::vector<int> pathTo(int from, int to) {
        if (from == to)
            return {};
        return pathToNearest(from, [to](int c) { return c == to; }, [](int) { return true; });
    }

private:
    std::uint32_t nextStamp() {
        if (++m_current == 0) { // wrapped: clear once every 4 billion searches
            std::fill(m_stamp.begin(), m_stamp.end(), 0);
            m_current = 1;
        }
        return m_current;
    }
    std::vector<int> trace(int from, int to) const {
        std::vector<int> path;
        for (int c = to; c != from; c -= dirOffset(m_grid, m_from[c]))
            path.push_back(c);
        return std::vector<int>(path.rbegin(), path.rend());
    }

    const grid::Grid& m_grid;
    std::vector<std::uint32_t> m_stamp;
    std::vector<std::uint8_t> m_from; // direction of the move that reached the cell
    std::vector<int> m_queue;
    std::uint32_t m_current = 0;
    std::vector<std::uint32_t> m_layerOf; // pathToNearestStraightest: the wave layer a cell was reached in
};

} // namespace pf::plan
