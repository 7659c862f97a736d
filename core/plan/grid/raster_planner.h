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

// The original algorithm as the paper describes it (Santamaria et al., section V: it "didn't provide a
// safe path to fly from the current position to the next free cell" only "when all neighbor cells next
// to the current position have been visited"): a walk over neighbouring cells that scans the area line
// by line (rows, or columns when `byColumns`). At each cell it continues along the line; at the end of
// the line it steps to the next line (towards the side of the start with more lines) and reverses; if
// that is not free either, to the previous line, then back along the line. Only when no neighbour is
// free does it jump to the nearest unvisited cell (straight-line distance, then lowest index), which is
// the transition the paper counts as a jump. Unlike rasterSweep it never flies across a gap while a
// neighbour is still free, so contour teeth and holes cut its lines (the paper's figure 7b).
CellPath rasterWalk(const grid::Grid& g, int start, bool byColumns);

// The better of the row walk and the column walk (rasterWalk) (fewer turns, then shorter distance), with
// transit paths from the take-off cell and to the landing cell.
Result<CellPath> planRaster(const grid::Grid& g, const CoverageRequest& req);

} // namespace pf::plan
