// OutputGrid: the mosaic's pixel grid in the output coordinate system (north up, square pixels).
#pragma once

#include "core/geo/types.h"

#include <algorithm>
#include <cmath>

namespace pf::mosaic {

// A pixel window of the grid: columns [x0, x0 + w), rows [y0, y0 + h).
struct PixelWindow {
    int x0 = 0, y0 = 0, w = 0, h = 0;
    bool empty() const { return w <= 0 || h <= 0; }
    // The smallest window holding both.
    PixelWindow united(const PixelWindow& o) const {
        if (empty())
            return o;
        if (o.empty())
            return *this;
        const int x1 = std::max(x0 + w, o.x0 + o.w), y1 = std::max(y0 + h, o.y0 + o.h);
        const int nx = std::min(x0, o.x0), ny = std::min(y0, o.y0);
        return {nx, ny, x1 - nx, y1 - ny};
    }
};

struct OutputGrid {
    double originX = 0.0; // grid x of the left edge of column 0
    double originY = 0.0; // grid y of the top edge of row 0
    double gsd = 1.0;     // metres per pixel
    int width = 0;
    int height = 0;

    // The centre of pixel (col, row) in grid coordinates.
    double x(double col) const { return originX + (col + 0.5) * gsd; }
    double y(double row) const { return originY - (row + 0.5) * gsd; }
    // Continuous pixel coordinates (GDAL convention) of a grid point.
    double col(double gx) const { return (gx - originX) / gsd; }
    double row(double gy) const { return (originY - gy) / gsd; }
    // The pixels whose centres lie in the box [minX, maxX] x [minY, maxY], clipped to the grid.
    PixelWindow window(double minX, double minY, double maxX, double maxY) const {
        const int c0 = std::max(0, static_cast<int>(std::floor(col(minX))));
        const int c1 = std::min(width, static_cast<int>(std::ceil(col(maxX))));
        const int r0 = std::max(0, static_cast<int>(std::floor(row(maxY))));
        const int r1 = std::min(height, static_cast<int>(std::ceil(row(minY))));
        return {c0, r0, std::max(0, c1 - c0), std::max(0, r1 - r0)};
    }
    void geoTransform(double gt[6]) const {
        gt[0] = originX;
        gt[1] = gsd;
        gt[2] = 0.0;
        gt[3] = originY;
        gt[4] = 0.0;
        gt[5] = -gsd;
    }
};

} // namespace pf::mosaic
