// Fewer vertices for detailed polygons (traced boundaries), within a tolerance.
#pragma once

#include "core/geo/types.h"

#include <cstddef>

namespace pf::geo {

// The polygon with fewer vertices, no point of its boundary more than `toleranceM` from the
// original's (GEOS Douglas-Peucker that preserves topology: rings stay simple and holes inside).
// Returns the polygon unchanged when GEOS gives back anything but one valid polygon.
Polygon simplified(const Polygon& poly, double toleranceM);

// Number of vertices of all rings.
std::size_t vertexCount(const Polygon& poly);

} // namespace pf::geo
