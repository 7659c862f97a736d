// The stride planner (Santamaria et al., section IV): long straight strides, few turns, no jumps.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/cell_path.h"
#include "core/plan/planner.h"
#include "core/result.h"

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

// What happened while planning, for tests and reports.
struct StrideTrace {
    // Cells photographed after each stride or dead-end transit (counts, so they survive the clean-up,
    // which only removes transit occurrences).
    std::vector<int> segmentEnds;
    struct Partition {
        int photographed = 0;        // cells photographed when the split was found
        std::vector<int> partSizes;  // sizes of the parts found closed off (the rest is larger)
        int chosenSize = 0;          // the part visited first (the smallest)
    };
    std::vector<Partition> partitions;
    int deadEnds = 0;
    int partitionSearches = 0; // searches started because a local test could not rule out a split
    std::size_t scratchBytes = 0; // heap bytes of the planner's per-cell working arrays
};

// A rule variant of the planner. The paper's rules take the longest stride; on areas whose lanes are
// long in one direction that greedy choice often turns across the lanes (a long stride up the side of
// the area) and leaves short pieces behind. A lane variant cuts such a stride to its first step (a lane
// change) when the next lane is at least 1 / laneWeight as long as the whole stride.
struct StrideVariant {
    double laneWeight = 0.0; // 0: the paper's rules only
    int laneAxis = -1;       // lane axis before the first long stride: -1 none, 0 east-west, 1 north-south
    // Lead-in: -1 none; else the cell where coverage starts: the path first flies there from the start
    // without photographing (the shortest, straightest path over allowed moves). Starting in the middle
    // of an edge leaves the other half of the edge to come back to, and lanes flown towards a receding
    // side of the area need a way back at each step: starting at an end of the edge or at a corner of
    // the area avoids both for the price of the lead-in.
    int leadTo = -1;
};

// The variants planStride compares from `start`: the paper's rules first, then lane variants.
std::vector<StrideVariant> strideVariants(const grid::Grid& g, int start);

// Plans with one variant (the paper's rules by default). See planStride.
Result<CellPath> planStrideVariant(const grid::Grid& g, const CoverageRequest& req, const StrideVariant& variant,
                                   StrideTrace* trace = nullptr);

// Plans a complete coverage path with the stride rules, the partition rule (smallest part first),
// distance-transform paths out of dead ends, clean-up of removable revisits, and transit paths from the
// take-off cell and to the landing cell. Every variant of strideVariants(g) is planned from the same
// start and the best path by `choice` is kept (the earlier variant on a tie); `trace` describes it.
Result<CellPath> planStride(const grid::Grid& g, const CoverageRequest& req, StrideTrace* trace = nullptr,
                            const StrideChoice& choice = {});

// The paper's clean-up: removes each sequence of transit occurrences that joins two cells which are
// the same or joined by an allowed move. Photographed occurrences are never removed.
void cleanUpRevisits(const grid::Grid& g, CellPath& path);

// Appends a transit path from the path's last cell to `to` (shortest over allowed moves; a jump if no
// allowed path exists). Used for landing paths by every planner.
void appendTransit(const grid::Grid& g, CellPath& path, int to);

} // namespace pf::plan
