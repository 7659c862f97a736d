// CellPath: a planner's output, the ordered cells an aircraft flies over.
#pragma once

#include <vector>

namespace pf::plan {

struct CellPath {
    std::vector<int> cells;     // grid cell indices in flight order
    // Same size: true where the aircraft only passes over the cell (transit): it was already
    // photographed (a revisit), or it lies on the way from the take-off cell to the first cell and is
    // photographed later. No photo is taken at a transit occurrence.
    std::vector<bool> revisit;
    // Consecutive cells joined by no allowed move (not adjacent, or the straight segment between them
    // is unsafe). The raster baseline jumps by design; the other planners only jump between parts of
    // the area that no allowed move connects.
    int jumps = 0;
};

} // namespace pf::plan
