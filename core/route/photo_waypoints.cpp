#include "core/route/photo_waypoints.h"

#include <cmath>

namespace pf::route {

using geo::Vec2;

PhotosPerCell photosPerCell(double cellSizeM, const sensor::EffectiveFootprint& fp) {
    // A tolerance keeps a cell exactly one footprint long at one photo despite rounding.
    auto count = [cellSizeM](double len) {
        if (len <= 0)
            return 1;
        return std::max(1, static_cast<int>(std::ceil(cellSizeM / len - 1e-9)));
    };
    return {count(fp.alongM), count(fp.acrossM)};
}

double headingDeg(const Vec2& dir) {
    double h = std::atan2(dir.x(), dir.y()) * 180.0 / M_PI;
    if (h < 0)
        h += 360.0;
    if (h >= 360.0)
        h -= 360.0;
    return h;
}

std::vector<LocalWaypoint> photoWaypoints(const grid::Grid& g, const plan::CellPath& path,
                                          const sensor::EffectiveFootprint& fp) {
    std::vector<LocalWaypoint> out;
    const std::size_t n = path.cells.size();
    if (n == 0)
        return out;
    const double a = g.angleDeg() * M_PI / 180.0;
    const Vec2 ex(std::cos(a), std::sin(a)), ey(-std::sin(a), std::cos(a));
    auto stepDir = [&](std::size_t i, std::size_t j) -> Vec2 {
        const int dc = g.col(path.cells[j]) - g.col(path.cells[i]);
        const int dr = g.row(path.cells[j]) - g.row(path.cells[i]);
        const Vec2 v = dc * ex + dr * ey;
        return v.norm() > 0 ? Vec2(v.normalized()) : ex;
    };
    const double cell = g.cellSize();
    const PhotosPerCell ppc = photosPerCell(cell, fp);
    const double sAlong = cell / ppc.along, sAcross = cell / ppc.across;
    bool anyPhoto = false;
    for (std::size_t i = 0; i < n; ++i) {
        const int c = path.cells[i];
        const Vec2 p = g.flightPosition(c);
        const Vec2 in = i > 0 ? stepDir(i - 1, i) : (n > 1 ? stepDir(0, 1) : ex);
        const Vec2 outDir = i + 1 < n ? stepDir(i, i + 1) : in;
        const bool turns = (in - outDir).norm() > 1e-9;
        if (path.revisit[i]) {
            if (turns || i == 0 || i + 1 == n) {
                // Cells flown over before their photo (before the first photo of the path) are turn
                // points; later ones are revisits.
                out.push_back({p, headingDeg(outDir), anyPhoto ? WaypointKind::Transit : WaypointKind::Turn, c});
            }
            continue;
        }
        // Photos: the long side across `in`, spaced along it; rows across in a back-and-forth order.
        const Vec2 right(in.y(), -in.x());
        const double h = headingDeg(in);
        for (int r = 0; r < ppc.across; ++r) {
            const double across = (r + 0.5) * sAcross - cell / 2;
            for (int k0 = 0; k0 < ppc.along; ++k0) {
                const int k = (r % 2 == 0) ? k0 : ppc.along - 1 - k0;
                const double along = (k + 0.5) * sAlong - cell / 2;
                out.push_back({p + along * in + across * right, h, WaypointKind::Photo, c});
                anyPhoto = true;
            }
        }
    }
    return out;
}

} // namespace pf::route
