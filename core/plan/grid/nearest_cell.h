// The nearest cell to a given one by straight-line distance, for the planners' jumps to a part of
// the area no allowed move reaches (raster, stride and wavefront share it).
#pragma once

#include "core/grid/grid.h"

#include <algorithm>
#include <limits>

namespace pf::plan {

// What "nearest" measures: between flight positions in metres (what the aircraft flies), or between
// cell centres in whole cells (the raster baseline's original rule: Shifted cells count as centred).
enum class NearestBy { FlightPosition, CellCentre };

// The visitable cell other than `from` accepted by `wanted(cell)` that lies nearest to `from`, or -1
// if there is none. Ties: the lowest index, so the answer is the one a scan in index order keeping
// only strictly nearer cells would give. Scans square rings of growing radius around `from` and
// stops once a ring cannot hold a nearer cell, so a jump costs about the square of its length.
template <class Wanted>
int nearestCell(const grid::Grid& g, int from, Wanted wanted, NearestBy by = NearestBy::FlightPosition) {
    const int c0 = g.col(from), r0 = g.row(from);
    const geo::Vec2 p0 = g.flightPosition(from);
    double best2 = std::numeric_limits<double>::infinity();
    int best = -1;
    auto test = [&](int x, int y) {
        const int i = g.index(x, y);
        if (!g.needsVisit(i) || !wanted(i))
            return;
        const double d2 = by == NearestBy::CellCentre
                              ? static_cast<double>(x - c0) * (x - c0) + static_cast<double>(y - r0) * (y - r0)
                              : (g.flightPosition(i) - p0).squaredNorm();
        if (d2 < best2 || (d2 == best2 && i < best)) {
            best2 = d2;
            best = i;
        }
    };
    // A cell of ring k lies k cells from `from` (Chebyshev) between centres; a flight position lies
    // within half a diagonal of its centre, so flight positions are at least (k - sqrt 2) cells apart.
    auto ringCanHoldNearer = [&](int k) {
        if (by == NearestBy::CellCentre)
            return static_cast<double>(k) * k <= best2;
        const double gap = (k - 1.5) * g.cellSize();
        return k <= 1 || gap * gap <= best2;
    };
    const int maxK = std::max(g.cols(), g.rows());
    for (int k = 1; k <= maxK && ringCanHoldNearer(k); ++k) {
        const int x0 = std::max(0, c0 - k), x1 = std::min(g.cols() - 1, c0 + k);
        if (r0 - k >= 0)
            for (int x = x0; x <= x1; ++x)
                test(x, r0 - k);
        if (r0 + k < g.rows())
            for (int x = x0; x <= x1; ++x)
                test(x, r0 + k);
        const int y0 = std::max(0, r0 - k + 1), y1 = std::min(g.rows() - 1, r0 + k - 1);
        if (c0 - k >= 0)
            for (int y = y0; y <= y1; ++y)
                test(c0 - k, y);
        if (c0 + k < g.cols())
            for (int y = y0; y <= y1; ++y)
                test(c0 + k, y);
    }
    return best;
}

} // namespace pf::plan
