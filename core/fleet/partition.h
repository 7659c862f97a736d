// Splitting a shared area between several aircraft: flood-fill partition of the cells of a base grid
// (paper 001, section V) with redistribution to target sizes. Balancing on flight time is in
// time_balance.h, the subareas' polygons in subarea_polygons.h.
#pragma once

#include "core/result.h"

#include <vector>

namespace pf::grid {
class Grid;
}

namespace pf::fleet {

struct Partition {
    std::vector<int> owner;              // per grid cell: aircraft index, -1 where no visit is needed
    std::vector<std::vector<int>> cells; // per aircraft: its base cells, ascending
    std::vector<int> targets;            // per aircraft: the cell count its share asked for
    // Subareas made of several pieces. Only happens when the area itself falls apart into more
    // pieces (separated by no-fly zones) than there are aircraft to give one each.
    int disconnectedSubareas = 0;
};

// Splits the cells that need a visit (Grid::needsVisit) between aircraft in proportion to `shares`
// (positive; normalised here):
//  1. integer targets by largest remainder;
//  2. one seed per aircraft, taken in turn at the far end of the cells still free (a double BFS
//     sweep), so the subareas line up instead of boxing each other in;
//  3. flood-fill growth to the target, preferring the free cell with the most 4-neighbours already
//     in the subarea (paper fig. 8), then the one with the most walls (edge, hole, other subarea),
//     then the one nearest the sweep's start;
//  4. cells left free afterwards (paper fig. 9) join an adjacent subarea, as whole pieces;
//  5. redistribution: boundary cells move, one at a time, from subareas above target towards the
//     nearest subarea below it (through intermediate subareas if needed), never disconnecting the
//     subarea that gives the cell.
// Every subarea is connected through the grid's allowed moves whenever the area itself is
// connected. Errors: no shares, a share not positive, fewer active cells than aircraft;
// ErrorCode::Cancelled when the thread's job is cancelled (stopRequested()).
Result<Partition> partitionCells(const grid::Grid& g, const std::vector<double>& shares);

// True if `cells` (non-empty) form one piece through the grid's allowed moves.
bool isConnected(const grid::Grid& g, const std::vector<int>& cells);

} // namespace pf::fleet
