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

} // namespace

double MonotoneCell::xLeft(double y) const { return chainX(left, std::clamp(y, ylo, yhi), true); }
double MonotoneCell::xRight(double y) const { return chainX(right, std::clamp(y, ylo, yhi), false); }

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

double MonotoneCell::area() const { return std::abs(geo::signedArea(ring())); }

Result<Decomposition> decompose(const geo::MultiPolygon& polys, const SweepFrame& frame) {
    Decomposition out;
    out.frame = frame;
    // Rings in the frame, without repeated points.
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
    // Edges: edge (ring, i) joins vertex i to vertex i + 1.
    std::vector<int> ringStart(rings.size() + 1, 0);
    for (std::size_t r = 0; r < rings.size(); ++r)
        ringStart[r + 1] = ringStart[r] + static_cast<int>(rings[r].size());
    std::vector<Edge> edges(static_cast<std::size_t>(ringStart.back()));
    std::vector<Vertex> verts;
    verts.reserve(edges.size());
    for (std::size_t r = 0; r < rings.size(); ++r) {
        const auto& ring = rings[r];
        const int n = static_cast<int>(ring.size());
        for (int i = 0; i < n; ++i) {
            const Vec2& a = ring[static_cast<std::size_t>(i)];
            const Vec2& b = ring[static_cast<std::size_t>((i + 1) % n)];
            Edge& e = edges[static_cast<std::size_t>(ringStart[r] + i)];
            e.lo = lexLess(a, b) ? a : b;
            e.hi = lexLess(a, b) ? b : a;
            verts.push_back(Vertex{a, static_cast<int>(r), i});
        }
    }
    std::sort(verts.begin(), verts.end(), [](const Vertex& a, const Vertex& b) {
        if (a.p != b.p)
            return lexLess(a.p, b.p);
        return a.ring != b.ring ? a.ring < b.ring : a.index < b.index;
    });

    auto& cells = out.cells;
    std::vector<int> active;   // edge ids crossing the sweep line, left to right
    std::vector<int> openCell; // cell between active[2k] and active[2k + 1]
    auto bad = [&](const char* what) {
        return makeError(ErrorCode::InvalidGeometry,
                         std::string("The area's outline could not be decomposed along the sweep direction (") + what +
                             "): it may touch or cross itself.");
    };
    auto indexOf = [&](int e) {
        auto it = std::find(active.begin(), active.end(), e);
        return it == active.end() ? -1 : static_cast<int>(it - active.begin());
    };
    auto newCell = [&](const Vec2& l, const Vec2& r) {
        MonotoneCell c;
        c.left.push_back(l);
        c.right.push_back(r);
        c.ylo = l.y();
        cells.push_back(std::move(c));
        return static_cast<int>(cells.size()) - 1;
    };
    auto link = [&](int lower, int upper) {
        cells[static_cast<std::size_t>(lower)].above.push_back(upper);
        cells[static_cast<std::size_t>(upper)].below.push_back(lower);
    };

    for (const auto& vx : verts) {
        const auto& ring = rings[static_cast<std::size_t>(vx.ring)];
        const int n = static_cast<int>(ring.size());
        const Vec2& v = vx.p;
        const Vec2& u = ring[static_cast<std::size_t>((vx.index + n - 1) % n)];
        const Vec2& w = ring[static_cast<std::size_t>((vx.index + 1) % n)];
        const int eu = ringStart[static_cast<std::size_t>(vx.ring)] + (vx.index + n - 1) % n; // u - v
        const int ew = ringStart[static_cast<std::size_t>(vx.ring)] + vx.index;               // v - w
        const bool uAbove = lexLess(v, u), wAbove = lexLess(v, w);
        if (uAbove != wAbove) {
            // Regular: the edge from below ends here and the one above continues the same chain.
            const int ending = uAbove ? ew : eu, starting = uAbove ? eu : ew;
            const int idx = indexOf(ending);
            if (idx < 0)
                return bad("a boundary edge was lost");
            active[static_cast<std::size_t>(idx)] = starting;
            auto& c = cells[static_cast<std::size_t>(openCell[static_cast<std::size_t>(idx / 2)])];
            (idx % 2 == 0 ? c.left : c.right).push_back(v);
            continue;
        }
        if (uAbove) {
            // Two edges begin: the left one is the more counter-clockwise direction.
            const bool uLeft = cross(w - v, u - v) > 0;
            const int eL = uLeft ? eu : ew, eR = uLeft ? ew : eu;
            int pos = 0;
            for (int e : active) {
                const Edge& ed = edges[static_cast<std::size_t>(e)];
                if (cross(ed.hi - ed.lo, v - ed.lo) < 0)
                    ++pos;
                else
                    break;
            }
            if (pos % 2 == 0) {
                // Start: a new piece of free space.
                active.insert(active.begin() + pos, {eL, eR});
                const int ci = newCell(v, v);
                cells[static_cast<std::size_t>(ci)].bottomTouches.push_back(v);
                openCell.insert(openCell.begin() + pos / 2, ci);
            } else {
                // Split: an obstacle begins inside the interval; its cell ends, two begin.
                const int k = (pos - 1) / 2;
                const int ci = openCell[static_cast<std::size_t>(k)];
                const double xl = edges[static_cast<std::size_t>(active[static_cast<std::size_t>(2 * k)])].xAt(v.y());
                const double xr = edges[static_cast<std::size_t>(active[static_cast<std::size_t>(2 * k + 1)])].xAt(v.y());
                {
                    auto& c = cells[static_cast<std::size_t>(ci)];
                    c.left.emplace_back(xl, v.y());
                    c.right.emplace_back(xr, v.y());
                    c.topTouches.push_back(v);
                    const Edge& er = edges[static_cast<std::size_t>(eR)];
                    if (er.horizontal())
                        c.topContacts.emplace_back(er.lo.x(), er.hi.x());
                }
                const int cl = newCell(Vec2(xl, v.y()), v);
                const int cr = newCell(v, Vec2(xr, v.y()));
                link(ci, cl);
                link(ci, cr);
                active.insert(active.begin() + pos, {eL, eR});
                openCell[static_cast<std::size_t>(k)] = cl;
                openCell.insert(openCell.begin() + k + 1, cr);
            }
            continue;
        }
        // Two edges end here.
        const int iu = indexOf(eu), iw = indexOf(ew);
        if (iu < 0 || iw < 0 || std::abs(iu - iw) != 1)
            return bad("two closing edges are not neighbours");
        const int lo = std::min(iu, iw);
        if (lo % 2 == 0) {
            // End: the interval closes at v.
            auto& c = cells[static_cast<std::size_t>(openCell[static_cast<std::size_t>(lo / 2)])];
            c.left.push_back(v);
            c.right.push_back(v);
            c.topTouches.push_back(v);
            active.erase(active.begin() + lo, active.begin() + lo + 2);
            openCell.erase(openCell.begin() + lo / 2);
        } else {
            // Merge: an obstacle ends; the two cells beside it end and one begins above it.
            const int k = (lo - 1) / 2;
            const int c1 = openCell[static_cast<std::size_t>(k)], c2 = openCell[static_cast<std::size_t>(k + 1)];
            const double xl = edges[static_cast<std::size_t>(active[static_cast<std::size_t>(2 * k)])].xAt(v.y());
            const double xr = edges[static_cast<std::size_t>(active[static_cast<std::size_t>(2 * k + 3)])].xAt(v.y());
            cells[static_cast<std::size_t>(c1)].left.emplace_back(xl, v.y());
            cells[static_cast<std::size_t>(c1)].right.push_back(v);
            cells[static_cast<std::size_t>(c2)].left.push_back(v);
            cells[static_cast<std::size_t>(c2)].right.emplace_back(xr, v.y());
            const int cm = newCell(Vec2(xl, v.y()), Vec2(xr, v.y()));
            cells[static_cast<std::size_t>(cm)].bottomTouches.push_back(v);
            const Edge& el = edges[static_cast<std::size_t>(active[static_cast<std::size_t>(lo)])];
            if (el.horizontal())
                cells[static_cast<std::size_t>(cm)].bottomContacts.emplace_back(el.lo.x(), el.hi.x());
            link(c1, cm);
            link(c2, cm);
            active.erase(active.begin() + lo, active.begin() + lo + 2);
            openCell[static_cast<std::size_t>(k)] = cm;
            openCell.erase(openCell.begin() + k + 1);
        }
    }
    if (!active.empty())
        return bad("the sweep ended with open edges");

    for (auto& c : cells) {
        c.ylo = std::min(c.left.front().y(), c.right.front().y());
        c.yhi = std::max(c.left.back().y(), c.right.back().y());
        // Chains that run horizontally along the bottom or the top: boundary lies flat there.
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

    // Drop cells without height; join their neighbours across them.
    std::vector<char> keep(cells.size(), 1);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        auto& c = cells[i];
        if (c.yhi - c.ylo > 1e-9)
            continue;
        keep[i] = 0;
        for (int b : c.below)
            for (int a : c.above)
                link(b, a);
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
