#include "core/plan/sweep/lane_trim.h"

#include "core/plan/lanes/lane.h"

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
    // needed(k) reads only the bands within `dependsWithin` of lane k's line: it is worked out again
    // at the lane's turn only when one of those changed since.
    std::vector<double> share(refs.size());
    std::vector<std::pair<double, double>> neededAtStart(refs.size());
    std::vector<char> stale(refs.size(), 0);
    const double dependsWithin = beyond + 0.5 * s + 1e-3;
    auto changed = [&](std::size_t j) {
        const auto first = std::lower_bound(ys.begin(), ys.end(), rects[j].y - dependsWithin);
        for (auto it = first; it != ys.end() && *it <= rects[j].y + dependsWithin; ++it)
            stale[byY[static_cast<std::size_t>(it - ys.begin())]] = 1;
    };
    for (std::size_t k = 0; k < refs.size(); ++k) {
        neededAtStart[k] = needed(k);
        const auto [lo, hi] = neededAtStart[k];
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
        const auto [lo, hi] = stale[k] ? needed(k) : neededAtStart[k];
        if (lo > hi) {
            rects[k].gone = true;
            changed(k);
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
        changed(k);
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

int dropCoveredLanes(const Decomposition& d, std::vector<std::vector<CellLane>>& lanes,
                     const std::vector<std::vector<char>>& pinned, const SweepLaneParams& p, const SweepGround& ground,
                     double realAcrossM, double realAlongM, double maxLengthM) {
    struct Ref {
        std::size_t cell, lane;
    };
    std::vector<Ref> all, candidates;
    for (std::size_t c = 0; c < lanes.size(); ++c)
        for (std::size_t j = 0; j < lanes[c].size(); ++j) {
            all.push_back(Ref{c, j});
            const auto& l = lanes[c][j];
            const bool pin = c < pinned.size() && j < pinned[c].size() && pinned[c][j];
            if (!pin && (l.flyB - l.flyA).norm() <= maxLengthM)
                candidates.push_back(Ref{c, j});
        }
    if (candidates.empty())
        return 0;
    std::stable_sort(candidates.begin(), candidates.end(), [&](const Ref& a, const Ref& b) {
        const auto &la = lanes[a.cell][a.lane], &lb = lanes[b.cell][b.lane];
        return (la.flyB - la.flyA).squaredNorm() < (lb.flyB - lb.flyA).squaredNorm();
    });
    const double s = p.trackSpacingM;
    const double pad = 0.5 * std::hypot(realAcrossM, realAlongM) + 0.5 * s;
    // Lanes by the box of their strip, on a grid, to find the photos near a candidate.
    geo::Box whole{lanes[all.front().cell][all.front().lane].stripA, lanes[all.front().cell][all.front().lane].stripA};
    std::vector<geo::Box> boxes;
    boxes.reserve(all.size());
    for (const auto& r : all) {
        const auto& l = lanes[r.cell][r.lane];
        geo::Box b{l.stripA.cwiseMin(l.stripB), l.stripA.cwiseMax(l.stripB)};
        b.min -= Vec2(pad, pad);
        b.max += Vec2(pad, pad);
        boxes.push_back(b);
        whole.min = whole.min.cwiseMin(b.min);
        whole.max = whole.max.cwiseMax(b.max);
    }
    const double g = std::max(50.0, 2 * pad);
    const int nx = static_cast<int>((whole.max.x() - whole.min.x()) / g) + 1;
    const int ny = static_cast<int>((whole.max.y() - whole.min.y()) / g) + 1;
    std::vector<std::vector<int>> grid(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
    auto cellRange = [&](const geo::Box& b, int& x0, int& y0, int& x1, int& y1) {
        x0 = std::clamp(static_cast<int>((b.min.x() - whole.min.x()) / g), 0, nx - 1);
        y0 = std::clamp(static_cast<int>((b.min.y() - whole.min.y()) / g), 0, ny - 1);
        x1 = std::clamp(static_cast<int>((b.max.x() - whole.min.x()) / g), 0, nx - 1);
        y1 = std::clamp(static_cast<int>((b.max.y() - whole.min.y()) / g), 0, ny - 1);
    };
    for (std::size_t i = 0; i < all.size(); ++i) {
        int x0, y0, x1, y1;
        cellRange(boxes[i], x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                grid[static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(x)].push_back(static_cast<int>(i));
    }
    std::vector<char> dropped(all.size(), 0);
    std::vector<std::vector<Vec2>> photos(all.size());
    std::vector<char> built(all.size(), 0);
    std::vector<std::size_t> offset(lanes.size() + 1, 0);
    for (std::size_t c = 0; c < lanes.size(); ++c)
        offset[c + 1] = offset[c] + lanes[c].size();
    auto refIndex = [&](const Ref& r) { return offset[r.cell] + r.lane; };
    const double ha = 0.5 * realAlongM, hc = 0.5 * realAcrossM;
    const Vec2 u = d.frame.toWorld(Vec2(1, 0)); // every lane runs along u: footprints are aligned with it
    const double r = std::clamp(s / 20.0, 0.25, 1.5);
    int count = 0;
    for (const auto& cand : candidates) {
        const std::size_t ci = refIndex(cand);
        const CellLane& l = lanes[cand.cell][cand.lane];
        // the photos of the other lanes near it
        int x0, y0, x1, y1;
        cellRange(boxes[ci], x0, y0, x1, y1);
        std::vector<int> near;
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                for (int o : grid[static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(x)])
                    if (static_cast<std::size_t>(o) != ci && !dropped[static_cast<std::size_t>(o)] && boxes[static_cast<std::size_t>(o)].intersects(boxes[ci]))
                        near.push_back(o);
        std::sort(near.begin(), near.end());
        near.erase(std::unique(near.begin(), near.end()), near.end());
        std::vector<Vec2> pts;
        for (int o : near) {
            const auto& ref = all[static_cast<std::size_t>(o)];
            if (!built[static_cast<std::size_t>(o)]) {
                const auto& ol = lanes[ref.cell][ref.lane];
                photos[static_cast<std::size_t>(o)] = makeLane(ol.stripA, ol.stripB, p.photoSpacingM, ol.flyA, ol.flyB).photos;
                built[static_cast<std::size_t>(o)] = 1;
            }
            pts.insert(pts.end(), photos[static_cast<std::size_t>(o)].begin(), photos[static_cast<std::size_t>(o)].end());
        }
        // The photos whose footprint may overlap the one of the own photo being checked: a point of
        // that footprint is seen by no other (1 m spare for rounding).
        std::vector<Vec2> close;
        auto seen = [&](const Vec2& q) {
            for (const auto& c : close) {
                const Vec2 dq = q - c;
                if (std::abs(dq.dot(u)) <= ha && std::abs(u.x() * dq.y() - u.y() * dq.x()) <= hc)
                    return true;
            }
            return false;
        };
        // Everything its own photos see that is ground must be seen by another photo too.
        const std::vector<Vec2> own = makeLane(l.stripA, l.stripB, p.photoSpacingM, l.flyA, l.flyB).photos;
        const Vec2 v(-u.y(), u.x());
        bool covered = !pts.empty();
        for (std::size_t k = 0; covered && k < own.size(); ++k) {
            close.clear();
            for (const auto& c : pts) {
                const Vec2 dc = own[k] - c;
                if (std::abs(dc.dot(u)) <= 2 * ha + 1.0 && std::abs(u.x() * dc.y() - u.y() * dc.x()) <= 2 * hc + 1.0)
                    close.push_back(c);
            }
            for (double b = -hc + 0.5 * r; covered && b < hc; b += r)
                for (double a = -ha + 0.5 * r; covered && a < ha; a += r) {
                    const Vec2 q = own[k] + a * u + b * v;
                    if (!seen(q) && ground.insideArea(q) && !ground.inZone(q))
                        covered = false;
                }
        }
        if (covered) {
            dropped[ci] = 1;
            ++count;
        }
    }
    // remove the dropped lanes
    std::size_t k = 0;
    for (auto& cl : lanes) {
        std::vector<CellLane> keep;
        for (auto& l : cl)
            if (!dropped[k++])
                keep.push_back(l);
        cl = std::move(keep);
    }
    return count;
}

} // namespace pf::plan

