// CellPath: a planner's output, the ordered cells an aircraft flies over.
#pragma once

#include <vector>

namespace pf::plan {

struct CellPath {
    std::vector<int> cells;     // grid cell indices in flight order
    std::vector<bool> revisit;  // same size: true where the cell was already photographed (transit)
    int jumps = 0;              // consecutive cells that are not 4-adjacent (raster baseline only)
};

} // namespace pf::plan
