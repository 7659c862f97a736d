// Lanes from a grid planner's cell path: maximal straight runs become straight lanes with exact ends.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/cell_path.h"
#include "core/plan/lanes/lane.h"
#include "core/sensor/camera.h"

#include <vector>

namespace pf::route {

// A piece of the cell path that is photographed together, in flight order.
// - A lane: consecutive photographed cells of one straight run of the path (one grid direction). Its
//   strip is the union of the cells; its ends are where the admissible ground of the end cells begins
//   and ends along the lane's line (exact geometry, not the cell staircase), so the aircraft turns
//   where its photos have covered the area, not half a cell outside it. Photos follow plan::makeLane:
//   the trigger distance apart, along the line through the cells' centres, so a lane is flown straight.
// - A cell group: photographed cells the lane's line cannot fly through (a no-fly margin crosses their
//   part of the line, or the flight position is shifted off it) or reached by diagonal steps: they keep
//   the per-cell photos around their flight positions (paper 001's rule, with the safe placement of
//   photoWaypoints), so the aircraft flies round the margin as the grid allows.
// Every photographed occurrence of the path belongs to exactly one group; transit occurrences to none.
struct PathGroup {
    bool lane = false;
    int first = 0; // occurrences [first, last] of the cell path
    int last = 0;
    plan::Lane strip; // lanes only
    // Lanes only: the occurrences [firstClean, lastClean] whose cells the lane's line crosses safely
    // (first and last may be cells a margin cuts, flown only up to the margin's edge).
    int firstClean = 0;
    int lastClean = 0;
};

// Choices, documented here and tested:
// - Runs: consecutive photographed occurrences joined by the same unit grid step. A cell where the path
//   turns from one run to the next belongs to the longer of the two (ties: the earlier), so a lane
//   change in a back-and-forth pattern is a connector without photos between two full lanes.
// - A single photographed cell between two turns is a lane one cell long, oriented by the step into it.
// - A cell is flown on the lane's line ("clean") when it is Free and the line's part through it (up to
//   the strip's ends) keeps the grid's buffered margins (Grid::segmentIsSafe); maximal runs of clean
//   cells are lanes, the other cells of the run cell groups.
// - A lane that runs into a no-fly margin ends at the margin: the cell the margin cuts joins the lane,
//   flown up to the margin's edge with the photos beyond it moved back there (plan::makeLane with a
//   flyable part), when the real footprints of the lane's photos then still see all of that cell's
//   admissible ground (measured exactly, 0.1 % of the cell allowed for rounding); otherwise it stays a
//   cell group. Both ends of a lane are tried.
// - The track spacing is the cell side: when the effective footprint across the track is narrower than
//   the cell (overlaps that make the photo spacing the longer side), one line per cell would leave gaps,
//   so every cell is a cell group.
std::vector<PathGroup> cellPathGroups(const grid::Grid& g, const plan::CellPath& path,
                                      const sensor::EffectiveFootprint& fp);

} // namespace pf::route
