#include "core/plan/lane_trim.h"

#include "core/plan/lane.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace pf::plan {

using geo::Vec2;

namespace {

struct Rect {
    double y = 0.0, x0 = 0.0, x1 = 0.0; // band centre and effective extent along (frame)
    bool gone = false;
};

Rect rectOf(const Decomposition& d, const CellLane& l, double photoSpacing) {
    const double a = d.frame.toFrame(l.span.first).x(), b = d.frame.toFrame(l.span.last).x();
    return Rect{l.y, std::min(a, b) - 0.5 * photoSpacing, std::max(a, b) + 0.5 * photoSpacing, false};
}

} // namespace

LaneTrimStats trimCoveredLanes(const Decomposition& d, std::vector<std::vector<CellLane>>& lanes,
                               const SweepLaneParams& p, const SweepGround& ground, double stepM,
                               const std::vector<char>* flownCells) {
    LaneTrimStats stats;
    const double s = p.trackSpacingM, ph = p.photoSpacingM, h = std::max(0.25, stepM);
    struct Ref {
        std::size_t cell, lane;
    };
    std::vector<Ref> refs;
    std::vector<Rect> rects;
    for (std::size_t c = 0; c < lanes.size(); ++c)
        for (std::size_t j = 0; j < lanes[c].size(); ++j) {
            if (flownCells && c < flownCells->size() && !(*flownCells)[c])
                continue; // never flown: it sees nothing, and nothing is gained by shortening it
            refs.push_back(Ref{c, j});
            rects.push_back(rectOf(d, lanes[c][j], ph));
        }
    if (refs.size() < 2)
        return stats;
    // Lanes by height, for the neighbours whose bands reach a line.
    std::vector<std::size_t> byY(refs.size());
    std::iota(byY.begin(), byY.end(), std::size_t{0});
    std::sort(byY.begin(), byY.end(), [&](std::size_t a, std::size_t b) { return rects[a].y < rects[b].y; });
    std::vector<double> ys(byY.size());
    for (std::size_t k = 0; k < byY.size(); ++k)
        ys[k] = rects[byY[k]].y;

    // Lines a step apart across the band and on beyond it as far as the real footprint sees past the
    // band (ground there, in a margin say, that the neighbour lane does not fly over, only this lane
    // sees); the lane's own line first: in an open field it alone shows the lane needed end to end.
    const double beyond = p.neighbourReachM > 0.1 ? 0.5 * s + p.neighbourReachM - 0.05 : 0.5 * s - 0.02;
    std::vector<double> offsets{0.0, -0.5 * s + 0.02, 0.5 * s - 0.02};
    {
        const int n = std::max(4, static_cast<int>(std::ceil(2.0 * beyond / h)));
        for (int i = 0; i <= n; ++i)
            offsets.push_back(-beyond + 2.0 * beyond * i / n);
    }
    // What others leave uncovered of line y over [a, b]: sorted disjoint intervals.
    auto uncovered = [&](std::size_t self, double y, double a, double b) {
        std::vector<std::pair<double, double>> cov;
        const auto lo = std::lower_bound(ys.begin(), ys.end(), y - 0.5 * s - 1e-9);
        for (auto it = lo; it != ys.end() && *it <= y + 0.5 * s + 1e-9; ++it) {
            const std::size_t k = byY[static_cast<std::size_t>(it - ys.begin())];
            const Rect& r = rects[k];
            if (k == self || r.gone || std::abs(r.y - y) > 0.5 * s + 1e-9 || r.x1 <= a || r.x0 >= b)
                continue;
            cov.emplace_back(r.x0, r.x1);
        }
        std::sort(cov.begin(), cov.end());
        std::vector<std::pair<double, double>> out;
        double at = a;
        for (const auto& [c0, c1] : cov) {
            if (c0 > at)
                out.emplace_back(at, std::min(c0, b));
            at = std::max(at, c1);
            if (at >= b)
                break;
        }
        if (at < b)
            out.emplace_back(at, b);
        return out;
    };
    auto needs = [&](double x, double y) {
        const Vec2 w = d.frame.toWorld(Vec2(x, y));
        return ground.insideArea(w) && !ground.inZone(w);
    };
    // The stretch [lo, hi] of lane k's strip where its band holds ground only it sees; empty: lo > hi.
    auto needed = [&](std::size_t k) {
        const CellLane& l = lanes[refs[k].cell][refs[k].lane];
        const double sa = d.frame.toFrame(l.stripA).x(), sb = d.frame.toFrame(l.stripB).x();
        // Along too as far as its real footprint sees past the effective one (ground in a pocket
        // between two zones, say, that only this lane's end photo reaches).
        const double past = std::max(0.0, p.reachAlongM - 0.5 * ph - 0.05);
        const double a = std::max(std::min(sa, sb) - past, rects[k].x0 - past);
        const double b = std::min(std::max(sa, sb) + past, rects[k].x1 + past);
        double lo = 1e300, hi = -1e300;
        // Gaps between the other bands open just past their edges: probe there too.
        std::vector<double> probes = offsets;
        {
            const auto first = std::lower_bound(ys.begin(), ys.end(), l.y - beyond - 0.5 * s);
            for (auto it = first; it != ys.end() && *it <= l.y + beyond + 0.5 * s; ++it) {
                const Rect& r = rects[byY[static_cast<std::size_t>(it - ys.begin())]];
                if (r.gone || r.x1 <= a || r.x0 >= b)
                    continue;
                for (double e : {r.y + 0.5 * s + 0.02 - l.y, r.y - 0.5 * s - 0.02 - l.y})
                    if (std::abs(e) <= beyond)
                        probes.push_back(e);
            }
        }
        for (double o : probes) {
            if (lo <= rects[k].x0 + h && hi >= rects[k].x1 - h)
                break; // needed from end to end: nothing to shorten
            const double y = l.y + o;
            const auto gaps = uncovered(k, y, a, b);
            // from the left: the first needing point
            for (const auto& [g0, g1] : gaps) {
                if (g0 >= lo)
                    break;
                bool found = false;
                for (double x = g0;; x += h) {
                    const double xx = std::min(x, g1);
                    if (xx >= lo)
                        break;
                    if (needs(xx, y)) {
                        lo = xx;
                        found = true;
                        break;
                    }
                    if (xx >= g1)
                        break;
                }
                if (found)
                    break;
            }
            for (auto it = gaps.rbegin(); it != gaps.rend(); ++it) {
                const auto& [g0, g1] = *it;
                if (g1 <= hi)
                    break;
                bool found = false;
                for (double x = g1;; x -= h) {
                    const double xx = std::max(x, g0);
                    if (xx <= hi)
                        break;
                    if (needs(xx, y)) {
                        hi = xx;
                        found = true;
                        break;
                    }
                    if (xx <= g0)
                        break;
                }
                if (found)
                    break;
            }
        }
        return std::make_pair(lo, hi);
    };
    // Most redundant first: by the share of the strip others leave, measured before any change.
    std::vector<double> share(refs.size());
    for (std::size_t k = 0; k < refs.size(); ++k) {
        const auto [lo, hi] = needed(k);
        const double len = rects[k].x1 - rects[k].x0;
        share[k] = lo > hi ? 0.0 : (hi - lo) / std::max(len, 1e-9);
    }
    std::vector<std::size_t> order(refs.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return share[a] < share[b]; });
    std::vector<std::vector<char>> drop(lanes.size());
    for (std::size_t c = 0; c < lanes.size(); ++c)
        drop[c].assign(lanes[c].size(), 0);
    for (std::size_t k : order) {
        if (share[k] >= 1.0 - 1e-9)
            continue; // needed from end to end before any change: it stays so
        CellLane& l = lanes[refs[k].cell][refs[k].lane];
        const auto [lo, hi] = needed(k);
        if (lo > hi) {
            rects[k].gone = true;
            drop[refs[k].cell][refs[k].lane] = 1;
            ++stats.dropped;
            stats.savedM += (l.stripB - l.stripA).norm();
            continue;
        }
        const double sa = d.frame.toFrame(l.stripA).x(), sb = d.frame.toFrame(l.stripB).x();
        const double fa = d.frame.toFrame(l.flyA).x(), fb = d.frame.toFrame(l.flyB).x();
        // Needed up to the end of what its photos see with the effective footprint: that end stays
        // (the strip may run on through a margin's ground that only the real footprint sees).
        // Whole trigger distances come off an end, so that the photos kept stay where they were (the
        // lane's photos are centred on its strip): what they saw, they still see.
        const double na = lo <= rects[k].x0 + h ? sa : sa + std::floor(std::max(0.0, lo - h - sa) / ph) * ph;
        const double nb = hi >= rects[k].x1 - h ? sb : sb - std::floor(std::max(0.0, sb - hi - h) / ph) * ph;
        if (na >= nb) {
            continue; // what it alone sees lies past its photos' reach along: it stays as it is
        }
        if (na <= sa + 1e-6 && nb >= sb - 1e-6)
            continue;
        const double nfa = std::clamp(na, fa, fb), nfb = std::clamp(nb, fa, fb);
        stats.savedM += (nb - na < sb - sa) ? (sb - sa) - (nb - na) : 0.0;
        ++stats.shortened;
        if (na > sa + 1e-6)
            l.wedgeLeftBelow = l.wedgeLeftAbove = 0.0;
        if (nb < sb - 1e-6)
            l.wedgeRightBelow = l.wedgeRightAbove = 0.0;
        l.stripA = d.frame.toWorld(Vec2(na, l.y));
        l.stripB = d.frame.toWorld(Vec2(nb, l.y));
        l.flyA = d.frame.toWorld(Vec2(nfa, l.y));
        l.flyB = d.frame.toWorld(Vec2(nfb, l.y));
        l.span = laneSpan(l.stripA, l.stripB, ph, l.flyA, l.flyB);
        rects[k] = rectOf(d, l, ph);
    }
    for (std::size_t c = 0; c < lanes.size(); ++c) {
        std::vector<CellLane> kept;
        kept.reserve(lanes[c].size());
        for (std::size_t j = 0; j < lanes[c].size(); ++j)
            if (!drop[c][j])
                kept.push_back(std::move(lanes[c][j]));
        lanes[c] = std::move(kept);
    }
    return stats;
}

} // namespace pf::plan

