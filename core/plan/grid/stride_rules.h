// The paper's stride rules (Santamaria et al., section IV): a cell's limits and how far a stride grows.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/grid/grid_search.h"

#include <cstdint>
#include <vector>

namespace pf::plan {

// Sides of a cell, relative to a stride direction, where a limit lies (bit set):
constexpr unsigned kLeftLimit = 1u;  // on the left of the stride direction
constexpr unsigned kRightLimit = 2u; // on the right

// The limits of cell c orthogonal to direction d (the paper's L(c), with the side of each). A side is a
// limit when the move there is not allowed (the neighbour is outside the area, not visitable, past the
// grid's edge, or the straight segment to it is unsafe) or when the neighbour is already visited.
unsigned strideLimits(const grid::Grid& g, const std::vector<std::uint8_t>& visited, int c, grid::Dir d);

// Why a stride stopped growing.
enum class StrideStop {
    None,              // no stride: the first cell is visited or cannot be reached
    AreaLimit,         // the next cell is visited, not visitable, or the move to it is not allowed
    NoLimit,           // rule (1): L(cn) = 0
    LimitCountDiffers, // rule (2): L(cn) != L(c0)
    LimitOppositeSide, // rule (3): L(cn) = 1 with the limit on the other side than c0's
};

struct Stride {
    grid::Dir dir = grid::Dir::East;
    std::vector<int> cells; // the new cells, c0 excluded; the paper's length is cells.size() + 1
    StrideStop stop = StrideStop::None;
    int length() const { return cells.empty() ? 0 : static_cast<int>(cells.size()) + 1; }
};

// The longest stride from c0 in direction d under the paper's rules: the first neighbour is always
// taken; each further cell cn after the last cell cl is added when it is unvisited and reachable and
// either L(cl) = 2, or L(cn) equals L(c0) with the limits on the same sides (L(cn) != 0).
Stride buildStride(const grid::Grid& g, const std::vector<std::uint8_t>& visited, int c0, grid::Dir d);

namespace detail {

// The stride walk's inner steps, with directions as 0..3 (grid::Dir order); inline because the walk
// calls them for every candidate.
inline int popcount2(unsigned m) { return static_cast<int>((m & 1u) + ((m >> 1) & 1u)); }

// True if the side of c in direction s is a limit: no allowed move there, or the neighbour is visited.
inline bool blocked(const grid::Grid& g, const std::vector<std::uint8_t>& visited, int c, int s) {
    return !g.canMove(c, static_cast<grid::Dir>(s)) || visited[c + dirOffset(g, s)] != 0;
}

inline unsigned limitsOf(const grid::Grid& g, const std::vector<std::uint8_t>& visited, int c, int d) {
    const int left = (d + 1) % 4, right = (d + 3) % 4;
    return (blocked(g, visited, c, left) ? kLeftLimit : 0u) | (blocked(g, visited, c, right) ? kRightLimit : 0u);
}

// Grows a stride; writes its new cells to `out` (cleared) and returns why it stopped. `full` grows it to
// the area limit, ignoring the limit rules (a lane's whole length).
StrideStop growStride(const grid::Grid& g, const std::vector<std::uint8_t>& visited, int c0, int d,
                      std::vector<int>& out, bool full = false);

} // namespace detail

} // namespace pf::plan
