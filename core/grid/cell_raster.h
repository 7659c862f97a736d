// Row-span rasterisation of polygons onto the cell grid: the cells a region covers, with exact
// geometry only for the cells its boundary crosses.
#pragma once

#include "core/geo/types.h"

#include <cstdint>
#include <vector>

namespace pf::grid::detail {

enum Mark : std::uint8_t { kOut = 0, kIn = 1, kEdge = 2 };

// A ring in grid units (cell (c, r) is the unit square [c, c+1] x [r, r+1]), with the sign its clipped
// signed area takes in the region's area (outer rings count positive, holes negative, whatever the
// orientation the geometry library returned).
struct URing {
    std::vector<geo::Vec2> pts;
    double sign = 1.0;
    double minX = 0, maxX = 0, minY = 0, maxY = 0;
};

// The rotation between the local frame and the grid frame.
struct Frame {
    geo::Vec2 origin{0, 0};
    double c = 1.0, s = 0.0, size = 1.0;
    geo::Vec2 toGrid(const geo::Vec2& p) const { // local metres -> grid units
        const geo::Vec2 d = p - origin;
        return geo::Vec2(c * d.x() + s * d.y(), -s * d.x() + c * d.y()) / size;
    }
    geo::Vec2 toLocal(const geo::Vec2& u) const {
        return origin + size * geo::Vec2(c * u.x() - s * u.y(), s * u.x() + c * u.y());
    }
};

// The rings of a region in grid units.
std::vector<URing> makeURings(const geo::MultiPolygon& mp, const Frame& f);

// Marks every cell whose closed square an edge of the rings touches as kEdge, the others kIn or kOut.
std::vector<std::uint8_t> rasterise(const std::vector<URing>& rings, int cols, int rows);

// Replaces the kEdge marks by kIn or kOut from the exact area of the cell inside the region.
void resolveEdgeCells(std::vector<std::uint8_t>& mark, const std::vector<URing>& rings, int cols, int rows);

} // namespace pf::grid::detail
