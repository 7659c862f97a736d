#include "core/plan/sweep/decomposition.h"

#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pf::plan {

using geo::Vec2;

namespace {

// The sweep's order: by y, then x (an infinitesimal rotation that makes every edge rise or fall).
bool lexLess(const Vec2& a, const Vec2& b) { return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x()); }

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// x of the chain at y: the narrower side where it runs horizontally (wantMax for a left chain).
double chainX(const std::vector<Vec2>& c, double y, bool wantMax) {
    if (c.empty())
        return 0.0;
    if (y <= c.front().y()) {
        // every point at the bottom height counts (a chain may start with a horizontal run)
        double x = c.front().x();
        for (const auto& p : c) {
            if (p.y() > c.front().y())
                break;
            x = wantMax ? std::max(x, p.x()) : std::min(x, p.x());
        }
        return x;
    }
    if (y >= c.back().y()) {
        double x = c.back().x();
        for (auto it = c.rbegin(); it != c.rend() && it->y() >= c.back().y(); ++it)
            x = wantMax ? std::max(x, it->x()) : std::min(x, it->x());
        return x;
    }
    // first point with p.y >= y
    auto it = std::lower_bound(c.begin(), c.end(), y, [](const Vec2& p, double v) { return p.y() < v; });
    if (it->y() == y) {
        double x = it->x();
        for (auto j = it; j != c.end() && j->y() == y; ++j)
            x = wantMax ? std::max(x, j->x()) : std::min(x, j->x());
        return x;
    }
    const Vec2& b = *it;
    const Vec2& a = *(it - 1);
    return a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
}

// Extreme x of the chain between heights y1 <= y2.
double chainExtreme(const std::vector<Vec2>& c, double y1, double y2, bool wantMin) {
    double x = chainX(c, y1, !wantMin);
    const double x2 = chainX(c, y2, !wantMin);
    x = wantMin ? std::min(x, x2) : std::max(x, x2);
    auto it = std::upper_bound(c.begin(), c.end(), y1, [](double v, const Vec2& p) { return v < p.y(); });
    for (; it != c.end() && it->y() < y2; ++it)
        x = wantMin ? std::min(x, it->x()) : std::max(x, it->x());
    return x;
}

struct Edge {
    Vec2 lo{0, 0}, hi{0, 0}; // lexicographically lower and upper end
    double xAt(double y) const {
        const double dy = hi.y() - lo.y();
        if (dy <= 0.0)
            return lo.x(); // horizontal: only met at its own height, where its left end bounds
        return lo.x() + (y - lo.y()) * (hi.x() - lo.x()) / dy;
    }
    bool horizontal() const { return hi.y() == lo.y(); }
};

struct Vertex {
    Vec2 p{0, 0};
    int ring = 0;
    int index = 0;
};

Error badOutline(const char* what) {
    return makeError(
        ErrorCode::InvalidGeometry,
        std::string("The area's outline could not be decomposed along the sweep direction (") +
            what + "): it may touch or cross itself.");
}

void linkCells(std::vector<MonotoneCell>& cells, int lower, int upper) {
    cells[static_cast<std::size_t>(lower)].above.push_back(upper);
    cells[static_cast<std::size_t>(upper)].below.push_back(lower);
}

// The polygons' rings in the frame, without repeated points; rings of fewer than 3 points dropped.
std::vector<std::vector<Vec2>> frameRings(const geo::MultiPolygon& polys, const SweepFrame& frame) {
    std::vector<std::vector<Vec2>> rings;
    for (const auto& poly : polys) {
        auto add = [&](const geo::Ring& ring) {
            std::vector<Vec2> r;
            r.reserve(ring.size());
            for (const auto& p : ring) {
                const Vec2 q = frame.toFrame(p);
                if (r.empty() || r.back() != q)
                    r.push_back(q);
            }
            while (r.size() > 1 && r.front() == r.back())
                r.pop_back();
            if (r.size() >= 3)
                rings.push_back(std::move(r));
        };
        add(poly.outer);
        for (const auto& h : poly.holes)
            add(h);
    }
    return rings;
}

// The sweep line moving up through the rings' vertices in (y, x) order: the edges it crosses, left
// to right, and the cell open between each pair of them.
class SweepLine {
public:
    SweepLine(const std::vector<std::vector<Vec2>>& rings, std::vector<MonotoneCell>& cells)
        : m_rings(rings), m_cells(cells) {
        buildEdges();
    }

    // Every vertex in turn; an error when the rings cannot be ordered consistently.
    Status run() {
        for (const auto& vx : m_verts) {
            const auto& ring = m_rings[static_cast<std::size_t>(vx.ring)];
            const int n = static_cast<int>(ring.size());
            const Vec2& v = vx.p;
            const Vec2& u = ring[static_cast<std::size_t>((vx.index + n - 1) % n)];
            const Vec2& w = ring[static_cast<std::size_t>((vx.index + 1) % n)];
            const int eu =
                m_ringStart[static_cast<std::size_t>(vx.ring)] + (vx.index + n - 1) % n; // u - v
            const int ew = m_ringStart[static_cast<std::size_t>(vx.ring)] + vx.index;    // v - w
            const bool uAbove = lexLess(v, u), wAbove = lexLess(v, w);
            Status st;
            if (uAbove != wAbove)
                st = regular(v, uAbove ? ew : eu, uAbove ? eu : ew);
            else if (uAbove)
                begin(v, u, w, eu, ew);
            else
                st = close(v, eu, ew);
            if (!st)
                return st;
        }
        if (!m_active.empty())
            return badOutline("the sweep ended with open edges");
        return {};
    }

private:
    // Edges: edge (ring, i) joins vertex i to vertex i + 1; the vertices in the sweep's order.
    void buildEdges() {
        m_ringStart.assign(m_rings.size() + 1, 0);
        for (std::size_t r = 0; r < m_rings.size(); ++r)
            m_ringStart[r + 1] = m_ringStart[r] + static_cast<int>(m_rings[r].size());
        m_edges.resize(static_cast<std::size_t>(m_ringStart.back()));
        m_verts.reserve(m_edges.size());
        for (std::size_t r = 0; r < m_rings.size(); ++r) {
            const auto& ring = m_rings[r];
            const int n = static_cast<int>(ring.size());
            for (int i = 0; i < n; ++i) {
                const Vec2& a = ring[static_cast<std::size_t>(i)];
                const Vec2& b = ring[static_cast<std::size_t>((i + 1) % n)];
                Edge& e = m_edges[static_cast<std::size_t>(m_ringStart[r] + i)];
                e.lo = lexLess(a, b) ? a : b;
                e.hi = lexLess(a, b) ? b : a;
                m_verts.push_back(Vertex{a, static_cast<int>(r), i});
            }
        }
        std::sort(m_verts.begin(), m_verts.end(), [](const Vertex& a, const Vertex& b) {
            if (a.p != b.p)
                return lexLess(a.p, b.p);
            return a.ring != b.ring ? a.ring < b.ring : a.index < b.index;
        });
    }

    int indexOf(int e) const {
        auto it = std::find(m_active.begin(), m_active.end(), e);
        return it == m_active.end() ? -1 : static_cast<int>(it - m_active.begin());
    }

    int newCell(const Vec2& l, const Vec2& r) {
        MonotoneCell c;
        c.left.push_back(l);
        c.right.push_back(r);
        c.ylo = l.y();
        m_cells.push_back(std::move(c));
        return static_cast<int>(m_cells.size()) - 1;
    }

    MonotoneCell& cell(int i) { return m_cells[static_cast<std::size_t>(i)]; }
    const Edge& edge(int e) const { return m_edges[static_cast<std::size_t>(e)]; }
    // x at height y of the active edge at position i.
    double activeX(int i, double y) const {
        return edge(m_active[static_cast<std::size_t>(i)]).xAt(y);
    }

    // Regular: the edge from below ends here and the one above continues the same chain.
    Status regular(const Vec2& v, int ending, int starting) {
        const int idx = indexOf(ending);
        if (idx < 0)
            return badOutline("a boundary edge was lost");
        m_active[static_cast<std::size_t>(idx)] = starting;
        auto& c = cell(m_openCell[static_cast<std::size_t>(idx / 2)]);
        (idx % 2 == 0 ? c.left : c.right).push_back(v);
        return {};
    }

    // Two edges begin: a new piece of free space (start), or an obstacle inside an interval
    // (split).
    void begin(const Vec2& v, const Vec2& u, const Vec2& w, int eu, int ew) {
        // The left one is the more counter-clockwise direction.
        const bool uLeft = cross(w - v, u - v) > 0;
        const int eL = uLeft ? eu : ew, eR = uLeft ? ew : eu;
        int pos = 0;
        for (int e : m_active) {
            const Edge& ed = edge(e);
            if (cross(ed.hi - ed.lo, v - ed.lo) < 0)
                ++pos;
            else
                break;
        }
        if (pos % 2 == 0) {
            m_active.insert(m_active.begin() + pos, {eL, eR});
            const int ci = newCell(v, v);
            cell(ci).bottomTouches.push_back(v);
            m_openCell.insert(m_openCell.begin() + pos / 2, ci);
            return;
        }
        // Split: the interval's cell ends, two begin.
        const int k = (pos - 1) / 2;
        const int ci = m_openCell[static_cast<std::size_t>(k)];
        const double xl = activeX(2 * k, v.y());
        const double xr = activeX(2 * k + 1, v.y());
        {
            auto& c = cell(ci);
            c.left.emplace_back(xl, v.y());
            c.right.emplace_back(xr, v.y());
            c.topTouches.push_back(v);
            const Edge& er = edge(eR);
            if (er.horizontal())
                c.topContacts.emplace_back(er.lo.x(), er.hi.x());
        }
        const int cl = newCell(Vec2(xl, v.y()), v);
        const int cr = newCell(v, Vec2(xr, v.y()));
        linkCells(m_cells, ci, cl);
        linkCells(m_cells, ci, cr);
        m_active.insert(m_active.begin() + pos, {eL, eR});
        m_openCell[static_cast<std::size_t>(k)] = cl;
        m_openCell.insert(m_openCell.begin() + k + 1, cr);
    }

    // Two edges end here: an interval closes (end), or an obstacle ends and the two cells beside it
    // end and one begins above it (merge).
    Status close(const Vec2& v, int eu, int ew) {
        const int iu = indexOf(eu), iw = indexOf(ew);
        if (iu < 0 || iw < 0 || std::abs(iu - iw) != 1)
            return badOutline("two closing edges are not neighbours");
        const int lo = std::min(iu, iw);
        if (lo % 2 == 0) {
            auto& c = cell(m_openCell[static_cast<std::size_t>(lo / 2)]);
            c.left.push_back(v);
            c.right.push_back(v);
            c.topTouches.push_back(v);
            m_active.erase(m_active.begin() + lo, m_active.begin() + lo + 2);
            m_openCell.erase(m_openCell.begin() + lo / 2);
            return {};
        }
        const int k = (lo - 1) / 2;
        const int c1 = m_openCell[static_cast<std::size_t>(k)],
                  c2 = m_openCell[static_cast<std::size_t>(k + 1)];
        const double xl = activeX(2 * k, v.y());
        const double xr = activeX(2 * k + 3, v.y());
        cell(c1).left.emplace_back(xl, v.y());
        cell(c1).right.push_back(v);
        cell(c2).left.push_back(v);
        cell(c2).right.emplace_back(xr, v.y());
        const int cm = newCell(Vec2(xl, v.y()), Vec2(xr, v.y()));
        cell(cm).bottomTouches.push_back(v);
        const Edge& el = edge(m_active[static_cast<std::size_t>(lo)]);
        if (el.horizontal())
            cell(cm).bottomContacts.emplace_back(el.lo.x(), el.hi.x());
        linkCells(m_cells, c1, cm);
        linkCells(m_cells, c2, cm);
        m_active.erase(m_active.begin() + lo, m_active.begin() + lo + 2);
        m_openCell[static_cast<std::size_t>(k)] = cm;
        m_openCell.erase(m_openCell.begin() + k + 1);
        return {};
    }

    const std::vector<std::vector<Vec2>>& m_rings;
    std::vector<MonotoneCell>& m_cells;
    std::vector<int> m_ringStart;
    std::vector<Edge> m_edges;
    std::vector<Vertex> m_verts;
    std::vector<int> m_active;   // edge ids crossing the sweep line, left to right
    std::vector<int> m_openCell; // cell between active[2k] and active[2k + 1]
};

// Each cell's height range, and the chains' horizontal runs along its bottom or top: boundary lies
// flat there.
void finishCells(std::vector<MonotoneCell>& cells) {
    for (auto& c : cells) {
        c.ylo = std::min(c.left.front().y(), c.right.front().y());
        c.yhi = std::max(c.left.back().y(), c.right.back().y());
        auto runs = [&](const std::vector<Vec2>& chain) {
            for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
                const Vec2 &a = chain[i], &b = chain[i + 1];
                if (a.y() != b.y() || a.x() == b.x())
                    continue;
                const std::pair<double, double> r{std::min(a.x(), b.x()), std::max(a.x(), b.x())};
                if (a.y() == c.ylo)
                    c.bottomContacts.push_back(r);
                else if (a.y() == c.yhi)
                    c.topContacts.push_back(r);
            }
        };
        runs(c.left);
        runs(c.right);
    }
}

// Drops cells without height, joining their neighbours across them, and renumbers the rest.
void dropFlatCells(std::vector<MonotoneCell>& cells) {
    std::vector<char> keep(cells.size(), 1);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        auto& c = cells[i];
        if (c.yhi - c.ylo > 1e-9)
            continue;
        keep[i] = 0;
        for (int b : c.below)
            for (int a : c.above)
                linkCells(cells, b, a);
    }
    std::vector<int> newId(cells.size(), -1);
    int next = 0;
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (keep[i])
            newId[i] = next++;
    std::vector<MonotoneCell> kept;
    kept.reserve(static_cast<std::size_t>(next));
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (!keep[i])
            continue;
        MonotoneCell c = std::move(cells[i]);
        auto remap = [&](std::vector<int>& ids) {
            std::vector<int> r;
            for (int id : ids)
                if (newId[static_cast<std::size_t>(id)] >= 0 &&
                    std::find(r.begin(), r.end(), newId[static_cast<std::size_t>(id)]) == r.end())
                    r.push_back(newId[static_cast<std::size_t>(id)]);
            ids = std::move(r);
        };
        remap(c.below);
        remap(c.above);
        kept.push_back(std::move(c));
    }
    cells = std::move(kept);
}

} // namespace

double MonotoneCell::xLeft(double y) const {
    return chainX(left, std::clamp(y, ylo, yhi), true);
}
double MonotoneCell::xRight(double y) const {
    return chainX(right, std::clamp(y, ylo, yhi), false);
}

double MonotoneCell::minLeft(double y1, double y2) const {
    y1 = std::clamp(y1, ylo, yhi);
    y2 = std::clamp(y2, ylo, yhi);
    return chainExtreme(left, std::min(y1, y2), std::max(y1, y2), true);
}

double MonotoneCell::maxRight(double y1, double y2) const {
    y1 = std::clamp(y1, ylo, yhi);
    y2 = std::clamp(y2, ylo, yhi);
    return chainExtreme(right, std::min(y1, y2), std::max(y1, y2), false);
}

geo::Ring MonotoneCell::ring() const {
    geo::Ring r;
    r.reserve(left.size() + right.size());
    auto push = [&](const Vec2& p) {
        if (r.empty() || (r.back() - p).squaredNorm() > 1e-18)
            r.push_back(p);
    };
    for (const auto& p : right)
        push(p);
    for (auto it = left.rbegin(); it != left.rend(); ++it)
        push(*it);
    if (r.size() > 1 && (r.front() - r.back()).squaredNorm() <= 1e-18)
        r.pop_back();
    return r;
}

double MonotoneCell::area() const {
    return std::abs(geo::signedArea(ring()));
}

Result<Decomposition> decompose(const geo::MultiPolygon& polys, const SweepFrame& frame) {
    Decomposition out;
    out.frame = frame;
    const std::vector<std::vector<Vec2>> rings = frameRings(polys, frame);
    if (Status st = SweepLine(rings, out.cells).run(); !st)
        return st.error();
    finishCells(out.cells);
    dropFlatCells(out.cells);
    return out;
}

std::vector<MergedCell> mergeCells(const Decomposition& d) {
    const auto& cells = d.cells;
    struct Pair {
        int lower, upper;
        double overlap;
    };
    std::vector<Pair> pairs;
    for (std::size_t i = 0; i < cells.size(); ++i)
        for (int a : cells[i].above) {
            const auto& lo = cells[i];
            const auto& up = cells[static_cast<std::size_t>(a)];
            const double l = std::max(lo.xLeft(lo.yhi), up.xLeft(up.ylo));
            const double r = std::min(lo.xRight(lo.yhi), up.xRight(up.ylo));
            pairs.push_back(Pair{static_cast<int>(i), a, r - l});
        }
    std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.overlap > b.overlap; });
    std::vector<int> up(cells.size(), -1), down(cells.size(), -1);
    for (const auto& p : pairs) {
        if (p.overlap <= 0 || up[static_cast<std::size_t>(p.lower)] >= 0 || down[static_cast<std::size_t>(p.upper)] >= 0)
            continue;
        up[static_cast<std::size_t>(p.lower)] = p.upper;
        down[static_cast<std::size_t>(p.upper)] = p.lower;
    }
    std::vector<MergedCell> out;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (down[i] >= 0)
            continue;
        MergedCell m;
        for (int c = static_cast<int>(i); c >= 0; c = up[static_cast<std::size_t>(c)])
            m.parts.push_back(c);
        out.push_back(std::move(m));
    }
    return out;
}

geo::Ring mergedRing(const Decomposition& d, const MergedCell& m) {
    geo::Ring r;
    auto push = [&](const Vec2& p) {
        if (r.empty() || (r.back() - p).squaredNorm() > 1e-18)
            r.push_back(p);
    };
    for (int c : m.parts)
        for (const auto& p : d.cells[static_cast<std::size_t>(c)].right)
            push(p);
    for (auto it = m.parts.rbegin(); it != m.parts.rend(); ++it) {
        const auto& left = d.cells[static_cast<std::size_t>(*it)].left;
        for (auto p = left.rbegin(); p != left.rend(); ++p)
            push(*p);
    }
    if (r.size() > 1 && (r.front() - r.back()).squaredNorm() <= 1e-18)
        r.pop_back();
    return r;
}

} // namespace pf::plan
