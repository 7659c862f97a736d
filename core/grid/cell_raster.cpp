// Row-span rasterisation of polygons onto the cell grid (see cell_raster.h).
#include "core/grid/cell_raster.h"

#include "core/geo/half_plane_clip.h"
#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace pf::grid::detail {

using geo::Vec2;

namespace {

// A cell overlapping the admissible area by less than this fraction of its own area is left Outside:
// such slivers come from rounding where a boundary runs along a cell edge, and photographing a cell for
// a millionth of its area would only add detours.
constexpr double kSliverFraction = 1e-6;
// Slack (in cells) when marking the cells an edge touches: marking one cell too many only costs an
// exact test, missing one would misclassify it.
constexpr double kEdgeEps = 1e-9;

URing makeURing(const geo::Ring& ring, const Frame& f, bool hole) {
    URing u;
    u.pts.reserve(ring.size());
    for (const auto& p : ring)
        u.pts.push_back(f.toGrid(p));
    const double sa = geo::signedArea(u.pts);
    u.sign = (hole ? -1.0 : 1.0) * (sa >= 0 ? 1.0 : -1.0);
    const geo::Box b = geo::bounds(u.pts);
    u.minX = b.min.x();
    u.maxX = b.max.x();
    u.minY = b.min.y();
    u.maxY = b.max.y();
    return u;
}

} // namespace

std::vector<URing> makeURings(const geo::MultiPolygon& mp, const Frame& f) {
    std::vector<URing> out;
    for (const auto& poly : mp) {
        if (poly.outer.size() >= 3)
            out.push_back(makeURing(poly.outer, f, false));
        for (const auto& h : poly.holes)
            if (h.size() >= 3)
                out.push_back(makeURing(h, f, true));
    }
    return out;
}

// Marks every cell whose closed square an edge of the rings touches as kEdge, then fills the remaining
// cells row by row: a cell no edge touches is entirely inside or entirely outside, which the even-odd
// rule at its centre decides.
std::vector<std::uint8_t> rasterise(const std::vector<URing>& rings, int cols, int rows) {
    std::vector<std::uint8_t> mark(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows), kOut);
    std::vector<std::pair<int, double>> crossings;
    for (const auto& ring : rings) {
        const std::size_t n = ring.pts.size();
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2& a = ring.pts[i];
            const Vec2& b = ring.pts[(i + 1) % n];
            const double ylo = std::min(a.y(), b.y()), yhi = std::max(a.y(), b.y());
            // Cells touched by the edge.
            const int r0 = std::max(0, static_cast<int>(std::floor(ylo - kEdgeEps)));
            const int r1 = std::min(rows - 1, static_cast<int>(std::floor(yhi + kEdgeEps)));
            for (int r = r0; r <= r1; ++r) {
                double y0 = std::max(ylo, static_cast<double>(r));
                double y1 = std::min(yhi, static_cast<double>(r) + 1.0);
                if (y0 > y1)
                    y0 = y1 = 0.5 * (y0 + y1);
                double xa, xb;
                if (yhi - ylo <= 0.0) {
                    xa = std::min(a.x(), b.x());
                    xb = std::max(a.x(), b.x());
                } else {
                    xa = a.x() + (b.x() - a.x()) * (y0 - a.y()) / (b.y() - a.y());
                    xb = a.x() + (b.x() - a.x()) * (y1 - a.y()) / (b.y() - a.y());
                    if (xa > xb)
                        std::swap(xa, xb);
                }
                const int c0 = std::max(0, static_cast<int>(std::floor(xa - kEdgeEps)));
                const int c1 = std::min(cols - 1, static_cast<int>(std::floor(xb + kEdgeEps)));
                for (int c = c0; c <= c1; ++c)
                    mark[static_cast<std::size_t>(r) * cols + c] = kEdge;
            }
            // Crossings with the centre lines y = r + 0.5 (half-open rule: ylo <= y < yhi).
            if (yhi > ylo) {
                const int s0 = std::max(0, static_cast<int>(std::ceil(ylo - 0.5)));
                const int s1 = std::min(rows - 1, static_cast<int>(std::ceil(yhi - 0.5)) - 1);
                for (int r = s0; r <= s1; ++r) {
                    const double y = r + 0.5;
                    crossings.emplace_back(r, a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()));
                }
            }
        }
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size();) {
        const int r = crossings[k].first;
        std::size_t end = k;
        while (end < crossings.size() && crossings[end].first == r)
            ++end;
        for (std::size_t j = k; j + 1 < end; j += 2) {
            const int c0 = std::max(0, static_cast<int>(std::ceil(crossings[j].second - 0.5)));
            const int c1 = std::min(cols - 1, static_cast<int>(std::ceil(crossings[j + 1].second - 0.5)) - 1);
            std::uint8_t* row = mark.data() + static_cast<std::size_t>(r) * cols;
            for (int c = c0; c <= c1; ++c)
                if (row[c] == kOut)
                    row[c] = kIn;
        }
        k = end;
    }
    return mark;
}

// Replaces the kEdge marks by kIn or kOut from the exact area of the cell inside the region, computed
// by clipping the rings first to the cell's row band, then to the cell's column.
void resolveEdgeCells(std::vector<std::uint8_t>& mark, const std::vector<URing>& rings, int cols, int rows) {
    struct Band {
        std::vector<Vec2> pts;
        double sign;
        double minX, maxX;
    };
    std::vector<Band> bands;
    std::vector<Vec2> tmp, tmp2;
    for (int r = 0; r < rows; ++r) {
        std::uint8_t* row = mark.data() + static_cast<std::size_t>(r) * cols;
        if (std::find(row, row + cols, static_cast<std::uint8_t>(kEdge)) == row + cols)
            continue;
        bands.clear();
        for (const auto& ring : rings) {
            if (ring.maxY < r || ring.minY > r + 1)
                continue;
            geo::clipHalfPlane(ring.pts, tmp, 1, r, true);
            geo::clipHalfPlane(tmp, tmp2, 1, r + 1.0, false);
            if (tmp2.size() < 3)
                continue;
            const geo::Box b = geo::bounds(tmp2);
            bands.push_back(Band{tmp2, ring.sign, b.min.x(), b.max.x()});
        }
        for (int c = 0; c < cols; ++c) {
            if (row[c] != kEdge)
                continue;
            double a = 0.0;
            for (const auto& band : bands) {
                if (band.maxX < c || band.minX > c + 1)
                    continue;
                geo::clipHalfPlane(band.pts, tmp, 0, c, true);
                geo::clipHalfPlane(tmp, tmp2, 0, c + 1.0, false);
                a += band.sign * geo::signedArea(tmp2);
            }
            row[c] = a > kSliverFraction ? kIn : kOut;
        }
    }
}

} // namespace pf::grid::detail
