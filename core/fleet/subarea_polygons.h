// The subareas of a partition as polygons: the union of each aircraft's cells, clipped to the area.
#pragma once

#include "core/fleet/partition.h"
#include "core/geo/types.h"

#include <vector>

namespace pf::fleet {

// The subarea of each aircraft as polygons in local metres: the union of its cells, plus the cells
// touching the area that are not active (assigned to the nearest subarea so that nothing of the
// area is left out), clipped to `clipTo`. Neighbouring subareas share their boundary.
std::vector<geo::MultiPolygon> subareaPolygons(const grid::Grid& g, const Partition& p,
                                               const geo::MultiPolygon& clipTo);
// The union of a set of grid cells (duplicates allowed), exact: one polygon per 4-connected group
// of cells (cells touching only at a corner are separate polygons, so every ring is simple), outer
// rings counter-clockwise, holes clockwise, collinear corners left out. Empty for no cells.
geo::MultiPolygon cellsUnion(const grid::Grid& g, const std::vector<int>& cells);
// One set of cells as polygons (for estimators that plan over a candidate subarea).
geo::MultiPolygon cellsPolygon(const grid::Grid& g, const std::vector<int>& cells, const geo::MultiPolygon& clipTo);

} // namespace pf::fleet
