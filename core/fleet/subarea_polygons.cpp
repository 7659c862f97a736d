// Subarea polygons: row runs of cells united and clipped; area-touching cells without a visit
// go to the nearest subarea so that the subareas tile the whole area.
#include "core/fleet/subarea_polygons.h"

#include "core/fleet/cell_assignment.h"
#include "core/geo/polygon_ops.h"
#include "core/grid/grid.h"

#include <algorithm>
#include <deque>
#include <limits>

namespace pf::fleet {

geo::MultiPolygon cellsPolygon(const grid::Grid& g, const std::vector<int>& cells, const geo::MultiPolygon& clipTo) {
    if (cells.empty())
        return {};
    // Runs of consecutive cells in a row become one rectangle: far fewer pieces for GEOS to unite.
    std::vector<int> sorted = cells;
    std::sort(sorted.begin(), sorted.end());
    geo::MultiPolygon rects;
    for (std::size_t i = 0; i < sorted.size();) {
        std::size_t j = i;
        while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1 && sorted[j + 1] / g.cols() == sorted[i] / g.cols())
            ++j;
        const auto a = baseCellSquare(g, sorted[i]);
        const auto b = baseCellSquare(g, sorted[j]);
        rects.push_back(geo::Polygon{{a[0], b[1], b[2], a[3]}, {}});
        i = j + 1;
    }
    auto merged = geo::unite(rects);
    if (clipTo.empty())
        return merged;
    geo::MultiPolygon out;
    for (const auto& clip : clipTo)
        for (auto& piece : geo::intersection(merged, clip))
            out.push_back(std::move(piece));
    return out;
}

std::vector<geo::MultiPolygon> subareaPolygons(const grid::Grid& g, const Partition& p, const geo::MultiPolygon& clipTo) {
    // Cells touching the area but not active (no flyable point) still hold some of the area: give
    // each to the nearest subarea (8-neighbour BFS from the assigned cells, then plain distance).
    std::vector<int> owner = p.owner;
    auto touches = [&](int c) { return g.state(c) != grid::CellState::Outside; };
    std::deque<int> q;
    for (int c = 0; c < g.cellCount(); ++c)
        if (owner[static_cast<std::size_t>(c)] >= 0)
            q.push_back(c);
    while (!q.empty()) {
        const int c = q.front();
        q.pop_front();
        const int cx = c % g.cols(), cy = c / g.cols();
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = cx + dx, y = cy + dy;
                if ((dx == 0 && dy == 0) || x < 0 || y < 0 || x >= g.cols() || y >= g.rows())
                    continue;
                const int nb = y * g.cols() + x;
                if (owner[static_cast<std::size_t>(nb)] >= 0 || !touches(nb))
                    continue;
                owner[static_cast<std::size_t>(nb)] = owner[static_cast<std::size_t>(c)];
                q.push_back(nb);
            }
    }
    for (int c = 0; c < g.cellCount(); ++c) {
        if (!touches(c) || owner[static_cast<std::size_t>(c)] >= 0)
            continue;
        double bestD = std::numeric_limits<double>::infinity();
        for (int x = 0; x < g.cellCount(); ++x)
            if (p.owner[static_cast<std::size_t>(x)] >= 0) {
                const double d = (baseCellCenter(g, x) - baseCellCenter(g, c)).squaredNorm();
                if (d < bestD) {
                    bestD = d;
                    owner[static_cast<std::size_t>(c)] = p.owner[static_cast<std::size_t>(x)];
                }
            }
    }
    std::vector<std::vector<int>> cells(p.cells.size());
    for (int c = 0; c < g.cellCount(); ++c)
        if (owner[static_cast<std::size_t>(c)] >= 0)
            cells[static_cast<std::size_t>(owner[static_cast<std::size_t>(c)])].push_back(c);
    std::vector<geo::MultiPolygon> out;
    for (const auto& cs : cells)
        out.push_back(cellsPolygon(g, cs, clipTo));
    return out;
}

} // namespace pf::fleet
