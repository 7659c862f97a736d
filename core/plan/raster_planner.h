// The raster baseline the paper compares against: boustrophedon row by row or column by column.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/cell_path.h"
#include "core/plan/planner.h"
#include "core/result.h"

namespace pf::plan {

// One boustrophedon sweep from `start`: the start's line (row, or column when `byColumns`) first,
// beginning with the longer side of the start, then the following lines towards the side of the
// area with more lines, then the lines on the other side. Each line is flown from the end nearer to
// the previous cell, and lists all of its visitable cells, so gaps and line changes may be jumps
// between non-adjacent cells (the original algorithm did not plan safe transits).
CellPath rasterSweep(const grid::Grid& g, int start, bool byColumns);

// The better of the row sweep and the column sweep (fewer turns, then shorter distance), with
// transit paths from the take-off cell and to the landing cell.
Result<CellPath> planRaster(const grid::Grid& g, const CoverageRequest& req);

} // namespace pf::plan
