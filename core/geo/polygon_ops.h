// Operations on local-metre polygons with holes: area, containment, distance, buffer, booleans (OGR/GEOS).
#pragma once

#include "core/geo/types.h"

#include <string>

namespace pf::geo {

// Area in square metres (outer minus holes).
double area(const Polygon& poly);
double area(const MultiPolygon& polys);

// True if p lies inside the polygon or on its boundary (and not strictly inside a hole).
bool contains(const Polygon& poly, const Vec2& p);
bool contains(const MultiPolygon& polys, const Vec2& p);

// Distance from p to the nearest edge of any ring of the polygon (>= 0, inside or outside).
double distanceToBoundary(const Polygon& poly, const Vec2& p);

// The nearest point to p on any ring (outer or hole) of polys; p itself when polys is empty.
Vec2 nearestOnBoundary(const MultiPolygon& polys, const Vec2& p);

// Distance from p to the polygon (0 inside).
double distanceTo(const Polygon& poly, const Vec2& p);
double distanceTo(const MultiPolygon& polys, const Vec2& p);

// Outward (d > 0) or inward (d < 0) offset; `quadrantSegments` arcs per quarter circle.
MultiPolygon buffer(const Polygon& poly, double d, int quadrantSegments = 8);
MultiPolygon buffer(const MultiPolygon& polys, double d, int quadrantSegments = 8);

MultiPolygon unite(const MultiPolygon& polys);
MultiPolygon difference(const Polygon& a, const MultiPolygon& b);
MultiPolygon difference(const MultiPolygon& a, const MultiPolygon& b);
MultiPolygon intersection(const Polygon& a, const Polygon& b);
MultiPolygon intersection(const MultiPolygon& a, const Polygon& b);

// True if the segment ab touches the interior of any polygon (grazing the boundary is allowed).
bool segmentCrossesInterior(const MultiPolygon& polys, const Vec2& a, const Vec2& b);
bool segmentCrossesInterior(const Polygon& poly, const Vec2& a, const Vec2& b);

// GEOS validity; on failure `reason` receives GEOS's explanation (with a location when it has one).
bool isValid(const Polygon& poly, std::string* reason = nullptr);

// Axis-aligned bounding box.
struct Box {
    Vec2 min{0, 0};
    Vec2 max{0, 0};
    bool contains(const Vec2& p) const {
        return p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y();
    }
    bool intersects(const Box& o) const {
        return min.x() <= o.max.x() && o.min.x() <= max.x() && min.y() <= o.max.y() && o.min.y() <= max.y();
    }
};
Box bounds(const Ring& ring);
Box bounds(const Polygon& poly);
Box bounds(const MultiPolygon& polys);

// Signed area of an open ring (counter-clockwise positive).
double signedArea(const Ring& ring);

} // namespace pf::geo
