// Subarea polygons: row runs of cells united and clipped; area-touching cells without a visit
// go to the nearest subarea so that the subareas tile the whole area.
#include "core/fleet/subarea_polygons.h"

#include "core/fleet/cell_assignment.h"
#include "core/geo/polygon_ops.h"
#include "core/grid/grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>

namespace pf::fleet {

geo::MultiPolygon cellsUnion(const grid::Grid& g, const std::vector<int>& cells) {
    if (cells.empty())
        return {};
    // Work in the cells' bounding box (grid units: a cell (c, r) spans [c, c+1] x [r, r+1]), with a
    // border of empty cells so that every lookup stays inside.
    int c0 = g.cols(), c1 = -1, r0 = g.rows(), r1 = -1;
    for (int i : cells) {
        c0 = std::min(c0, i % g.cols());
        c1 = std::max(c1, i % g.cols());
        r0 = std::min(r0, i / g.cols());
        r1 = std::max(r1, i / g.cols());
    }
    const int w = c1 - c0 + 3, h = r1 - r0 + 3; // cells of the padded box
    std::vector<int> label(static_cast<std::size_t>(w) * h, -2); // -2 not in the set, else its component
    const auto at = [&](int x, int y) -> int& { return label[static_cast<std::size_t>(y) * w + x]; };
    for (int i : cells)
        at(i % g.cols() - c0 + 1, i / g.cols() - r0 + 1) = -1;
    // 4-connected components: cells that only touch at a corner are separate polygons.
    int components = 0;
    std::vector<std::pair<int, int>> stack;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            if (at(x, y) != -1)
                continue;
            at(x, y) = components;
            stack.push_back({x, y});
            while (!stack.empty()) {
                const auto [cx, cy] = stack.back();
                stack.pop_back();
                for (const auto& [nx, ny] : {std::pair{cx + 1, cy}, {cx - 1, cy}, {cx, cy + 1}, {cx, cy - 1}})
                    if (at(nx, ny) == -1) {
                        at(nx, ny) = components;
                        stack.push_back({nx, ny});
                    }
            }
            ++components;
        }
    // Directed boundary edges with the set on their left: 0 east, 1 north, 2 west, 3 south, from
    // corner (x, y) of the padded box (corners (w+1) x (h+1)). A corner starts at most two.
    constexpr int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
    const int cw = w + 1;
    std::vector<std::array<int, 2>> out(static_cast<std::size_t>(cw) * (h + 1), {-1, -1}); // directions
    const auto addEdge = [&](int x, int y, int d) {
        auto& o = out[static_cast<std::size_t>(y) * cw + x];
        (o[0] < 0 ? o[0] : o[1]) = d;
    };
    std::size_t edges = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            if (at(x, y) < 0)
                continue;
            if (at(x, y - 1) < 0)
                addEdge(x, y, 0), ++edges;
            if (at(x + 1, y) < 0)
                addEdge(x + 1, y, 1), ++edges;
            if (at(x, y + 1) < 0)
                addEdge(x + 1, y + 1, 2), ++edges;
            if (at(x - 1, y) < 0)
                addEdge(x, y + 1, 3), ++edges;
        }
    // The cell on the left of edge d from corner (x, y).
    const auto leftCell = [&](int x, int y, int d) {
        constexpr int lx[4] = {0, -1, -1, 0}, ly[4] = {0, 0, -1, -1};
        return at(x + lx[d], y + ly[d]);
    };
    const double a = g.angleDeg() * M_PI / 180.0;
    const geo::Vec2 u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    const auto corner = [&](int x, int y) -> geo::Vec2 {
        return g.origin() + (x - 1 + c0) * g.cellSize() * u + (y - 1 + r0) * g.cellSize() * v;
    };
    std::vector<geo::Polygon> shells(static_cast<std::size_t>(components));
    std::vector<int> shellRings(static_cast<std::size_t>(components), 0);
    std::vector<std::pair<int, geo::Ring>> holes; // component, ring
    // One simple closed loop of corners (each corner once) into a ring: only the corners where the
    // boundary turns, its orientation telling a shell (counter-clockwise) from a hole.
    const auto emit = [&](const std::vector<std::array<int, 2>>& loop) {
        const std::size_t n = loop.size();
        const int d = loop[1][0] > loop[0][0] ? 0 : loop[1][1] > loop[0][1] ? 1 : loop[1][0] < loop[0][0] ? 2 : 3;
        const int comp = leftCell(loop[0][0], loop[0][1], d);
        geo::Ring ring;
        long long twiceArea = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const auto& p = loop[(i + n - 1) % n];
            const auto& q = loop[i];
            const auto& r = loop[(i + 1) % n];
            twiceArea += static_cast<long long>(q[0]) * r[1] - static_cast<long long>(r[0]) * q[1];
            const bool straight = (q[0] - p[0]) * (r[1] - q[1]) == (q[1] - p[1]) * (r[0] - q[0]);
            if (!straight)
                ring.push_back(corner(q[0], q[1]));
        }
        if (twiceArea > 0) {
            shells[static_cast<std::size_t>(comp)].outer = std::move(ring);
            ++shellRings[static_cast<std::size_t>(comp)];
        } else {
            holes.emplace_back(comp, std::move(ring));
        }
    };
    std::size_t used = 0;
    std::vector<int> onPath(out.size(), -1); // position of a corner on the path being traced
    std::vector<std::array<int, 2>> path;
    for (int sy = 0; sy <= h && used < edges; ++sy)
        for (int sx = 0; sx <= w && used < edges; ++sx) {
            if (out[static_cast<std::size_t>(sy) * cw + sx][0] < 0)
                continue;
            // Trace one closed boundary from here. Where two cells of the set touch diagonally, it
            // turns left, round the cell it came along, so that cells touching at a corner only are
            // separate polygons; a polygon touching itself at a corner (a group of cells closing
            // round a hole diagonally) passes the corner twice, and the path is cut there into a
            // shell and a hole touching at that point, as a valid polygon may.
            int x = sx, y = sy, prev = -1;
            path.clear();
            while (true) {
                const std::size_t id = static_cast<std::size_t>(y) * cw + x;
                if (onPath[id] >= 0) {
                    // Back at a corner of the path: what lies after it is a closed loop.
                    const auto from = path.begin() + onPath[id];
                    std::vector<std::array<int, 2>> loop(from, path.end());
                    for (const auto& p : loop)
                        onPath[static_cast<std::size_t>(p[1]) * cw + p[0]] = -1;
                    path.erase(from, path.end());
                    emit(loop);
                }
                auto& o = out[id];
                if (o[0] < 0)
                    break; // every edge from here is used: the boundary is closed
                int take = o[0];
                if (o[1] >= 0 && prev >= 0) {
                    const auto rank = [&](int dd) { return (prev - dd + 5) % 4; }; // left 0, straight 1, right 2
                    take = rank(o[0]) <= rank(o[1]) ? o[0] : o[1];
                }
                if (o[0] == take) {
                    o[0] = o[1];
                    o[1] = -1;
                } else {
                    o[1] = -1;
                }
                ++used;
                onPath[id] = static_cast<int>(path.size());
                path.push_back({x, y});
                x += dx[take];
                y += dy[take];
                prev = take;
            }
            if (!path.empty())
                return {}; // an open end: not expected; the caller falls back to a polygon union
        }
    if (used != edges || std::any_of(shellRings.begin(), shellRings.end(), [](int n) { return n != 1; }))
        return {}; // not expected; the caller falls back to a polygon union
    for (auto& [comp, ring] : holes)
        shells[static_cast<std::size_t>(comp)].holes.push_back(std::move(ring));
    return shells;
}

geo::MultiPolygon cellsPolygon(const grid::Grid& g, const std::vector<int>& cells, const geo::MultiPolygon& clipTo) {
    if (cells.empty())
        return {};
    geo::MultiPolygon merged = cellsUnion(g, cells);
    if (merged.empty()) {
        // Runs of consecutive cells in a row become one rectangle: far fewer pieces for GEOS to unite.
        std::vector<int> sorted = cells;
        std::sort(sorted.begin(), sorted.end());
        geo::MultiPolygon rects;
        for (std::size_t i = 0; i < sorted.size();) {
            std::size_t j = i;
            while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1 &&
                   sorted[j + 1] / g.cols() == sorted[i] / g.cols())
                ++j;
            const auto a = baseCellSquare(g, sorted[i]);
            const auto b = baseCellSquare(g, sorted[j]);
            rects.push_back(geo::Polygon{{a[0], b[1], b[2], a[3]}, {}});
            i = j + 1;
        }
        merged = geo::unite(rects);
    }
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
