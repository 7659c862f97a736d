#include "core/plan/lanes/photo_thinning.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace pf::plan {

using geo::Vec2;

namespace {

struct Shot {
    Vec2 c{0, 0};
    Vec2 u{1, 0}; // along the lane
    int lane = 0;
    bool interior = false;
    bool kept = true;
};

Vec2 laneDirection(const Lane& l) {
    if (l.photos.size() >= 2) {
        const Vec2 d = l.photos.back() - l.photos.front();
        if (d.norm() > 1e-9)
            return d.normalized();
    }
    const double h = l.headingDeg * M_PI / 180.0;
    return Vec2(std::sin(h), std::cos(h));
}

double segmentDistance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    auto pointSeg = [](const Vec2& p, const Vec2& q, const Vec2& r) {
        const Vec2 qr = r - q;
        const double l2 = qr.squaredNorm();
        const double t = l2 > 0 ? std::clamp((p - q).dot(qr) / l2, 0.0, 1.0) : 0.0;
        return (p - (q + t * qr)).norm();
    };
    auto cross = [](const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); };
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c),
                 d4 = cross(d - c, b - c);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return 0.0;
    return std::min({pointSeg(a, c, d), pointSeg(b, c, d), pointSeg(c, a, b), pointSeg(d, a, b)});
}

// Pairs of segments (i < j) closer than `threshold`: sorted by their extent across a fixed
// direction (the lanes of one sweep are parallel, so each meets only its neighbours there).
template <typename Visit>
void closePairs(const std::vector<std::pair<Vec2, Vec2>>& seg, const Vec2& normal, double threshold,
                Visit visit) {
    struct Span {
        double lo, hi;
        int i;
    };
    std::vector<Span> spans;
    spans.reserve(seg.size());
    for (std::size_t i = 0; i < seg.size(); ++i) {
        const double a = seg[i].first.dot(normal), b = seg[i].second.dot(normal);
        spans.push_back(Span{std::min(a, b), std::max(a, b), static_cast<int>(i)});
    }
    std::sort(spans.begin(), spans.end(), [](const Span& x, const Span& y) {
        return x.lo < y.lo || (x.lo == y.lo && x.i < y.i);
    });
    for (std::size_t k = 0; k < spans.size(); ++k)
        for (std::size_t m = k + 1; m < spans.size() && spans[m].lo <= spans[k].hi + threshold;
             ++m) {
            const auto& p = seg[static_cast<std::size_t>(spans[k].i)];
            const auto& q = seg[static_cast<std::size_t>(spans[m].i)];
            if (segmentDistance(p.first, p.second, q.first, q.second) < threshold)
                visit(spans[k].i, spans[m].i);
        }
}

// A uniform hash grid over the photos' real footprints.
class ShotIndex {
public:
    ShotIndex(const std::vector<Shot>& shots, const std::vector<char>& indexed, double cell,
              double reach)
        : m_shots(shots), m_cell(cell) {
        for (std::size_t i = 0; i < shots.size(); ++i) {
            if (!indexed[i])
                continue;
            const Vec2& c = shots[i].c;
            const auto [x0, y0] = key(c - Vec2(reach, reach));
            const auto [x1, y1] = key(c + Vec2(reach, reach));
            for (std::int64_t x = x0; x <= x1; ++x)
                for (std::int64_t y = y0; y <= y1; ++y)
                    m_cells[pack(x, y)].push_back(static_cast<int>(i));
        }
    }
    // Kept photos other than `self` listed in the cells the box [lo, hi] meets, each once.
    void near(const Vec2& lo, const Vec2& hi, int self, std::vector<int>& out) const {
        out.clear();
        const auto [x0, y0] = key(lo);
        const auto [x1, y1] = key(hi);
        for (std::int64_t x = x0; x <= x1; ++x)
            for (std::int64_t y = y0; y <= y1; ++y) {
                const auto it = m_cells.find(pack(x, y));
                if (it == m_cells.end())
                    continue;
                for (int i : it->second)
                    if (i != self && m_shots[static_cast<std::size_t>(i)].kept)
                        out.push_back(i);
            }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

private:
    std::pair<std::int64_t, std::int64_t> key(const Vec2& p) const {
        return {static_cast<std::int64_t>(std::floor(p.x() / m_cell)),
                static_cast<std::int64_t>(std::floor(p.y() / m_cell))};
    }
    static std::uint64_t pack(std::int64_t x, std::int64_t y) {
        return (static_cast<std::uint64_t>(x) << 32) ^
               (static_cast<std::uint64_t>(y) & 0xffffffffu);
    }
    const std::vector<Shot>& m_shots;
    double m_cell;
    std::unordered_map<std::uint64_t, std::vector<int>> m_cells;
};

// Each lane's photos from first to last grown by `ext` at both ends (far away for a lane without
// photos).
std::vector<std::pair<Vec2, Vec2>> extendedSegments(const std::vector<Lane>& lanes, double ext) {
    std::vector<std::pair<Vec2, Vec2>> seg(lanes.size());
    for (std::size_t li = 0; li < lanes.size(); ++li) {
        const Lane& l = lanes[li];
        if (l.photos.empty()) {
            seg[li] = {Vec2(1e300, 1e300), Vec2(1e300, 1e300)};
            continue;
        }
        const Vec2 u = laneDirection(l);
        seg[li] = {l.photos.front() - ext * u, l.photos.back() + ext * u};
    }
    return seg;
}

// The normal of the first lane with photos (the lanes of a sweep are parallel).
Vec2 lanesNormal(const std::vector<Lane>& lanes) {
    for (const auto& l : lanes)
        if (!l.photos.empty()) {
            const Vec2 u = laneDirection(l);
            return Vec2(-u.y(), u.x());
        }
    return Vec2(0, 1);
}

// n evenly spread probes over [a, b], 5 cm inside its ends (at most half of it), at most `step`
// apart.
std::vector<double> probesOver(double a, double b, double step) {
    std::vector<double> t;
    const double in = std::min(0.05, 0.5 * (b - a));
    const double lo = a + in, hi = b - in;
    const int n = std::max(1, static_cast<int>(std::ceil((hi - lo) / step)));
    for (int k = 0; k <= n; ++k)
        t.push_back(lo + (hi - lo) * k / n);
    return t;
}

// Whether a photo's interior ground is seen by other kept photos: with the effective footprint
// (spacing across, trigger distance along) and, when larger, with the real one.
class Redundancy {
public:
    Redundancy(const std::vector<Shot>& shots, const PhotoThinningOptions& opt, double ra,
               double rl, const std::function<bool(const Vec2&)>& ground)
        : m_shots(shots), m_indexed(shots.size(), 1),
          m_index(shots, m_indexed, std::max(ra, rl), 0.5 * std::hypot(ra, rl)),
          m_s(opt.trackSpacingM), m_ph(opt.photoSpacingM), m_ra(ra), m_rl(rl),
          m_step(std::max(0.25, opt.stepM)), m_ground(ground) {}

    bool operator()(int i) {
        const Shot& sh = m_shots[static_cast<std::size_t>(i)];
        const double r = 0.5 * std::hypot(m_ra, m_rl);
        m_index.near(sh.c - Vec2(r, r), sh.c + Vec2(r, r), i, m_nearby);
        return seenByOthers(sh, 0.5 * m_ph, 0.5 * m_s) &&
               (m_ra <= m_s && m_rl <= m_ph ? true : seenByOthers(sh, 0.5 * m_rl, 0.5 * m_ra));
    }

private:
    // Whether every point of ground in the footprint of half-sizes (hx along, hy across) centred on
    // the photo lies in the footprint of the same size of another kept photo on a parallel lane:
    // the footprint is cut at the others' edges into strips across, and in each strip the stretches
    // no other footprint covers are probed for ground every stepM (and 5 cm inside their ends).
    // Photos on lanes at an angle (a photographed turn) are not counted as seeing anything here.
    bool seenByOthers(const Shot& sh, double hx, double hy) {
        const Vec2 v(-sh.u.y(), sh.u.x());
        m_spansX.clear();
        m_spansY.clear();
        for (int j : m_nearby) {
            const Shot& o = m_shots[static_cast<std::size_t>(j)];
            if (std::fabs(o.u.dot(sh.u)) < 0.9999)
                continue;
            const Vec2 d = o.c - sh.c;
            const double x = d.dot(sh.u), y = d.dot(v);
            if (x - hx >= hx || x + hx <= -hx || y - hy >= hy || y + hy <= -hy)
                continue;
            m_spansX.emplace_back(x - hx, x + hx);
            m_spansY.emplace_back(y - hy, y + hy);
        }
        std::vector<double> cuts{-hy, hy};
        for (const auto& [y0, y1] : m_spansY)
            for (double y : {y0, y1})
                if (y > -hy && y < hy)
                    cuts.push_back(y);
        std::sort(cuts.begin(), cuts.end());
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
            const double ya = cuts[c], yb = cuts[c + 1];
            if (yb - ya < 1e-9)
                continue;
            if (!stripSeen(sh, v, hx, ya, yb))
                return false;
        }
        return true;
    }

    // The strip [ya, yb] across of the footprint (half-length hx along): the stretches the others'
    // footprints leave hold no ground.
    bool stripSeen(const Shot& sh, const Vec2& v, double hx, double ya, double yb) {
        m_cover.clear();
        for (std::size_t k = 0; k < m_spansY.size(); ++k)
            if (m_spansY[k].first <= ya + 1e-9 && m_spansY[k].second >= yb - 1e-9)
                m_cover.emplace_back(std::max(-hx, m_spansX[k].first),
                                     std::min(hx, m_spansX[k].second));
        std::sort(m_cover.begin(), m_cover.end());
        auto gap = [&](double xa, double xb) {
            if (xb - xa < 1e-9)
                return true;
            for (double py : probesOver(ya, yb, m_step))
                for (double px : probesOver(xa, xb, m_step))
                    if (m_ground(sh.c + px * sh.u + py * v))
                        return false;
            return true;
        };
        double x = -hx;
        for (const auto& [x0, x1] : m_cover) {
            if (x0 > x && !gap(x, x0))
                return false;
            x = std::max(x, x1);
        }
        return !(x < hx && !gap(x, hx));
    }

    const std::vector<Shot>& m_shots;
    const std::vector<char> m_indexed;
    const ShotIndex m_index;
    const double m_s, m_ph, m_ra, m_rl, m_step;
    const std::function<bool(const Vec2&)>& m_ground;
    // Scratch: the kept photos near the one checked, their footprints in its frame, a strip's
    // cover.
    std::vector<int> m_nearby;
    std::vector<std::pair<double, double>> m_spansX, m_spansY, m_cover;
};

} // namespace

int thinLanePhotos(std::vector<Lane>& lanes, const std::vector<char>& fixedLanes,
                   const PhotoThinningOptions& opt,
                   const std::function<bool(const Vec2&)>& ground) {
    const double s = opt.trackSpacingM, ph = opt.photoSpacingM;
    if (!(s > 0) || !(ph > 0))
        return 0;
    const double ra = std::max(opt.realAcrossM, s), rl = std::max(opt.realAlongM, ph);
    // Only a photo whose centre another lane's effective band reaches can be redundant (the centre,
    // on the flown line, is ground); only photos within a real footprint's width of such a lane can
    // see its ground. Regular lanes a spacing apart have neither: nothing to index.
    const std::size_t nl = lanes.size();
    const Vec2 normal = lanesNormal(lanes);
    auto hasInterior = [&](std::size_t li) {
        return lanes[li].photos.size() > 2 && !(li < fixedLanes.size() && fixedLanes[li]);
    };
    std::vector<char> candidate(nl, 0), context(nl, 0);
    closePairs(extendedSegments(lanes, 0.5 * ph), normal, 0.5 * s, [&](int a, int b) {
        candidate[static_cast<std::size_t>(a)] |= hasInterior(static_cast<std::size_t>(a)) ? 1 : 0;
        candidate[static_cast<std::size_t>(b)] |= hasInterior(static_cast<std::size_t>(b)) ? 1 : 0;
    });
    if (std::none_of(candidate.begin(), candidate.end(), [](char c) { return c != 0; }))
        return 0;
    closePairs(extendedSegments(lanes, 0.5 * rl), normal, ra + 0.5, [&](int a, int b) {
        if (candidate[static_cast<std::size_t>(a)] || candidate[static_cast<std::size_t>(b)])
            context[static_cast<std::size_t>(a)] = context[static_cast<std::size_t>(b)] = 1;
    });
    std::vector<Shot> shots;
    std::vector<std::size_t> firstShot(nl + 1, 0);
    for (std::size_t li = 0; li < nl; ++li) {
        firstShot[li] = shots.size();
        if (!candidate[li] && !context[li])
            continue;
        const Lane& l = lanes[li];
        const Vec2 u = laneDirection(l);
        for (std::size_t k = 0; k < l.photos.size(); ++k)
            shots.push_back(Shot{l.photos[k], u, static_cast<int>(li),
                                 candidate[li] && k > 0 && k + 1 < l.photos.size(), true});
    }
    firstShot[nl] = shots.size();
    Redundancy redundant(shots, opt, ra, rl, ground);

    // Most redundant lanes first.
    std::vector<double> share(lanes.size(), 0.0);
    for (std::size_t li = 0; li < lanes.size(); ++li) {
        if (!candidate[li])
            continue;
        int n = 0, r = 0;
        for (std::size_t k = firstShot[li]; k < firstShot[li + 1]; ++k)
            if (shots[k].interior) {
                ++n;
                r += redundant(static_cast<int>(k)) ? 1 : 0;
            }
        share[li] = n > 0 ? static_cast<double>(r) / n : 0.0;
    }
    std::vector<std::size_t> order(lanes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return share[a] > share[b]; });
    int dropped = 0;
    for (std::size_t li : order) {
        if (share[li] <= 0.0)
            break;
        for (std::size_t k = firstShot[li]; k < firstShot[li + 1]; ++k)
            if (shots[k].interior && redundant(static_cast<int>(k))) {
                shots[k].kept = false;
                ++dropped;
            }
    }
    if (dropped == 0)
        return 0;
    for (std::size_t li = 0; li < lanes.size(); ++li) {
        if (!candidate[li])
            continue;
        std::vector<Vec2> kept;
        for (std::size_t k = firstShot[li]; k < firstShot[li + 1]; ++k)
            if (shots[k].kept)
                kept.push_back(shots[k].c);
        lanes[li].photos = std::move(kept);
    }
    return dropped;
}

} // namespace pf::plan
