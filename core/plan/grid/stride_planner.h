// The stride planner (Santamaria et al., section IV): long straight strides, few turns, no jumps.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/cell_path.h"
#include "core/plan/grid/path_cleanup.h"
#include "core/plan/grid/stride_rules.h"
#include "core/plan/planner.h"
#include "core/result.h"

#include <cstdint>
#include <vector>

namespace pf::plan {

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

} // namespace pf::plan
