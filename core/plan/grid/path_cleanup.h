// Repairs of a finished cell path: the transit to a cell (landing paths) and the removal of revisits.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/cell_path.h"

namespace pf::plan {

// The paper's clean-up: removes each sequence of transit occurrences that joins two cells which are
// the same or joined by an allowed move. Photographed occurrences are never removed.
void cleanUpRevisits(const grid::Grid& g, CellPath& path);

// Appends a transit path from the path's last cell to `to` (shortest over allowed moves; a jump if no
// allowed path exists). Used for landing paths by every planner.
void appendTransit(const grid::Grid& g, CellPath& path, int to);

} // namespace pf::plan
