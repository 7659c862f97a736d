#include "core/plan/sweep_lanes.h"

#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>

namespace pf::plan {

using geo::Vec2;

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Even-odd containment over the polygons' rings: the ground model probes points a few centimetres off
// a boundary, never on one, so the boundary case does not matter and the plain rule is exact.
bool insideEvenOdd(const geo::Polygon& poly, const Vec2& p) {
    bool inside = false;
    auto ring = [&](const geo::Ring& r) {
        for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
            if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
                p.x() < (r[j].x() - r[i].x()) * (p.y() - r[i].y()) / (r[j].y() - r[i].y()) + r[i].x())
                inside = !inside;
    };
    ring(poly.outer);
    for (const auto& h : poly.holes)
        ring(h);
    return inside;
}

bool insideAny(const geo::MultiPolygon& polys, const std::vector<geo::Box>& boxes, const Vec2& p) {
    for (std::size_t i = 0; i < polys.size(); ++i)
        if (boxes[i].contains(p) && insideEvenOdd(polys[i], p))
            return true;
    return false;
}

void addRings(const geo::Polygon& poly, std::vector<geo::Ring>& out) {
    out.push_back(poly.outer);
    for (const auto& h : poly.holes)
        out.push_back(h);
}

} // namespace

SweepGround::SweepGround(const geo::MultiPolygon& area, const std::vector<geo::Polygon>& zones,
                         const geo::MultiPolygon& grownZones)
    : m_area(area), m_grown(grownZones), m_zones(zones) {
    auto add = [&](const geo::Polygon& poly) {
        Rings r;
        addRings(poly, r.rings);
        r.box = geo::bounds(poly);
        m_blockers.push_back(std::move(r));
    };
    for (const auto& z : zones)
        add(z);
    for (const auto& g : grownZones)
        add(g);
    for (const auto& a : area)
        add(a);
    for (const auto& a : area)
        m_areaBoxes.push_back(geo::bounds(a));
    for (const auto& g : grownZones)
        m_grownBoxes.push_back(geo::bounds(g));
}

bool SweepGround::insideArea(const Vec2& p) const { return insideAny(m_area, m_areaBoxes, p); }

bool SweepGround::inMargin(const Vec2& p) const { return insideArea(p) && insideAny(m_grown, m_grownBoxes, p); }

double SweepGround::marginRun(const Vec2& p, const Vec2& u, double cap) const {
    double best = cap;
    const Vec2 far = p + cap * u;
    const geo::Box ray{p.cwiseMin(far), p.cwiseMax(far)};
    for (const auto& b : m_blockers) {
        if (!b.box.intersects(ray))
            continue;
        for (const auto& ring : b.rings) {
            const std::size_t n = ring.size();
            for (std::size_t i = 0; i < n; ++i) {
                const Vec2& c = ring[i];
                const Vec2 e = ring[(i + 1) % n] - c;
                const double den = cross(u, e);
                if (std::abs(den) < 1e-15)
                    continue;
                const Vec2 pc = c - p;
                const double t = cross(pc, e) / den;  // along the ray
                const double s = cross(pc, u) / den;  // along the edge
                if (t > 0.02 && t < best && s >= 0.0 && s <= 1.0)
                    best = t;
            }
        }
    }
    return best;
}

std::vector<int> SweepGround::zonesNear(const Vec2& p, double d) const {
    std::vector<int> out;
    for (std::size_t i = 0; i < m_zones.size(); ++i) {
        const geo::Box& b = m_blockers[i].box;
        if (p.x() < b.min.x() - d || p.x() > b.max.x() + d || p.y() < b.min.y() - d || p.y() > b.max.y() + d)
            continue;
        if (insideEvenOdd(m_zones[i], p) || geo::distanceToBoundary(m_zones[i], p) <= d)
            out.push_back(static_cast<int>(i));
    }
    return out;
}

namespace {

struct Window {
    double lo, hi;
};

// How far beyond the cell's top (or bottom) the outermost lane's strip must reach: the ground of a
// margin lies there when a zone's grown boundary touches the cut, up to the zone itself. Flat along
// the cut, that is the grown margin; at a corner of a zone whose side runs at a shallow angle to the
// lanes, the side's rise too (the lanes beside the zone end at that side and see little of it). Less
// what the real footprint's extra width sees anyway.
double contactReach(const Decomposition& d, const MonotoneCell& c, bool top, const SweepLaneParams& p,
                    const SweepGround& ground) {
    const double y = top ? c.yhi : c.ylo, dir = top ? 1.0 : -1.0;
    double need = 0.0;
    for (const auto& [x1, x2] : top ? c.topContacts : c.bottomContacts) {
        if (x2 - x1 < 0.5)
            continue;
        if (ground.inMargin(d.frame.toWorld(Vec2(0.5 * (x1 + x2), y + 0.05 * dir))))
            need = std::max(need, p.grownMarginM);
    }
    constexpr double kShallow = 30.0 * M_PI / 180.0;
    for (const auto& t : top ? c.topTouches : c.bottomTouches) {
        if (!ground.inMargin(d.frame.toWorld(Vec2(t.x(), t.y() + 0.05 * dir))))
            continue;
        for (int zi : ground.zonesNear(d.frame.toWorld(t), p.grownMarginM + 0.5)) {
            // The zone's vertex nearest the cut and its two sides from there, in the frame.
            const auto& ring = ground.zone(zi).outer;
            const std::size_t n = ring.size();
            std::size_t best = 0;
            for (std::size_t i = 1; i < n; ++i)
                if (dir * d.frame.toFrame(ring[i]).y() < dir * d.frame.toFrame(ring[best]).y())
                    best = i;
            const Vec2 z = d.frame.toFrame(ring[best]);
            double h = dir * (z.y() - y);
            for (const std::size_t k : {(best + 1) % n, (best + n - 1) % n}) {
                const Vec2 e = d.frame.toFrame(ring[k]) - z;
                const double len = e.norm();
                const double a = std::atan2(std::abs(e.y()), std::abs(e.x()));
                if (len > 0 && a < kShallow)
                    h = std::max(h, dir * (z.y() - y) + len * std::sin(a));
            }
            need = std::max(need, h);
        }
    }
    return std::max(0.0, need - p.neighbourReachM);
}

} // namespace

std::vector<double> laneHeights(const Decomposition& d, const MergedCell& m, const SweepLaneParams& p,
                                const SweepGround& ground, std::optional<double> coverFrom,
                                std::optional<double> coverTo) {
    const auto& first = d.cells[static_cast<std::size_t>(m.parts.front())];
    const auto& last = d.cells[static_cast<std::size_t>(m.parts.back())];
    const double ylo = first.ylo, yhi = last.yhi, s = p.trackSpacingM;
    if (yhi - ylo <= 0.04)
        return {0.5 * (ylo + yhi)};
    const double eps = 0.01;
    const double cap = 0.5 * s - 2 * eps;
    auto reach = [&](const MonotoneCell& c, bool top) { return std::min(cap, contactReach(d, c, top, p, ground)); };
    std::vector<Window> w;
    // The heights the outer strips must reach.
    const double from = coverFrom ? *coverFrom : ylo - reach(first, false);
    const double to = coverTo ? *coverTo : yhi + reach(last, true);
    if (m.parts.size() == 1 && from >= to)
        return {};
    const double et = to - yhi;
    w.push_back(Window{ylo + eps, from + 0.5 * s});
    w.push_back(Window{to - 0.5 * s, yhi - eps});
    for (std::size_t i = 1; i < m.parts.size(); ++i) {
        const auto& lo = d.cells[static_cast<std::size_t>(m.parts[i - 1])];
        const auto& up = d.cells[static_cast<std::size_t>(m.parts[i])];
        const double c = lo.yhi;
        const bool narrowing = up.xLeft(up.ylo) >= lo.xLeft(lo.yhi) - 1e-6 && up.xRight(up.ylo) <= lo.xRight(lo.yhi) + 1e-6;
        if (narrowing) {
            const double ec = reach(lo, true);
            w.push_back(Window{c - 0.5 * s + ec, c - eps});
        } else {
            const double ec = reach(up, false);
            w.push_back(Window{c + eps, c + 0.5 * s - ec});
        }
    }
    if (m.parts.size() == 1 && w[0].hi >= w[1].lo) {
        // One lane does: in the middle of what it may take.
        const double lo = std::max(ylo + eps, w[1].lo), hi = std::min(yhi - eps, w[0].hi);
        return {lo <= hi ? 0.5 * (lo + hi) : 0.5 * (ylo + yhi)};
    }
    for (auto& win : w) {
        win.lo = std::clamp(win.lo, ylo + eps, yhi - eps);
        win.hi = std::clamp(win.hi, ylo + eps, yhi - eps);
        if (win.lo > win.hi)
            win.lo = win.hi;
    }
    // Greedy from the bottom: every lane as high as the spacing and the windows still ahead allow.
    double y = w.front().hi;
    for (const auto& win : w)
        y = std::min(y, win.hi);
    std::vector<double> ys{y};
    for (;;) {
        double next = y + s;
        bool pending = false;
        for (const auto& win : w)
            if (win.lo > y) {
                pending = true;
                next = std::min(next, win.hi);
            }
        if (!pending)
            break;
        if (next <= y + 1e-9)
            next = y + s;
        y = std::min(next, yhi - eps);
        ys.push_back(y);
        if (y >= yhi - eps)
            break;
    }
    // Centre: move every lane down by half the excess at the top, as far as the windows allow.
    double shift = 0.5 * ((ys.back() + 0.5 * s) - (yhi + et));
    shift = std::min(shift, ys.front() - (ylo + eps));
    for (const auto& win : w) {
        double inside = -1.0;
        for (double v : ys)
            if (v >= win.lo - 1e-12 && v <= win.hi + 1e-12)
                inside = std::max(inside, v - win.lo);
        if (inside >= 0.0)
            shift = std::min(shift, inside);
    }
    if (shift > 0)
        for (auto& v : ys)
            v -= shift;
    return ys;
}

std::vector<std::vector<double>> allLaneHeights(const Decomposition& d, const std::vector<MergedCell>& merged,
                                                const SweepLaneParams& p, const SweepGround& ground) {
    std::vector<std::vector<double>> hs;
    hs.reserve(merged.size());
    for (const auto& m : merged)
        hs.push_back(laneHeights(d, m, p, ground));
    // Which merged cell each part is in, and where in its chain.
    std::vector<int> mergedOf(d.cells.size(), -1), posOf(d.cells.size(), -1);
    for (std::size_t i = 0; i < merged.size(); ++i)
        for (std::size_t k = 0; k < merged[i].parts.size(); ++k) {
            mergedOf[static_cast<std::size_t>(merged[i].parts[k])] = static_cast<int>(i);
            posOf[static_cast<std::size_t>(merged[i].parts[k])] = static_cast<int>(k);
        }
    const double s = p.trackSpacingM, tol = 1e-6;
    std::vector<std::vector<double>> out = hs;
    for (std::size_t i = 0; i < merged.size(); ++i) {
        const auto& m = merged[i];
        const auto& bottom = d.cells[static_cast<std::size_t>(m.parts.front())];
        const auto& top = d.cells[static_cast<std::size_t>(m.parts.back())];
        std::optional<double> from, to;
        // A cell below whose chain goes on past this cut (so it keeps a lane just under it) and whose
        // lane there spans this cell's bottom.
        for (int b : bottom.below) {
            const int mb = mergedOf[static_cast<std::size_t>(b)];
            const int pos = posOf[static_cast<std::size_t>(b)];
            if (mb < 0 || mb == static_cast<int>(i) || pos + 1 >= static_cast<int>(merged[static_cast<std::size_t>(mb)].parts.size()))
                continue;
            const auto& cb = d.cells[static_cast<std::size_t>(b)];
            for (double y : hs[static_cast<std::size_t>(mb)]) {
                if (y < cb.ylo || y > cb.yhi || y < bottom.ylo - 0.5 * s)
                    continue;
                if (cb.xLeft(y) <= bottom.xLeft(bottom.ylo) + tol && cb.xRight(y) >= bottom.xRight(bottom.ylo) - tol)
                    from = std::max(from.value_or(-1e300), y + 0.5 * s);
            }
        }
        for (int a : top.above) {
            const int ma = mergedOf[static_cast<std::size_t>(a)];
            const int pos = posOf[static_cast<std::size_t>(a)];
            if (ma < 0 || ma == static_cast<int>(i) || pos == 0)
                continue;
            const auto& ca = d.cells[static_cast<std::size_t>(a)];
            for (double y : hs[static_cast<std::size_t>(ma)]) {
                if (y < ca.ylo || y > ca.yhi || y > top.yhi + 0.5 * s)
                    continue;
                if (ca.xLeft(y) <= top.xLeft(top.yhi) + tol && ca.xRight(y) >= top.xRight(top.yhi) - tol)
                    to = std::min(to.value_or(1e300), y - 0.5 * s);
            }
        }
        if (from || to)
            out[i] = laneHeights(d, m, p, ground, from, to);
    }
    return out;
}

std::vector<CellLane> cellLanes(const Decomposition& d, const MergedCell& m, const std::vector<double>& heights,
                                const SweepLaneParams& p, const SweepGround& ground,
                                const std::function<bool(const Vec2&, const Vec2&)>& safe) {
    std::vector<CellLane> out;
    out.reserve(heights.size());
    const Vec2 u = d.frame.toWorld(Vec2(1, 0));
    const double s = p.trackSpacingM;
    std::size_t part = 0;
    for (double y : heights) {
        while (part + 1 < m.parts.size() && y > d.cells[static_cast<std::size_t>(m.parts[part])].yhi)
            ++part;
        const auto& cell = d.cells[static_cast<std::size_t>(m.parts[part])];
        double xl = cell.xLeft(y), xr = cell.xRight(y);
        if (xr < xl)
            xl = xr = 0.5 * (xl + xr);
        const double b1 = std::max(y - 0.5 * s, cell.ylo), b2 = std::min(y + 0.5 * s, cell.yhi);
        double sa = std::min(xl, cell.minLeft(b1, b2)), sb = std::max(xr, cell.maxRight(b1, b2));
        double fa = xl, fb = xr;
        const double inset = std::min(p.neighbourReachM, 0.25 * s);
        const double lb1 = std::max(y - 0.5 * s + inset, cell.ylo), ub2 = std::min(y + 0.5 * s - inset, cell.yhi);
        const double wrb = y > lb1 ? cell.maxRight(lb1, y) - xr : 0.0, wra = ub2 > y ? cell.maxRight(y, ub2) - xr : 0.0;
        const double wlb = y > lb1 ? xl - cell.minLeft(lb1, y) : 0.0, wla = ub2 > y ? xl - cell.minLeft(y, ub2) : 0.0;
        // What lies beyond each end along the lane's line.
        auto beyond = [&](double x, double dir, double& strip, double& fly) {
            const Vec2 e = d.frame.toWorld(Vec2(x, y));
            const Vec2 dirW = dir * u;
            const Vec2 q = e + 0.05 * dirW;
            if (!ground.insideArea(q)) {
                const double reach = dir > 0 ? strip - x : x - strip;
                if (p.flyOutsideArea && reach > 1e-6 && safe(e, d.frame.toWorld(Vec2(strip, y))))
                    fly = strip;
            } else if (ground.inMargin(q)) {
                const double run = ground.marginRun(e, dirW, p.marginRunCapM);
                strip = dir > 0 ? std::max(strip, x + run) : std::min(strip, x - run);
            }
        };
        beyond(xr, 1.0, sb, fb);
        beyond(xl, -1.0, sa, fa);
        CellLane l;
        l.y = y;
        l.part = m.parts[part];
        l.stripA = d.frame.toWorld(Vec2(sa, y));
        l.stripB = d.frame.toWorld(Vec2(sb, y));
        l.flyA = d.frame.toWorld(Vec2(fa, y));
        l.flyB = d.frame.toWorld(Vec2(fb, y));
        l.span = laneSpan(l.stripA, l.stripB, p.photoSpacingM, l.flyA, l.flyB);
        // Beyond the area's edge the lane itself flies on over the wedge.
        const double flownRight = fb - xr, flownLeft = xl - fa;
        l.wedgeRightBelow = std::max(0.0, wrb - flownRight);
        l.wedgeRightAbove = std::max(0.0, wra - flownRight);
        l.wedgeLeftBelow = std::max(0.0, wlb - flownLeft);
        l.wedgeLeftAbove = std::max(0.0, wla - flownLeft);
        out.push_back(l);
    }
    return out;
}

} // namespace pf::plan
