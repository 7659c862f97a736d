// Per-aircraft grids over the subareas of a partition (paper 001, section V.B, fig. 11.b).
#pragma once

#include "core/geo/types.h"
#include "core/grid/grid.h"
#include "core/result.h"

#include <string>
#include <vector>

namespace pf::fleet {

// One grid per aircraft, built over its subarea with its own cell size and the mission's no-fly
// zones. The cells to visit are those touching the subarea, so neighbouring aircraft overlap by at
// most one of their cells along a shared boundary and no strip is left between them. `names` label
// the errors ("Aircraft "X": ..."); sizes of the three lists must match.
Result<std::vector<grid::Grid>> buildAircraftGrids(const std::vector<geo::MultiPolygon>& subareas,
                                                   const std::vector<geo::Polygon>& noFly,
                                                   const std::vector<grid::GridOptions>& options,
                                                   const std::vector<std::string>& names);

} // namespace pf::fleet
