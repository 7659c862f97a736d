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

namespace {

// The cells in their bounding box (grid units: a cell (c, r) spans [c, c+1] x [r, r+1]), with a
// border of empty cells so that every lookup stays inside. -2 marks a cell not in the set, else
// its 4-connected component (-1 before labelling).
struct CellBox {
    int c0 = 0, r0 = 0, w = 0, h = 0; // first column and row; cells of the padded box
    std::vector<int> label;
    int& at(int x, int y) { return label[static_cast<std::size_t>(y) * w + x]; }
    int at(int x, int y) const { return label[static_cast<std::size_t>(y) * w + x]; }
};

CellBox boxOf(const grid::Grid& g, const std::vector<int>& cells) {
    int c0 = g.cols(), c1 = -1, r0 = g.rows(), r1 = -1;
    for (int i : cells) {
        c0 = std::min(c0, i % g.cols());
        c1 = std::max(c1, i % g.cols());
        r0 = std::min(r0, i / g.cols());
        r1 = std::max(r1, i / g.cols());
    }
    CellBox box{c0, r0, c1 - c0 + 3, r1 - r0 + 3, {}};
    box.label.assign(static_cast<std::size_t>(box.w) * box.h, -2);
    for (int i : cells)
        box.at(i % g.cols() - c0 + 1, i / g.cols() - r0 + 1) = -1;
    return box;
}

// Labels the 4-connected components (cells that only touch at a corner are separate polygons);
// returns how many.
int labelComponents(CellBox& box) {
    int components = 0;
    std::vector<std::pair<int, int>> stack;
    for (int y = 1; y + 1 < box.h; ++y)
        for (int x = 1; x + 1 < box.w; ++x) {
            if (box.at(x, y) != -1)
                continue;
            box.at(x, y) = components;
            stack.push_back({x, y});
            while (!stack.empty()) {
                const auto [cx, cy] = stack.back();
                stack.pop_back();
                for (const auto& [nx, ny] : {std::pair{cx + 1, cy}, {cx - 1, cy}, {cx, cy + 1}, {cx, cy - 1}})
                    if (box.at(nx, ny) == -1) {
                        box.at(nx, ny) = components;
                        stack.push_back({nx, ny});
                    }
            }
            ++components;
        }
    return components;
}

// Directed boundary edges with the set on their left: 0 east, 1 north, 2 west, 3 south, from
// corner (x, y) of the padded box (corners (w+1) x (h+1)). A corner starts at most two.
constexpr int kDx[4] = {1, 0, -1, 0}, kDy[4] = {0, 1, 0, -1};
struct BoundaryEdges {
    int cw = 0;                          // corners per row
    std::vector<std::array<int, 2>> out; // per corner, the directions of the edges leaving it
    std::size_t count = 0;
};

BoundaryEdges boundaryEdges(const CellBox& box) {
    BoundaryEdges e;
    e.cw = box.w + 1;
    e.out.assign(static_cast<std::size_t>(e.cw) * (box.h + 1), {-1, -1});
    const auto addEdge = [&](int x, int y, int d) {
        auto& o = e.out[static_cast<std::size_t>(y) * e.cw + x];
        (o[0] < 0 ? o[0] : o[1]) = d;
        ++e.count;
    };
    for (int y = 1; y + 1 < box.h; ++y)
        for (int x = 1; x + 1 < box.w; ++x) {
            if (box.at(x, y) < 0)
                continue;
            if (box.at(x, y - 1) < 0)
                addEdge(x, y, 0);
            if (box.at(x + 1, y) < 0)
                addEdge(x + 1, y, 1);
            if (box.at(x, y + 1) < 0)
                addEdge(x + 1, y + 1, 2);
            if (box.at(x - 1, y) < 0)
                addEdge(x, y + 1, 3);
        }
    return e;
}

using CornerLoop = std::vector<std::array<int, 2>>;

// The rings of the closed loops traced, by component: a counter-clockwise loop is its component's
// shell, a clockwise one a hole in it.
class RingCollector {
public:
    RingCollector(const grid::Grid& g, const CellBox& box, int components)
        : m_box(box), m_shells(static_cast<std::size_t>(components)),
          m_shellRings(static_cast<std::size_t>(components), 0) {
        const double a = g.angleDeg() * M_PI / 180.0;
        m_u = geo::Vec2(std::cos(a), std::sin(a));
        m_v = geo::Vec2(-std::sin(a), std::cos(a));
        m_origin = g.origin();
        m_cellSize = g.cellSize();
    }

    // One simple closed loop of corners (each corner once) into a ring: only the corners where the
    // boundary turns, its orientation telling a shell (counter-clockwise) from a hole.
    void add(const CornerLoop& loop) {
        const std::size_t n = loop.size();
        const int d = loop[1][0] > loop[0][0]   ? 0
                      : loop[1][1] > loop[0][1] ? 1
                      : loop[1][0] < loop[0][0] ? 2
                                                : 3;
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
            m_shells[static_cast<std::size_t>(comp)].outer = std::move(ring);
            ++m_shellRings[static_cast<std::size_t>(comp)];
        } else {
            m_holes.emplace_back(comp, std::move(ring));
        }
    }

    // The polygons, or nothing when a component did not get exactly one shell (not expected).
    geo::MultiPolygon polygons() {
        if (std::any_of(m_shellRings.begin(), m_shellRings.end(), [](int n) { return n != 1; }))
            return {};
        for (auto& [comp, ring] : m_holes)
            m_shells[static_cast<std::size_t>(comp)].holes.push_back(std::move(ring));
        return std::move(m_shells);
    }

private:
    // The cell on the left of edge d from corner (x, y).
    int leftCell(int x, int y, int d) const {
        constexpr int lx[4] = {0, -1, -1, 0}, ly[4] = {0, 0, -1, -1};
        return m_box.at(x + lx[d], y + ly[d]);
    }
    geo::Vec2 corner(int x, int y) const {
        return m_origin + (x - 1 + m_box.c0) * m_cellSize * m_u +
               (y - 1 + m_box.r0) * m_cellSize * m_v;
    }

    const CellBox& m_box;
    geo::Vec2 m_u, m_v, m_origin;
    double m_cellSize = 0.0;
    std::vector<geo::Polygon> m_shells;
    std::vector<int> m_shellRings;
    std::vector<std::pair<int, geo::Ring>> m_holes; // component, ring
};

// Traces every boundary edge into closed loops handed to `rings`; false if a boundary stays open or
// an edge unused (not expected).
bool traceLoops(BoundaryEdges& e, int w, int h, RingCollector& rings) {
    std::size_t used = 0;
    std::vector<int> onPath(e.out.size(), -1); // position of a corner on the path being traced
    CornerLoop path;
    for (int sy = 0; sy <= h && used < e.count; ++sy)
        for (int sx = 0; sx <= w && used < e.count; ++sx) {
            if (e.out[static_cast<std::size_t>(sy) * e.cw + sx][0] < 0)
                continue;
            // Trace one closed boundary from here. Where two cells of the set touch diagonally, it
            // turns left, round the cell it came along, so that cells touching at a corner only are
            // separate polygons; a polygon touching itself at a corner (a group of cells closing
            // round a hole diagonally) passes the corner twice, and the path is cut there into a
            // shell and a hole touching at that point, as a valid polygon may.
            int x = sx, y = sy, prev = -1;
            path.clear();
            while (true) {
                const std::size_t id = static_cast<std::size_t>(y) * e.cw + x;
                if (onPath[id] >= 0) {
                    // Back at a corner of the path: what lies after it is a closed loop.
                    const auto from = path.begin() + onPath[id];
                    CornerLoop loop(from, path.end());
                    for (const auto& p : loop)
                        onPath[static_cast<std::size_t>(p[1]) * e.cw + p[0]] = -1;
                    path.erase(from, path.end());
                    rings.add(loop);
                }
                auto& o = e.out[id];
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
                x += kDx[take];
                y += kDy[take];
                prev = take;
            }
            if (!path.empty())
                return false;
        }
    return used == e.count;
}

} // namespace

geo::MultiPolygon cellsUnion(const grid::Grid& g, const std::vector<int>& cells) {
    if (cells.empty())
        return {};
    CellBox box = boxOf(g, cells);
    const int components = labelComponents(box);
    BoundaryEdges edges = boundaryEdges(box);
    RingCollector rings(g, box, components);
    if (!traceLoops(edges, box.w, box.h, rings))
        return {}; // not expected; the caller falls back to a polygon union
    return rings.polygons(); // empty if not as expected: the caller falls back likewise
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
