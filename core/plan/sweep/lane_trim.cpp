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

struct LaneRef {
    std::size_t cell, lane;
};

// The first point, from the left, of the gaps of line y (sorted, disjoint) where ground needs a
// photo, probed every h; below `lo`, which it lowers. `needs(x, y)`: ground to photograph.
template <class Needs>
void lowerFirstNeeded(const std::vector<std::pair<double, double>>& gaps, double y, double h,
                      double& lo, const Needs& needs) {
    for (const auto& [g0, g1] : gaps) {
        if (g0 >= lo)
            break;
        for (double x = g0;; x += h) {
            const double xx = std::min(x, g1);
            if (xx >= lo)
                break;
            if (needs(xx, y)) {
                lo = xx;
                return;
            }
            if (xx >= g1)
                break;
        }
    }
}

// As lowerFirstNeeded from the right: raises `hi` to the last needing point above it.
template <class Needs>
void raiseLastNeeded(const std::vector<std::pair<double, double>>& gaps, double y, double h,
                     double& hi, const Needs& needs) {
    for (auto it = gaps.rbegin(); it != gaps.rend(); ++it) {
        const auto& [g0, g1] = *it;
        if (g1 <= hi)
            break;
        for (double x = g1;; x -= h) {
            const double xx = std::max(x, g0);
            if (xx <= hi)
                break;
            if (needs(xx, y)) {
                hi = xx;
                return;
            }
            if (xx <= g0)
                break;
        }
    }
}

// The lanes' effective rectangles while they are trimmed, and what each still needs to fly.
class LaneTrimmer {
public:
    LaneTrimmer(const Decomposition& d, std::vector<std::vector<CellLane>>& lanes,
                const SweepLaneParams& p, const SweepGround& ground, double stepM,
                const std::vector<char>* flownCells)
        : m_d(d), m_lanes(lanes), m_p(p), m_ground(ground), m_s(p.trackSpacingM),
          m_ph(p.photoSpacingM), m_h(std::max(0.25, stepM)) {
        for (std::size_t c = 0; c < lanes.size(); ++c)
            for (std::size_t j = 0; j < lanes[c].size(); ++j) {
                if (flownCells && c < flownCells->size() && !(*flownCells)[c])
                    continue; // never flown: it sees nothing, and nothing is gained by shortening
                              // it
                m_refs.push_back(LaneRef{c, j});
                m_rects.push_back(rectOf(d, lanes[c][j], m_ph));
            }
    }

    LaneTrimStats run() {
        if (m_refs.size() < 2)
            return m_stats;
        sortByHeight();
        probeLines();
        // Most redundant first: by the share of the strip others leave, measured before any change.
        // needed(k) reads only the bands within `dependsWithin` of lane k's line: it is worked out
        // again at the lane's turn only when one of those changed since.
        std::vector<double> share(m_refs.size());
        std::vector<std::pair<double, double>> neededAtStart(m_refs.size());
        m_stale.assign(m_refs.size(), 0);
        for (std::size_t k = 0; k < m_refs.size(); ++k) {
            neededAtStart[k] = needed(k);
            const auto [lo, hi] = neededAtStart[k];
            const double len = m_rects[k].x1 - m_rects[k].x0;
            share[k] = lo > hi ? 0.0 : (hi - lo) / std::max(len, 1e-9);
        }
        std::vector<std::size_t> order(m_refs.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return share[a] < share[b]; });
        std::vector<std::vector<char>> drop(m_lanes.size());
        for (std::size_t c = 0; c < m_lanes.size(); ++c)
            drop[c].assign(m_lanes[c].size(), 0);
        for (std::size_t k : order) {
            if (share[k] >= 1.0 - 1e-9)
                continue; // needed from end to end before any change: it stays so
            const auto [lo, hi] = m_stale[k] ? needed(k) : neededAtStart[k];
            if (lo > hi) {
                const CellLane& l = m_lanes[m_refs[k].cell][m_refs[k].lane];
                m_rects[k].gone = true;
                changed(k);
                drop[m_refs[k].cell][m_refs[k].lane] = 1;
                ++m_stats.dropped;
                m_stats.savedM += (l.stripB - l.stripA).norm();
                continue;
            }
            shorten(k, lo, hi);
        }
        removeDropped(drop);
        return m_stats;
    }

private:
    // Lanes by height, for the neighbours whose bands reach a line.
    void sortByHeight() {
        m_byY.resize(m_refs.size());
        std::iota(m_byY.begin(), m_byY.end(), std::size_t{0});
        std::sort(m_byY.begin(), m_byY.end(),
                  [&](std::size_t a, std::size_t b) { return m_rects[a].y < m_rects[b].y; });
        m_ys.resize(m_byY.size());
        for (std::size_t k = 0; k < m_byY.size(); ++k)
            m_ys[k] = m_rects[m_byY[k]].y;
    }

    // Lines a step apart across the band and on beyond it as far as the real footprint sees past the
    // band (ground there, in a margin say, that the neighbour lane does not fly over, only this lane
    // sees); the lane's own line first: in an open field it alone shows the lane needed end to end.
    void probeLines() {
        const double s = m_s;
        m_beyond =
            m_p.neighbourReachM > 0.1 ? 0.5 * s + m_p.neighbourReachM - 0.05 : 0.5 * s - 0.02;
        m_offsets = {0.0, -0.5 * s + 0.02, 0.5 * s - 0.02};
        const int n = std::max(4, static_cast<int>(std::ceil(2.0 * m_beyond / m_h)));
        for (int i = 0; i <= n; ++i)
            m_offsets.push_back(-m_beyond + 2.0 * m_beyond * i / n);
    }

    // What others leave uncovered of line y over [a, b]: sorted disjoint intervals.
    std::vector<std::pair<double, double>> uncovered(std::size_t self, double y, double a,
                                                     double b) const {
        const double s = m_s;
        std::vector<std::pair<double, double>> cov;
        const auto lo = std::lower_bound(m_ys.begin(), m_ys.end(), y - 0.5 * s - 1e-9);
        for (auto it = lo; it != m_ys.end() && *it <= y + 0.5 * s + 1e-9; ++it) {
            const std::size_t k = m_byY[static_cast<std::size_t>(it - m_ys.begin())];
            const Rect& r = m_rects[k];
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
    }

    // The lines lane l is probed on: the offsets, and where the gaps between the other bands over
    // [a, b] open, just past their edges.
    std::vector<double> probesOf(const CellLane& l, double a, double b) const {
        const double s = m_s;
        std::vector<double> probes = m_offsets;
        const auto first = std::lower_bound(m_ys.begin(), m_ys.end(), l.y - m_beyond - 0.5 * s);
        for (auto it = first; it != m_ys.end() && *it <= l.y + m_beyond + 0.5 * s; ++it) {
            const Rect& r = m_rects[m_byY[static_cast<std::size_t>(it - m_ys.begin())]];
            if (r.gone || r.x1 <= a || r.x0 >= b)
                continue;
            for (double e : {r.y + 0.5 * s + 0.02 - l.y, r.y - 0.5 * s - 0.02 - l.y})
                if (std::abs(e) <= m_beyond)
                    probes.push_back(e);
        }
        return probes;
    }

    // The stretch [lo, hi] of lane k's strip where its band holds ground only it sees; empty: lo > hi.
    std::pair<double, double> needed(std::size_t k) const {
        const CellLane& l = m_lanes[m_refs[k].cell][m_refs[k].lane];
        const double sa = m_d.frame.toFrame(l.stripA).x(), sb = m_d.frame.toFrame(l.stripB).x();
        // Along too as far as its real footprint sees past the effective one (ground in a pocket
        // between two zones, say, that only this lane's end photo reaches).
        const double past = std::max(0.0, m_p.reachAlongM - 0.5 * m_ph - 0.05);
        const double a = std::max(std::min(sa, sb) - past, m_rects[k].x0 - past);
        const double b = std::min(std::max(sa, sb) + past, m_rects[k].x1 + past);
        double lo = 1e300, hi = -1e300;
        auto needs = [&](double x, double y) {
            const Vec2 w = m_d.frame.toWorld(Vec2(x, y));
            return m_ground.insideArea(w) && !m_ground.inZone(w);
        };
        for (double o : probesOf(l, a, b)) {
            if (lo <= m_rects[k].x0 + m_h && hi >= m_rects[k].x1 - m_h)
                break; // needed from end to end: nothing to shorten
            const double y = l.y + o;
            const auto gaps = uncovered(k, y, a, b);
            lowerFirstNeeded(gaps, y, m_h, lo, needs);
            raiseLastNeeded(gaps, y, m_h, hi, needs);
        }
        return {lo, hi};
    }

    // Lane j's band changed: the lanes whose needed stretch depends on it are stale.
    void changed(std::size_t j) {
        const double dependsWithin = m_beyond + 0.5 * m_s + 1e-3;
        const auto first = std::lower_bound(m_ys.begin(), m_ys.end(), m_rects[j].y - dependsWithin);
        for (auto it = first; it != m_ys.end() && *it <= m_rects[j].y + dependsWithin; ++it)
            m_stale[m_byY[static_cast<std::size_t>(it - m_ys.begin())]] = 1;
    }

    // Lane k shortened to the needed stretch [lo, hi] (a non-empty one).
    void shorten(std::size_t k, double lo, double hi) {
        CellLane& l = m_lanes[m_refs[k].cell][m_refs[k].lane];
        const double ph = m_ph, h = m_h;
        const double sa = m_d.frame.toFrame(l.stripA).x(), sb = m_d.frame.toFrame(l.stripB).x();
        const double fa = m_d.frame.toFrame(l.flyA).x(), fb = m_d.frame.toFrame(l.flyB).x();
        // Needed up to the end of what its photos see with the effective footprint: that end stays
        // (the strip may run on through a margin's ground that only the real footprint sees).
        // Whole trigger distances come off an end, so that the photos kept stay where they were (the
        // lane's photos are centred on its strip): what they saw, they still see.
        const double na =
            lo <= m_rects[k].x0 + h ? sa : sa + std::floor(std::max(0.0, lo - h - sa) / ph) * ph;
        const double nb =
            hi >= m_rects[k].x1 - h ? sb : sb - std::floor(std::max(0.0, sb - hi - h) / ph) * ph;
        if (na >= nb)
            return; // what it alone sees lies past its photos' reach along: it stays as it is
        if (na <= sa + 1e-6 && nb >= sb - 1e-6)
            return;
        const double nfa = std::clamp(na, fa, fb), nfb = std::clamp(nb, fa, fb);
        m_stats.savedM += (nb - na < sb - sa) ? (sb - sa) - (nb - na) : 0.0;
        ++m_stats.shortened;
        if (na > sa + 1e-6)
            l.wedgeLeftBelow = l.wedgeLeftAbove = 0.0;
        if (nb < sb - 1e-6)
            l.wedgeRightBelow = l.wedgeRightAbove = 0.0;
        l.stripA = m_d.frame.toWorld(Vec2(na, l.y));
        l.stripB = m_d.frame.toWorld(Vec2(nb, l.y));
        l.flyA = m_d.frame.toWorld(Vec2(nfa, l.y));
        l.flyB = m_d.frame.toWorld(Vec2(nfb, l.y));
        l.span = laneSpan(l.stripA, l.stripB, ph, l.flyA, l.flyB);
        m_rects[k] = rectOf(m_d, l, ph);
        changed(k);
    }

    void removeDropped(const std::vector<std::vector<char>>& drop) {
        for (std::size_t c = 0; c < m_lanes.size(); ++c) {
            std::vector<CellLane> kept;
            kept.reserve(m_lanes[c].size());
            for (std::size_t j = 0; j < m_lanes[c].size(); ++j)
                if (!drop[c][j])
                    kept.push_back(std::move(m_lanes[c][j]));
            m_lanes[c] = std::move(kept);
        }
    }

    const Decomposition& m_d;
    std::vector<std::vector<CellLane>>& m_lanes;
    const SweepLaneParams& m_p;
    const SweepGround& m_ground;
    const double m_s, m_ph, m_h; // track spacing, trigger distance, probe step
    std::vector<LaneRef> m_refs; // the lanes of the flown cells
    std::vector<Rect> m_rects;   // per ref
    std::vector<std::size_t> m_byY;
    std::vector<double> m_ys;
    double m_beyond = 0.0;         // how far past its line a lane's real footprint sees
    std::vector<double> m_offsets; // the probe lines, from a lane's line
    std::vector<char> m_stale;
    LaneTrimStats m_stats;
};

// The lanes' strips grown by `pad`, on a grid of cells at least 50 m wide, to find the lanes near
// one.
class LaneBoxes {
public:
    LaneBoxes(const std::vector<std::vector<CellLane>>& lanes, const std::vector<LaneRef>& all,
              double pad) {
        m_whole = geo::Box{lanes[all.front().cell][all.front().lane].stripA,
                           lanes[all.front().cell][all.front().lane].stripA};
        m_boxes.reserve(all.size());
        for (const auto& r : all) {
            const auto& l = lanes[r.cell][r.lane];
            geo::Box b{l.stripA.cwiseMin(l.stripB), l.stripA.cwiseMax(l.stripB)};
            b.min -= Vec2(pad, pad);
            b.max += Vec2(pad, pad);
            m_boxes.push_back(b);
            m_whole.min = m_whole.min.cwiseMin(b.min);
            m_whole.max = m_whole.max.cwiseMax(b.max);
        }
        m_g = std::max(50.0, 2 * pad);
        m_nx = static_cast<int>((m_whole.max.x() - m_whole.min.x()) / m_g) + 1;
        m_ny = static_cast<int>((m_whole.max.y() - m_whole.min.y()) / m_g) + 1;
        m_grid.resize(static_cast<std::size_t>(m_nx) * static_cast<std::size_t>(m_ny));
        for (std::size_t i = 0; i < all.size(); ++i)
            forCells(m_boxes[i], [&](std::vector<int>& at) { at.push_back(static_cast<int>(i)); });
    }

    // The lanes other than i, not dropped, whose box meets lane i's, in increasing order.
    std::vector<int> near(std::size_t i, const std::vector<char>& dropped) {
        std::vector<int> out;
        forCells(m_boxes[i], [&](const std::vector<int>& at) {
            for (int o : at)
                if (static_cast<std::size_t>(o) != i && !dropped[static_cast<std::size_t>(o)] &&
                    m_boxes[static_cast<std::size_t>(o)].intersects(m_boxes[i]))
                    out.push_back(o);
        });
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }

private:
    template <class Fn> void forCells(const geo::Box& b, Fn fn) {
        const int x0 =
            std::clamp(static_cast<int>((b.min.x() - m_whole.min.x()) / m_g), 0, m_nx - 1);
        const int y0 =
            std::clamp(static_cast<int>((b.min.y() - m_whole.min.y()) / m_g), 0, m_ny - 1);
        const int x1 =
            std::clamp(static_cast<int>((b.max.x() - m_whole.min.x()) / m_g), 0, m_nx - 1);
        const int y1 =
            std::clamp(static_cast<int>((b.max.y() - m_whole.min.y()) / m_g), 0, m_ny - 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                fn(m_grid[static_cast<std::size_t>(y) * static_cast<std::size_t>(m_nx) +
                          static_cast<std::size_t>(x)]);
    }

    geo::Box m_whole;
    std::vector<geo::Box> m_boxes;
    double m_g = 0.0;
    int m_nx = 0, m_ny = 0;
    std::vector<std::vector<int>> m_grid;
};

// Whether every point of ground the photos `own` see (footprints across x along, aligned with the
// lanes' direction u) is seen by a photo of `others` too, probed every r metres (1 m spare for
// rounding where the footprints may meet).
bool seenByOthers(const std::vector<Vec2>& own, const std::vector<Vec2>& others, const Vec2& u,
                  double hc, double ha, double r, const SweepGround& ground) {
    std::vector<Vec2> close;
    auto seen = [&](const Vec2& q) {
        for (const auto& c : close) {
            const Vec2 dq = q - c;
            if (std::abs(dq.dot(u)) <= ha && std::abs(u.x() * dq.y() - u.y() * dq.x()) <= hc)
                return true;
        }
        return false;
    };
    const Vec2 v(-u.y(), u.x());
    bool covered = !others.empty();
    for (std::size_t k = 0; covered && k < own.size(); ++k) {
        close.clear();
        for (const auto& c : others) {
            const Vec2 dc = own[k] - c;
            if (std::abs(dc.dot(u)) <= 2 * ha + 1.0 &&
                std::abs(u.x() * dc.y() - u.y() * dc.x()) <= 2 * hc + 1.0)
                close.push_back(c);
        }
        for (double b = -hc + 0.5 * r; covered && b < hc; b += r)
            for (double a = -ha + 0.5 * r; covered && a < ha; a += r) {
                const Vec2 q = own[k] + a * u + b * v;
                if (!seen(q) && ground.insideArea(q) && !ground.inZone(q))
                    covered = false;
            }
    }
    return covered;
}

} // namespace

LaneTrimStats trimCoveredLanes(const Decomposition& d, std::vector<std::vector<CellLane>>& lanes,
                               const SweepLaneParams& p, const SweepGround& ground, double stepM,
                               const std::vector<char>* flownCells) {
    return LaneTrimmer(d, lanes, p, ground, stepM, flownCells).run();
}

int dropCoveredLanes(const Decomposition& d, std::vector<std::vector<CellLane>>& lanes,
                     const std::vector<std::vector<char>>& pinned, const SweepLaneParams& p, const SweepGround& ground,
                     double realAcrossM, double realAlongM, double maxLengthM) {
    std::vector<LaneRef> all, candidates;
    for (std::size_t c = 0; c < lanes.size(); ++c)
        for (std::size_t j = 0; j < lanes[c].size(); ++j) {
            all.push_back(LaneRef{c, j});
            const auto& l = lanes[c][j];
            const bool pin = c < pinned.size() && j < pinned[c].size() && pinned[c][j];
            if (!pin && (l.flyB - l.flyA).norm() <= maxLengthM)
                candidates.push_back(LaneRef{c, j});
        }
    if (candidates.empty())
        return 0;
    std::stable_sort(candidates.begin(), candidates.end(), [&](const LaneRef& a, const LaneRef& b) {
        const auto &la = lanes[a.cell][a.lane], &lb = lanes[b.cell][b.lane];
        return (la.flyB - la.flyA).squaredNorm() < (lb.flyB - lb.flyA).squaredNorm();
    });
    const double s = p.trackSpacingM;
    LaneBoxes boxes(lanes, all, 0.5 * std::hypot(realAcrossM, realAlongM) + 0.5 * s);
    std::vector<char> dropped(all.size(), 0);
    std::vector<std::vector<Vec2>> photos(all.size());
    std::vector<char> built(all.size(), 0);
    std::vector<std::size_t> offset(lanes.size() + 1, 0);
    for (std::size_t c = 0; c < lanes.size(); ++c)
        offset[c + 1] = offset[c] + lanes[c].size();
    const Vec2 u = d.frame.toWorld(Vec2(1, 0)); // every lane runs along u: footprints are aligned with it
    const double r = std::clamp(s / 20.0, 0.25, 1.5);
    int count = 0;
    for (const auto& cand : candidates) {
        const std::size_t ci = offset[cand.cell] + cand.lane;
        const CellLane& l = lanes[cand.cell][cand.lane];
        // the photos of the other lanes near it
        std::vector<Vec2> pts;
        for (int o : boxes.near(ci, dropped)) {
            const auto& ref = all[static_cast<std::size_t>(o)];
            if (!built[static_cast<std::size_t>(o)]) {
                const auto& ol = lanes[ref.cell][ref.lane];
                photos[static_cast<std::size_t>(o)] = makeLane(ol.stripA, ol.stripB, p.photoSpacingM, ol.flyA, ol.flyB).photos;
                built[static_cast<std::size_t>(o)] = 1;
            }
            pts.insert(pts.end(), photos[static_cast<std::size_t>(o)].begin(), photos[static_cast<std::size_t>(o)].end());
        }
        // Everything its own photos see that is ground must be seen by another photo too.
        const std::vector<Vec2> own = makeLane(l.stripA, l.stripB, p.photoSpacingM, l.flyA, l.flyB).photos;
        if (seenByOthers(own, pts, u, 0.5 * realAcrossM, 0.5 * realAlongM, r, ground)) {
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
