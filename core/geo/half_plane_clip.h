// Sutherland-Hodgman clip of a ring against an axis-aligned half-plane (the grid's cell areas, the
// lanes' strips).
#pragma once

#include "core/geo/types.h"

#include <vector>

namespace pf::geo {

// The part of the ring `in` where coord(axis) >= v (keepAbove) or <= v, into `out`. The result may hold
// degenerate edges along the clip line, but its signed area is exactly the signed area of the ring's
// part inside the half-plane, and its points are those of the ring inside plus the crossings.
void clipHalfPlane(const std::vector<Vec2>& in, std::vector<Vec2>& out, int axis, double v, bool keepAbove);

} // namespace pf::geo
