#include "core/route/lanes.h"

#include "core/geo/half_plane_clip.h"

#include "core/geo/polygon_ops.h"
#include "core/geo/prepared_region.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>

namespace pf::route {

using geo::Vec2;

namespace {

// Consecutive photographed occurrences [a, b] joined by one unit grid step (dc, dr); (0, 0) while the
// piece has a single cell.
struct Piece {
    int a = 0, b = 0;
    int dc = 0, dr = 0;
    int size() const { return b - a + 1; }
};

struct Step {
    int dc = 0, dr = 0;
    bool unit() const { return std::abs(dc) + std::abs(dr) == 1; }
    bool operator==(const Step& o) const { return dc == o.dc && dr == o.dr; }
};

class Builder {
public:
    Builder(const grid::Grid& g, const plan::CellPath& path, const sensor::EffectiveFootprint& fp)
        : m_g(g), m_path(path), m_fp(fp), m_spacing(fp.alongM) {
        const double a = g.angleDeg() * M_PI / 180.0;
        m_ex = Vec2(std::cos(a), std::sin(a));
        m_ey = Vec2(-std::sin(a), std::cos(a));
    }

    std::vector<PathGroup> run() {
        std::vector<Piece> pieces = findPieces();
        reassignTurningCells(pieces);
        std::vector<PathGroup> out;
        for (const Piece& p : pieces)
            emit(p, out);
        return out;
    }

private:
    Step step(int i, int j) const {
        const int ci = m_path.cells[static_cast<std::size_t>(i)], cj = m_path.cells[static_cast<std::size_t>(j)];
        return {m_g.col(cj) - m_g.col(ci), m_g.row(cj) - m_g.row(ci)};
    }
    bool photographed(int i) const { return !m_path.revisit[static_cast<std::size_t>(i)]; }
    int cell(int i) const { return m_path.cells[static_cast<std::size_t>(i)]; }

    std::vector<Piece> findPieces() const {
        std::vector<Piece> out;
        const int n = static_cast<int>(m_path.cells.size());
        std::optional<Piece> cur;
        for (int i = 0; i < n; ++i) {
            if (!photographed(i))
                continue;
            if (cur && i == cur->b + 1) {
                const Step s = step(cur->b, i);
                if (s.unit() && (cur->size() == 1 || (s.dc == cur->dc && s.dr == cur->dr))) {
                    cur->b = i;
                    cur->dc = s.dc;
                    cur->dr = s.dr;
                    continue;
                }
            }
            if (cur)
                out.push_back(*cur);
            cur = Piece{i, i, 0, 0};
        }
        if (cur)
            out.push_back(*cur);
        return out;
    }

    // The cell where the path turns from piece P into the following piece Q (P's last, flown into Q by
    // Q's own step) goes to the longer run: P as it is, or Q with that cell in front.
    void reassignTurningCells(std::vector<Piece>& pieces) const {
        for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
            Piece& p = pieces[k];
            Piece& q = pieces[k + 1];
            if (p.size() < 2 || q.a != p.b + 1)
                continue;
            const Step s = step(p.b, q.a);
            if (!s.unit() || (q.size() > 1 && !(s.dc == q.dc && s.dr == q.dr)))
                continue;
            if (q.size() + 1 <= p.size())
                continue; // ties stay with the earlier run
            q.a = p.b;
            q.dc = s.dc;
            q.dr = s.dr;
            --p.b;
            if (p.size() == 1) { // its direction is still the step out of its one cell
                p.dc = step(p.a, p.a + 1).dc;
                p.dr = step(p.a, p.a + 1).dr;
            }
        }
    }

    // The lane direction of a piece in the local frame, or nothing when it cannot be a lane (a single
    // cell reached and left by diagonal steps or jumps).
    std::optional<Vec2> direction(const Piece& p) const {
        Step s{p.dc, p.dr};
        if (p.size() == 1) {
            s = {};
            const int n = static_cast<int>(m_path.cells.size());
            if (p.a > 0 && step(p.a - 1, p.a).unit())
                s = step(p.a - 1, p.a);
            else if (p.a + 1 < n && step(p.a, p.a + 1).unit())
                s = step(p.a, p.a + 1);
            else if (p.a == 0 && n == 1)
                s = {1, 0};
        }
        if (!s.unit())
            return std::nullopt;
        return s.dc * m_ex + s.dr * m_ey;
    }

    // Along-line extent [lo, hi] (relative to the cell's centre, along u) of the cell's ground inside the
    // area: each outer ring of the admissible area clipped to the cell's square (Sutherland-Hodgman;
    // the clipped points span exactly the ring's part in the square). Holes (the no-fly zones) are left
    // out: where a zone cuts an end cell, the lane's line enters its margin and the lane ends at the
    // margin's edge instead (emit), which is never further than the zone.
    std::pair<double, double> groundExtent(int c, const Vec2& u) const {
        const double h = m_g.cellSize() / 2;
        const geo::MultiPolygon& adm = m_g.admissible();
        if (adm.empty())
            return {-h, h};
        const Vec2 centre = m_g.cellCenter(c), v(-u.y(), u.x());
        const geo::Box box = geo::bounds(m_g.cellCorners(c));
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        std::vector<Vec2> a, b;
        for (const auto& poly : adm) {
            if (!geo::bounds(poly.outer).intersects(box))
                continue;
            a.clear();
            for (const auto& p : poly.outer)
                a.emplace_back((p - centre).dot(u), (p - centre).dot(v));
            for (int axis = 0; axis < 2 && !a.empty(); ++axis)
                for (double side : {-1.0, 1.0}) {
                    geo::clipHalfPlane(a, b, axis, side * h, side < 0);
                    a.swap(b);
                }
            for (const auto& q : a) {
                lo = std::min(lo, q.x());
                hi = std::max(hi, q.x());
            }
        }
        if (!(lo <= hi))
            return {-h, h};
        return {std::max(-h, lo), std::min(h, hi)};
    }

    void emit(const Piece& p, std::vector<PathGroup>& out) const {
        const auto dir = direction(p);
        if (!dir) {
            out.push_back({false, p.a, p.b, {}, 0, 0});
            return;
        }
        const Vec2 u = *dir;
        const double cs = m_g.cellSize();
        const int n = p.size();
        // Positions along the line measured from the first cell's centre: cell k spans [k - 1/2, k + 1/2]
        // cells, the strip [t0, t1].
        const Vec2 origin = m_g.cellCenter(cell(p.a));
        const double t0 = groundExtent(cell(p.a), u).first;
        const double t1 = (n - 1) * cs + groundExtent(cell(p.b), u).second;
        auto at = [&](double t) { return origin + t * u; };
        auto lo = [&](int k) { return std::max(t0, (k - 0.5) * cs); };
        auto hi = [&](int k) { return std::min(t1, (k + 0.5) * cs); };
        std::vector<char> clean(static_cast<std::size_t>(n), 0);
        for (int k = 0; k < n; ++k) {
            const int c = cell(p.a + k);
            clean[static_cast<std::size_t>(k)] =
                m_g.state(c) == grid::CellState::Free && m_g.segmentIsSafe(at(lo(k)), at(hi(k)));
        }
        // Lanes over maximal runs of clean cells [k0, k1), each trying to take the cut cell at either end.
        struct Span {
            int k0, k1;          // cells [k0, k1)
            double from, to;     // strip
            double flyFrom, flyTo;
            int c0, c1;          // its clean cells [c0, c1)
        };
        std::vector<Span> spans;
        std::vector<char> taken(static_cast<std::size_t>(n), 0);
        for (int k = 0; k < n;) {
            if (!clean[static_cast<std::size_t>(k)]) {
                ++k;
                continue;
            }
            const int k0 = k;
            while (k < n && clean[static_cast<std::size_t>(k)])
                ++k;
            spans.push_back({k0, k, lo(k0), hi(k - 1), lo(k0), hi(k - 1), k0, k});
            for (int j = k0; j < k; ++j)
                taken[static_cast<std::size_t>(j)] = 1;
        }
        for (Span& s : spans) {
            if (s.k0 > 0 && !taken[static_cast<std::size_t>(s.k0 - 1)]) {
                const int j = s.k0 - 1;
                const double edge = (j + 0.5) * cs;
                const double fly = lastSafe(at(edge), at(lo(j)), edge, lo(j));
                if (coversCell(cell(p.a + j), at(lo(j)), at(s.to), at(fly), at(s.flyTo), u)) {
                    s.k0 = j;
                    s.from = lo(j);
                    s.flyFrom = fly;
                    taken[static_cast<std::size_t>(j)] = 1;
                }
            }
            if (s.k1 < n && !taken[static_cast<std::size_t>(s.k1)]) {
                const int j = s.k1;
                const double edge = (j - 0.5) * cs;
                const double fly = lastSafe(at(edge), at(hi(j)), edge, hi(j));
                if (coversCell(cell(p.a + j), at(s.from), at(hi(j)), at(s.flyFrom), at(fly), u)) {
                    s.k1 = j + 1;
                    s.to = hi(j);
                    s.flyTo = fly;
                    taken[static_cast<std::size_t>(j)] = 1;
                }
            }
        }
        // In flight order: the spans and, between them, the cells left to the per-cell photos.
        int k = 0;
        for (const Span& s : spans) {
            if (s.k0 > k)
                out.push_back({false, p.a + k, p.a + s.k0 - 1, {}, 0, 0});
            PathGroup grp;
            grp.lane = true;
            grp.first = p.a + s.k0;
            grp.last = p.a + s.k1 - 1;
            grp.strip = plan::makeLane(at(s.from), at(s.to), m_spacing, at(s.flyFrom), at(s.flyTo));
            grp.firstClean = p.a + s.c0;
            grp.lastClean = p.a + s.c1 - 1;
            out.push_back(std::move(grp));
            k = s.k1;
        }
        if (k < n)
            out.push_back({false, p.a + k, p.b, {}, 0, 0});
    }

    // The furthest position from ta towards tb (a, b the points there) up to which the line keeps the
    // margins, found by bisection to a millimetre (ta itself is safe: it lies on a clean cell's line).
    double lastSafe(const Vec2& a, const Vec2& b, double ta, double tb) const {
        if (m_g.segmentIsSafe(a, b))
            return tb;
        double lo = 0.0, hi = 1.0;
        const double len = std::fabs(tb - ta);
        while ((hi - lo) * len > 1e-3) {
            const double mid = 0.5 * (lo + hi);
            (m_g.segmentIsSafe(a, a + mid * (b - a)) ? lo : hi) = mid;
        }
        return ta + lo * (tb - ta);
    }

    // True if the photos of the lane with strip [a, b] flown over [flyA, flyB] see all of cell c's
    // admissible ground through their real footprints. The footprints are aligned with the lane and at
    // least the cell wide across it (the cell is an effective side, the real long side longer), so only
    // the positions along the lane matter: every stretch of the cell along u that no footprint reaches
    // must hold no admissible ground (tested on the prepared region, 1 cm inside the stretch so that a
    // boundary running along it does not count).
    bool coversCell(int c, const Vec2& a, const Vec2& b, const Vec2& flyA, const Vec2& flyB, const Vec2& u) const {
        const double h = m_g.cellSize() / 2;
        if (m_g.admissible().empty() || !(m_fp.real.shortSideM > 0) || m_fp.real.longSideM < m_g.cellSize())
            return false;
        if (!m_region) // built on first use: most paths never need it
            m_region.emplace(m_g.admissible());
        if ((flyB - flyA).dot(u) <= 0)
            return false; // nothing of the line is flyable
        const plan::Lane lane = plan::makeLane(a, b, m_spacing, flyA, flyB);
        const Vec2 centre = m_g.cellCenter(c), v(-u.y(), u.x());
        std::vector<std::pair<double, double>> seen;
        for (const auto& ph : lane.photos) {
            const double t = (ph - centre).dot(u);
            seen.emplace_back(t - m_fp.real.shortSideM / 2, t + m_fp.real.shortSideM / 2);
        }
        std::sort(seen.begin(), seen.end());
        constexpr double kIn = 0.01;
        auto groundIn = [&](double t0, double t1) {
            if (t1 - t0 <= 2 * kIn)
                return false;
            const geo::Ring r{centre + (t0 + kIn) * u + (-h + kIn) * v, centre + (t1 - kIn) * u + (-h + kIn) * v,
                              centre + (t1 - kIn) * u + (h - kIn) * v, centre + (t0 + kIn) * u + (h - kIn) * v};
            return m_region->intersects(geo::Polygon{r, {}});
        };
        double from = -h; // everything of the cell before `from` along u is seen
        for (const auto& [s0, s1] : seen) {
            if (s0 > from && groundIn(from, std::min(s0, h)))
                return false;
            from = std::max(from, s1);
            if (from >= h)
                return true;
        }
        return !groundIn(from, h);
    }

    const grid::Grid& m_g;
    const plan::CellPath& m_path;
    sensor::EffectiveFootprint m_fp;
    double m_spacing;
    Vec2 m_ex{1, 0}, m_ey{0, 1};
    mutable std::optional<geo::PreparedRegion> m_region;
};

} // namespace

std::vector<PathGroup> cellPathGroups(const grid::Grid& g, const plan::CellPath& path,
                                      const sensor::EffectiveFootprint& fp) {
    if (path.cells.empty())
        return {};
    if (fp.acrossM < g.cellSize() * (1 - 1e-9) || !(fp.alongM > 0)) {
        std::vector<PathGroup> cells;
        for (std::size_t i = 0; i < path.cells.size(); ++i)
            if (!path.revisit[i])
                cells.push_back({false, static_cast<int>(i), static_cast<int>(i), {}, 0, 0});
        return cells;
    }
    return Builder(g, path, fp).run();
}

} // namespace pf::route
