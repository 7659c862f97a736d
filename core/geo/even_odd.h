// Point in polygon by the even-odd rule alone, for hot loops whose points never lie on a boundary.
#pragma once

#include "core/geo/types.h"

namespace pf::geo {

// True if p lies inside the ring by the even-odd rule (a point on the ring may go either way:
// geo::contains answers that case, at the cost of a distance scan).
inline bool insideEvenOdd(const Ring& r, const Vec2& p) {
    bool inside = false;
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
        if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
            p.x() < (r[j].x() - r[i].x()) * (p.y() - r[i].y()) / (r[j].y() - r[i].y()) + r[i].x())
            inside = !inside;
    return inside;
}

// The same over the outer ring and the holes.
inline bool insideEvenOdd(const Polygon& poly, const Vec2& p) {
    bool inside = insideEvenOdd(poly.outer, p);
    for (const auto& h : poly.holes)
        inside = inside != insideEvenOdd(h, p);
    return inside;
}

} // namespace pf::geo
