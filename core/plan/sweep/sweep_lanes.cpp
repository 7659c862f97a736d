#include "core/plan/sweep/sweep_lanes.h"

#include "core/geo/even_odd.h"
#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace pf::plan {

using geo::Vec2;

namespace {

struct Window {
    double lo, hi;
    bool optional = false; // for time only (a lane may fly out over an outline's step instead)
    bool coversUp = false; // its lane's strip must reach up to a boundary above (else down to one below)
};

// Lanes at most s apart with one in every window, greedily from the bottom (each as high as the
// spacing and the windows ahead allow), then moved down by half the excess at the top as far as the
// windows allow.
std::vector<double> place(const std::vector<Window>& w, double ylo, double yhi, double et, double s, double eps) {
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

// At a cut where the wide cell (below a narrowing, above a widening) meets the cells on the other side,
// must the wide cell keep a lane right at the cut? Its ground next to the cut but beyond the other
// cells' intervals (under an obstacle that begins there, or where the outline steps in) is seen only by
// the other side's lane ends, up to the footprint's reach along the lane; wider than that, it needs a
// lane of its own within half a spacing of the cut. The obstacle's width is measured half a spacing
// past the cut, where the other side's first lanes lie at most.
enum class Need { None, ForCoverage, ForTime };
Need cutNeedsLane(const Decomposition& d, const MonotoneCell& wide, bool top, const SweepLaneParams& p) {
    const double s = p.trackSpacingM, c = top ? wide.yhi : wide.ylo;
    const double y = top ? c + 0.5 * s : c - 0.5 * s;
    std::vector<std::pair<double, double>> iv; // the other side's intervals there
    for (int o : top ? wide.above : wide.below) {
        const auto& oc = d.cells[static_cast<std::size_t>(o)];
        const double yy = std::clamp(y, oc.ylo, oc.yhi);
        iv.emplace_back(oc.xLeft(yy), oc.xRight(yy));
    }
    if (iv.empty())
        return Need::ForCoverage;
    std::sort(iv.begin(), iv.end());
    const double reach2 = 2.0 * p.reachAlongM;
    for (std::size_t k = 0; k + 1 < iv.size(); ++k)
        if (iv[k + 1].first - iv[k].second > reach2)
            return Need::ForCoverage;
    // An outline stepping in: the other side's lanes would have to fly out over the wide cell's
    // ground there (or cannot, kept inside).
    const double xl = wide.xLeft(c), xr = wide.xRight(c);
    if (iv.front().first - xl > 0.5 * reach2 || xr - iv.back().second > 0.5 * reach2)
        return p.flyOutsideArea ? Need::ForTime : Need::ForCoverage;
    return Need::None;
}

// Windows at the cuts between a merged cell's parts: where the wider part must keep a lane by the
// cut (cutNeedsLane), or the margin's ground beyond the cut needs one.
void cutWindows(const Decomposition& d, const MergedCell& m, const SweepLaneParams& p,
                const SweepGround& ground, double cap, double eps, std::vector<Window>& w) {
    const double s = p.trackSpacingM;
    for (std::size_t i = 1; i < m.parts.size(); ++i) {
        const auto& lo = d.cells[static_cast<std::size_t>(m.parts[i - 1])];
        const auto& up = d.cells[static_cast<std::size_t>(m.parts[i])];
        const double c = lo.yhi;
        const bool narrowing = up.xLeft(up.ylo) >= lo.xLeft(lo.yhi) - 1e-6 && up.xRight(up.ylo) <= lo.xRight(lo.yhi) + 1e-6;
        const double ec = narrowing ? std::min(cap, contactReach(d, lo, true, p, ground))
                                    : std::min(cap, contactReach(d, up, false, p, ground));
        const Need need = ec > 0 ? Need::ForCoverage : cutNeedsLane(d, narrowing ? lo : up, narrowing, p);
        if (need == Need::None)
            continue;
        if (narrowing)
            w.push_back(Window{c - 0.5 * s + ec, c - eps, need == Need::ForTime, true});
        else
            w.push_back(Window{c + eps, c + 0.5 * s - ec, need == Need::ForTime});
    }
}

// Steps of the outline inside a part (a chain running along the lanes): the wide side keeps a lane
// within half a spacing when the step is longer than the footprints from the narrow side reach
// along their lanes (or they would fly far out over the step, or cannot, kept inside).
void stepWindows(const Decomposition& d, const MergedCell& m, const SweepLaneParams& p,
                 const SweepGround& ground, double cap, double eps, std::vector<Window>& w) {
    const double s = p.trackSpacingM;
    for (int pi : m.parts) {
        const auto& c = d.cells[static_cast<std::size_t>(pi)];
        for (int side = 0; side < 2; ++side) {
            const auto& chain = side ? c.right : c.left;
            for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
                const Vec2 &a = chain[k], &b = chain[k + 1];
                if (a.y() != b.y() || a.y() <= c.ylo || a.y() >= c.yhi || std::abs(b.x() - a.x()) <= 2.0 * p.reachAlongM)
                    continue;
                // a right chain's run widens the cell above it; a left chain's run widens it below
                const bool wideAbove = side == 1;
                const double h = a.y();
                const Vec2 probe(0.5 * (a.x() + b.x()), wideAbove ? h - 0.05 : h + 0.05);
                const bool margin = ground.inMargin(d.frame.toWorld(probe));
                const double e = margin ? std::max(0.0, std::min(cap, p.grownMarginM - p.neighbourReachM)) : 0.0;
                const bool optional = !margin && p.flyOutsideArea;
                if (wideAbove)
                    w.push_back(Window{h + eps, h + 0.5 * s - e, optional});
                else
                    w.push_back(Window{h - 0.5 * s + e, h - eps, optional, true});
            }
        }
    }
}

// The lanes on the shared lines within the cell, then, for every window no lane meets yet (by
// their upper ends, as the greedy choice that meets all with the fewest lanes goes), a lane at the
// end farthest from the boundary its strip must reach. Lines are at most s apart, so the spacing
// holds; the outer windows keep the cell's edges covered.
// A cut or a step inside the cell (windows [2, innerEnd)) gets no lane of its own: the shared lines
// run on (the neighbour cell's line beyond the cut covers what the line below leaves, on the same
// lattice), and what they leave beside a zone's edge there (a wedge less than half a spacing deep)
// goes to spot photos (plan::chooseSpotPhotos), flown where they cost least; a lane per such window
// cost more turns than that on the generated areas (measured in the sweep note). The cell's bottom
// and top windows and the heights others lean on keep their lanes; the planner checks the finished
// plan's coverage before it prefers shared lines.
std::vector<double> onSharedLines(const std::vector<Window>& w, std::size_t innerEnd,
                                  const SweepLaneParams& p, double ylo, double yhi, double eps) {
    std::vector<double> ys(std::lower_bound(p.sharedLines.begin(), p.sharedLines.end(), ylo + eps),
                           std::upper_bound(p.sharedLines.begin(), p.sharedLines.end(), yhi - eps));
    std::vector<Window> need;
    for (std::size_t wi = 0; wi < w.size(); ++wi) {
        const auto& x = w[wi];
        const bool inner = !ys.empty() && wi >= 2 && wi < innerEnd;
        if (!x.optional && !inner)
            need.push_back(x);
    }
    std::sort(need.begin(), need.end(),
              [](const Window& a, const Window& b) { return a.hi < b.hi; });
    for (const auto& x : need)
        if (std::none_of(ys.begin(), ys.end(),
                         [&](double y) { return y >= x.lo - 1e-12 && y <= x.hi + 1e-12; }))
            ys.push_back(x.coversUp ? x.lo : x.hi);
    std::sort(ys.begin(), ys.end());
    return ys;
}

// The fewest lanes placed in the windows: windows kept for time only are dropped when that saves
// a lane.
std::vector<double> fewestLanes(const std::vector<Window>& w, double ylo, double yhi, double et,
                                double s, double eps) {
    const std::vector<double> all = place(w, ylo, yhi, et, s, eps);
    if (std::none_of(w.begin(), w.end(), [](const Window& x) { return x.optional; }))
        return all;
    std::vector<Window> needed;
    for (const auto& x : w)
        if (!x.optional)
            needed.push_back(x);
    const std::vector<double> fewer = place(needed, ylo, yhi, et, s, eps);
    return fewer.size() < all.size() ? fewer : all;
}

} // namespace

std::vector<double> laneHeights(const Decomposition& d, const MergedCell& m,
                                const SweepLaneParams& p, const SweepGround& ground,
                                std::optional<double> coverFrom, std::optional<double> coverTo,
                                const std::vector<double>& fixed) {
    const auto& first = d.cells[static_cast<std::size_t>(m.parts.front())];
    const auto& last = d.cells[static_cast<std::size_t>(m.parts.back())];
    const double ylo = first.ylo, yhi = last.yhi, s = p.trackSpacingM;
    if (yhi - ylo <= 0.04)
        return {0.5 * (ylo + yhi)};
    const double eps = 0.01;
    const double cap = 0.5 * s - 2 * eps;
    // The heights the outer strips must reach.
    const double from =
        coverFrom ? *coverFrom : ylo - std::min(cap, contactReach(d, first, false, p, ground));
    const double to =
        coverTo ? *coverTo : yhi + std::min(cap, contactReach(d, last, true, p, ground));
    if (m.parts.size() == 1 && from >= to && fixed.empty())
        return {};
    const double et = to - yhi;
    std::vector<Window> w;
    w.push_back(Window{ylo + eps, from + 0.5 * s});
    w.push_back(Window{to - 0.5 * s, yhi - eps, false, true});
    cutWindows(d, m, p, ground, cap, eps, w);
    stepWindows(d, m, p, ground, cap, eps, w);
    const std::size_t innerEnd = w.size(); // w[0], w[1]: the outer windows; then the cuts' and steps'
    for (double y : fixed)
        w.push_back(Window{y, y});
    if (m.parts.size() == 1 && w[0].hi >= w[1].lo && fixed.empty()) {
        // One lane does: in the middle of what it may take (on a shared line when one lies there).
        const double lo = std::max(ylo + eps, w[1].lo), hi = std::min(yhi - eps, w[0].hi);
        if (!p.sharedLines.empty() && lo <= hi) {
            const auto it = std::lower_bound(p.sharedLines.begin(), p.sharedLines.end(), lo);
            if (it != p.sharedLines.end() && *it <= hi)
                return {*it};
        }
        return {lo <= hi ? 0.5 * (lo + hi) : 0.5 * (ylo + yhi)};
    }
    for (auto& win : w) {
        win.lo = std::clamp(win.lo, ylo + eps, yhi - eps);
        win.hi = std::clamp(win.hi, ylo + eps, yhi - eps);
        if (win.lo > win.hi)
            win.lo = win.hi;
    }
    if (!p.sharedLines.empty())
        return onSharedLines(w, innerEnd, p, ylo, yhi, eps);
    return fewestLanes(w, ylo, yhi, et, s, eps);
}

std::vector<std::vector<double>> allLaneHeights(const Decomposition& d, const std::vector<MergedCell>& merged,
                                                const SweepLaneParams& p, const SweepGround& ground,
                                                std::vector<std::vector<char>>* pinned) {
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
    struct Lean {
        std::optional<double> from, to;
        std::vector<std::pair<int, int>> on; // (merged cell, lane) leaned on
    };
    std::vector<Lean> lean(merged.size());
    std::vector<char> leanedOn(merged.size(), 0);
    for (std::size_t i = 0; i < merged.size(); ++i) {
        const auto& m = merged[i];
        const auto& bottom = d.cells[static_cast<std::size_t>(m.parts.front())];
        const auto& top = d.cells[static_cast<std::size_t>(m.parts.back())];
        Lean& L = lean[i];
        // A cell below whose chain goes on past this cut (so it keeps a lane just under it) and whose
        // lane there spans this cell's bottom.
        for (int b : bottom.below) {
            const int mb = mergedOf[static_cast<std::size_t>(b)];
            const int pos = posOf[static_cast<std::size_t>(b)];
            if (mb < 0 || mb == static_cast<int>(i) || pos + 1 >= static_cast<int>(merged[static_cast<std::size_t>(mb)].parts.size()))
                continue;
            const auto& cb = d.cells[static_cast<std::size_t>(b)];
            const auto& ys = hs[static_cast<std::size_t>(mb)];
            for (std::size_t k = 0; k < ys.size(); ++k) {
                const double y = ys[k];
                if (y < cb.ylo || y > cb.yhi || y < bottom.ylo - 0.5 * s)
                    continue;
                if (cb.xLeft(y) <= bottom.xLeft(bottom.ylo) + tol && cb.xRight(y) >= bottom.xRight(bottom.ylo) - tol &&
                    y + 0.5 * s > L.from.value_or(-1e300)) {
                    L.from = y + 0.5 * s;
                    L.on.emplace_back(mb, static_cast<int>(k));
                }
            }
        }
        for (int a : top.above) {
            const int ma = mergedOf[static_cast<std::size_t>(a)];
            const int pos = posOf[static_cast<std::size_t>(a)];
            if (ma < 0 || ma == static_cast<int>(i) || pos == 0)
                continue;
            const auto& ca = d.cells[static_cast<std::size_t>(a)];
            const auto& ys = hs[static_cast<std::size_t>(ma)];
            for (std::size_t k = 0; k < ys.size(); ++k) {
                const double y = ys[k];
                if (y < ca.ylo || y > ca.yhi || y > top.yhi + 0.5 * s)
                    continue;
                if (ca.xLeft(y) <= top.xLeft(top.yhi) + tol && ca.xRight(y) >= top.xRight(top.yhi) - tol &&
                    y - 0.5 * s < L.to.value_or(1e300)) {
                    L.to = y - 0.5 * s;
                    L.on.emplace_back(ma, static_cast<int>(k));
                }
            }
        }
        for (const auto& [mc, k] : L.on)
            leanedOn[static_cast<std::size_t>(mc)] = 1;
    }
    // Every cell needs only what the lanes it leans on leave; a lane leaned on keeps its height.
    std::vector<std::vector<double>> fixed(merged.size());
    for (const auto& L : lean)
        for (const auto& [mc, k] : L.on)
            fixed[static_cast<std::size_t>(mc)].push_back(hs[static_cast<std::size_t>(mc)][static_cast<std::size_t>(k)]);
    std::vector<std::vector<double>> out = hs;
    for (std::size_t i = 0; i < merged.size(); ++i) {
        const Lean& L = lean[i];
        if (!L.from && !L.to)
            continue;
        out[i] = laneHeights(d, merged[i], p, ground, L.from, L.to, fixed[i]);
    }
    if (pinned) {
        pinned->assign(merged.size(), {});
        for (std::size_t i = 0; i < merged.size(); ++i) {
            (*pinned)[i].assign(out[i].size(), 0);
            for (std::size_t k = 0; k < out[i].size(); ++k)
                for (double y : fixed[i])
                    if (out[i][k] == y)
                        (*pinned)[i][k] = 1;
        }
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
    // The cell's extreme x between two heights, over all its parts (a part met over less than a
    // hair's height, where two lanes' bands meet at a cut, does not count).
    const double hair = 0.01 * s;
    auto extreme = [&](double y1, double y2, bool left, std::size_t own) {
        double x = left ? 1e300 : -1e300;
        for (std::size_t k = 0; k < m.parts.size(); ++k) {
            const auto& c = d.cells[static_cast<std::size_t>(m.parts[k])];
            const double a = std::max(y1, c.ylo), b = std::min(y2, c.yhi);
            if (a > b || (k != own && b - a < hair))
                continue;
            x = left ? std::min(x, c.minLeft(a, b)) : std::max(x, c.maxRight(a, b));
        }
        return x;
    };
    std::size_t part = 0;
    for (std::size_t j = 0; j < heights.size(); ++j) {
        const double y = heights[j];
        while (part + 1 < m.parts.size() && y > d.cells[static_cast<std::size_t>(m.parts[part])].yhi)
            ++part;
        const auto& cell = d.cells[static_cast<std::size_t>(m.parts[part])];
        double xl = cell.xLeft(y), xr = cell.xRight(y);
        if (xr < xl)
            xl = xr = 0.5 * (xl + xr);
        // The heights this lane answers for: its band less what the neighbour lanes' bands hold,
        // over every part of the cell (a part beside the lane's own may reach further there).
        double lo = y - 0.5 * s, hi = y + 0.5 * s;
        if (j > 0)
            lo = std::max(lo, std::min(y, heights[j - 1] + 0.5 * s));
        if (j + 1 < heights.size())
            hi = std::min(hi, std::max(y, heights[j + 1] - 0.5 * s));
        double sa = std::min(xl, extreme(lo, hi, true, part)), sb = std::max(xr, extreme(lo, hi, false, part));
        double fa = xl, fb = xr;
        const double inset = std::min(p.neighbourReachM, 0.25 * s);
        const double lb1 = std::max(lo, y - 0.5 * s + inset), ub2 = std::min(hi, y + 0.5 * s - inset);
        const double wrb = y > lb1 ? extreme(lb1, y, false, part) - xr : 0.0;
        const double wra = ub2 > y ? extreme(y, ub2, false, part) - xr : 0.0;
        const double wlb = y > lb1 ? xl - extreme(lb1, y, true, part) : 0.0;
        const double wla = ub2 > y ? xl - extreme(y, ub2, true, part) : 0.0;
        // What lies beyond each end along the lane's line.
        auto beyond = [&](double x, double dir, double& strip, double& fly) {
            const Vec2 e = d.frame.toWorld(Vec2(x, y));
            const Vec2 dirW = dir * u;
            const Vec2 q = e + 0.05 * dirW;
            if (!ground.insideArea(q)) {
                // Flown on over the area's edge up to the strip's end, but not back into the area (at a
                // notch of its outline the line returns over another cell) nor into a margin.
                double reach = dir > 0 ? strip - x : x - strip;
                if (p.flyOutsideArea && reach > 1e-6) {
                    reach = std::min(reach, ground.runToBoundary(e, dirW, reach + 1.0));
                    const double end = x + dir * reach;
                    if (safe(e, d.frame.toWorld(Vec2(end, y))))
                        fly = end;
                }
            } else if (ground.inMargin(q)) {
                const double run = ground.runToBoundary(e, dirW, p.marginRunCapM);
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

std::vector<double> latticeLines(double y0, double spacingM, double ylo, double yhi) {
    std::vector<double> out;
    if (!(spacingM > 0) || !(yhi >= ylo))
        return out;
    for (double k = std::floor((ylo - y0) / spacingM) - 1.0;; k += 1.0) {
        const double y = y0 + k * spacingM;
        if (y > yhi + spacingM)
            break;
        out.push_back(y);
    }
    return out;
}

std::vector<double> placeSharedLines(const Decomposition& d, double spacingM,
                                     const std::function<double(double, int)>& lineCost) {
    const double s = spacingM;
    if (d.cells.empty() || !(s > 0))
        return {};
    double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin;
    for (const auto& c : d.cells) {
        ymin = std::min(ymin, c.ylo);
        ymax = std::max(ymax, c.yhi);
    }
    // The same reach at the outer edges as the lattice laid from the lowest edge (0.02 m inside
    // half a spacing), and lines just off every cut: a line 3 cm under a zone's lowest point or
    // over its highest passes it.
    const double edge = 0.5 * s - 0.02, off = 0.03;
    const double bottomMax = ymin + edge, topMin = ymax - edge;
    if (bottomMax >= topMin)
        return {0.5 * (ymin + ymax)};
    std::vector<double> ys;
    const double step = s / 32.0;
    for (double y = ymin + off; y < ymax; y += step)
        ys.push_back(y);
    ys.push_back(bottomMax);
    ys.push_back(topMin);
    for (const auto& c : d.cells)
        for (double y : {c.ylo - off, c.ylo + off, c.yhi - off, c.yhi + off})
            if (y > ymin && y < ymax)
                ys.push_back(y);
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end(), [](double a, double b) { return b - a < 1e-6; }),
             ys.end());
    // Each candidate's cost: the cells it crosses (a sweep over the cells by height).
    std::vector<std::size_t> byLo(d.cells.size());
    for (std::size_t i = 0; i < byLo.size(); ++i)
        byLo[i] = i;
    std::sort(byLo.begin(), byLo.end(),
              [&](std::size_t a, std::size_t b) { return d.cells[a].ylo < d.cells[b].ylo; });
    std::vector<double> cost(ys.size());
    std::vector<std::size_t> active;
    std::size_t next = 0;
    for (std::size_t i = 0; i < ys.size(); ++i) {
        const double y = ys[i];
        while (next < byLo.size() && d.cells[byLo[next]].ylo < y)
            active.push_back(byLo[next++]);
        active.erase(std::remove_if(active.begin(), active.end(),
                                    [&](std::size_t c) { return d.cells[c].yhi <= y; }),
                     active.end());
        double len = 0.0;
        for (std::size_t c : active)
            len += std::max(0.0, d.cells[c].xRight(y) - d.cells[c].xLeft(y));
        cost[i] = lineCost(len, static_cast<int>(active.size()));
    }
    // best[i]: the least cost of lines from the bottom up to one at ys[i]; the window of lines
    // below within a spacing slides up with i (a deque of increasing best).
    constexpr double kInf = std::numeric_limits<double>::infinity();
    std::vector<double> best(ys.size(), kInf);
    std::vector<std::ptrdiff_t> prev(ys.size(), -1);
    std::deque<std::size_t> window;
    std::size_t enter = 0;
    for (std::size_t i = 0; i < ys.size(); ++i) {
        while (enter < i && ys[enter] < ys[i]) {
            if (best[enter] < kInf) {
                while (!window.empty() && best[window.back()] >= best[enter])
                    window.pop_back();
                window.push_back(enter);
            }
            ++enter;
        }
        while (!window.empty() && ys[i] - ys[window.front()] > s)
            window.pop_front();
        if (ys[i] <= bottomMax) {
            best[i] = cost[i];
        } else if (!window.empty()) {
            best[i] = best[window.front()] + cost[i];
            prev[i] = static_cast<std::ptrdiff_t>(window.front());
        }
    }
    std::ptrdiff_t end = -1;
    for (std::size_t i = 0; i < ys.size(); ++i)
        if (ys[i] >= topMin && best[i] < kInf &&
            (end < 0 || best[i] < best[static_cast<std::size_t>(end)]))
            end = static_cast<std::ptrdiff_t>(i);
    std::vector<double> out;
    for (std::ptrdiff_t i = end; i >= 0; i = prev[static_cast<std::size_t>(i)])
        out.push_back(ys[static_cast<std::size_t>(i)]);
    std::reverse(out.begin(), out.end());
    return out;
}

} // namespace pf::plan
