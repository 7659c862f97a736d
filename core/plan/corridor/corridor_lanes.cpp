#include "core/plan/corridor/corridor_lanes.h"

#include "core/geo/even_odd.h"
#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>

namespace pf::plan {

namespace {

using geo::Vec2;

double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// A lane's legs measured: arc length at each point, the measure arriving at and leaving each point
// (they differ by the corner's chord), and the directions of the legs.
struct LaneMeasure {
    std::vector<double> along, in, out;
    std::vector<Vec2> dir; // dir[k]: leg k -> k + 1
};

LaneMeasure measure(const Polyline& p, double spacing, double strip) {
    LaneMeasure m;
    const std::size_t n = p.size();
    m.along.assign(n, 0.0);
    m.in.assign(n, 0.0);
    m.out.assign(n, 0.0);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        const Vec2 d = p[k + 1] - p[k];
        const double len = d.norm();
        m.dir.push_back(len > 0 ? Vec2(d / len) : (k > 0 ? m.dir.back() : Vec2(0, 1)));
    }
    for (std::size_t k = 1; k < n; ++k) {
        const double len = (p[k] - p[k - 1]).norm();
        m.along[k] = m.along[k - 1] + len;
        m.in[k] = m.out[k - 1] + len;
        double chord = 0.0;
        if (k + 1 < n) {
            const double a =
                std::abs(std::atan2(cross(m.dir[k - 1], m.dir[k]), m.dir[k - 1].dot(m.dir[k])));
            chord = std::min(0.9 * spacing, strip * std::sin(0.5 * a));
        }
        m.out[k] = m.in[k] + chord;
    }
    return m;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
    const auto it = std::upper_bound(x.begin(), x.end(), at);
    if (it == x.begin())
        return y.front();
    if (it == x.end())
        return y.back();
    const std::size_t i = static_cast<std::size_t>(it - x.begin()) - 1;
    const double span = x[i + 1] - x[i];
    return span > 0 ? y[i] + (y[i + 1] - y[i]) * (at - x[i]) / span : y[i];
}

// The point at arc length `a` of the lane, with the direction of its leg.
CorridorPoint pointAtAlong(const OffsetLine& lane, const LaneMeasure& m, double a) {
    const auto& p = lane.points;
    const auto it = std::upper_bound(m.along.begin(), m.along.end(), a);
    std::size_t k = it == m.along.begin() ? 0 : static_cast<std::size_t>(it - m.along.begin()) - 1;
    k = std::min(k, p.size() - 2);
    CorridorPoint c;
    c.pos = p[k] + std::clamp(a - m.along[k], 0.0, m.along[k + 1] - m.along[k]) * m.dir[k];
    c.headingDeg = compassHeadingDeg(m.dir[k]);
    c.along = a;
    c.station = interpolate(m.along, lane.stations, a);
    return c;
}

// Insideness along the segment ab against the polygons: the parameters in [0, 1] where it crosses a
// ring, sorted, with 0 and 1.
std::vector<double> crossings(const Vec2& a, const Vec2& b,
                              const std::vector<const geo::Polygon*>& polys) {
    std::vector<double> ts{0.0, 1.0};
    const Vec2 d = b - a;
    auto ring = [&](const geo::Ring& r) {
        for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
            const Vec2 e = r[i] - r[j];
            const double den = cross(d, e);
            if (std::abs(den) < 1e-15)
                continue;
            const Vec2 w = r[j] - a;
            const double t = cross(w, e) / den, u = cross(w, d) / den;
            if (t > 0 && t < 1 && u >= 0 && u <= 1)
                ts.push_back(t);
        }
    };
    for (const geo::Polygon* poly : polys) {
        ring(poly->outer);
        for (const auto& h : poly->holes)
            ring(h);
    }
    std::sort(ts.begin(), ts.end());
    return ts;
}

bool insideAny(const std::vector<const geo::Polygon*>& polys, const Vec2& p) {
    for (const geo::Polygon* poly : polys)
        if (geo::insideEvenOdd(*poly, p))
            return true;
    return false;
}

} // namespace

double compassHeadingDeg(const Vec2& d) {
    if (d.squaredNorm() == 0)
        return 0.0;
    double h = std::atan2(d.x(), d.y()) * 180.0 / M_PI;
    if (h < 0)
        h += 360.0;
    return h >= 360.0 ? 0.0 : h;
}

std::vector<CorridorPoint> lanePhotos(const OffsetLine& lane, double spacing, double strip) {
    std::vector<CorridorPoint> out;
    const auto& p = lane.points;
    if (p.size() < 2 || !(spacing > 0))
        return out;
    const LaneMeasure m = measure(p, spacing, strip);
    const double total = m.in.back();
    const int n = std::max(1, static_cast<int>(std::min(std::ceil(total / spacing - 1e-9), 1e9)));
    std::size_t k = 0; // the point whose measure interval holds mu, or the leg after it
    for (int i = 0; i < n; ++i) {
        const double mu = 0.5 * total + (i - 0.5 * (n - 1)) * spacing;
        while (k + 1 < p.size() && m.in[k + 1] <= mu)
            ++k;
        if (k + 1 < p.size() && mu >= m.out[k]) { // on the leg k -> k + 1
            out.push_back(pointAtAlong(lane, m, m.along[k] + (mu - m.out[k])));
            continue;
        }
        // On corner k (or the lane's last point): the heading turns with the measure.
        CorridorPoint c = pointAtAlong(lane, m, m.along[k]);
        c.pos = p[k];
        if (k > 0 && k + 1 < p.size() && m.out[k] > m.in[k]) {
            const double f = (mu - m.in[k]) / (m.out[k] - m.in[k]);
            const double h0 = compassHeadingDeg(m.dir[k - 1]), h1 = compassHeadingDeg(m.dir[k]);
            const double dh = std::remainder(h1 - h0, 360.0);
            c.headingDeg = std::fmod(h0 + f * dh + 360.0, 360.0);
        }
        out.push_back(c);
    }
    return out;
}

std::vector<Interval> blockedIntervals(const Polyline& lane, const geo::MultiPolygon& blocked) {
    std::vector<Interval> out;
    if (blocked.empty() || lane.size() < 2)
        return out;
    std::vector<geo::Box> boxes;
    for (const auto& poly : blocked)
        boxes.push_back(geo::bounds(poly));
    double along = 0.0;
    std::vector<const geo::Polygon*> near;
    for (std::size_t k = 0; k + 1 < lane.size(); ++k) {
        const Vec2 a = lane[k], b = lane[k + 1];
        const double len = (b - a).norm();
        const geo::Box seg{a.cwiseMin(b), a.cwiseMax(b)};
        near.clear();
        for (std::size_t z = 0; z < blocked.size(); ++z)
            if (boxes[z].intersects(seg))
                near.push_back(&blocked[z]);
        if (len > 0 && !near.empty()) {
            const std::vector<double> ts = crossings(a, b, near);
            for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
                if (ts[i + 1] - ts[i] < 1e-12 ||
                    !insideAny(near, a + 0.5 * (ts[i] + ts[i + 1]) * (b - a)))
                    continue;
                const Interval iv{along + ts[i] * len, along + ts[i + 1] * len};
                if (!out.empty() && iv.first <= out.back().second + 1e-9)
                    out.back().second = std::max(out.back().second, iv.second);
                else
                    out.push_back(iv);
            }
        }
        along += len;
    }
    return out;
}

std::vector<CorridorRun> laneRuns(const OffsetLine& lane, int laneIndex,
                                  std::vector<CorridorPoint> photos,
                                  const std::vector<Interval>& blocked) {
    std::vector<CorridorRun> runs;
    const auto& p = lane.points;
    if (p.size() < 2 || photos.empty())
        return runs;
    const LaneMeasure m = measure(p, 1.0, 0.0);
    const double length = m.along.back();
    // Photos in a blocked stretch move to its nearer flyable end.
    std::vector<CorridorPoint> kept;
    for (auto& ph : photos) {
        const auto in = std::find_if(blocked.begin(), blocked.end(), [&](const Interval& iv) {
            return ph.along > iv.first && ph.along < iv.second;
        });
        if (in != blocked.end()) {
            const bool lowOk = in->first > 1e-9, highOk = in->second < length - 1e-9;
            if (!lowOk && !highOk)
                continue;
            const bool low = lowOk && (!highOk || ph.along - in->first <= in->second - ph.along);
            ph = pointAtAlong(lane, m, low ? in->first : in->second);
            ph.photo = true;
        }
        ph.photo = true;
        if (!kept.empty() && (kept.back().pos - ph.pos).norm() < 0.01)
            continue;
        kept.push_back(ph);
    }
    // Flyable stretches between the blocked ones, each a run from its first photo to its last.
    std::vector<Interval> free;
    double from = 0.0;
    for (const auto& iv : blocked) {
        if (iv.first > from)
            free.push_back({from, iv.first});
        from = std::max(from, iv.second);
    }
    if (from < length || free.empty())
        free.push_back({from, length});
    std::size_t next = 0;
    for (const auto& [lo, hi] : free) {
        CorridorRun run;
        run.lane = laneIndex;
        while (next < kept.size() && kept[next].along <= hi + 1e-6) {
            if (kept[next].along >= lo - 1e-6) {
                // The lane's corners since the last photo, flown without a photo.
                if (!run.points.empty())
                    for (std::size_t k = 1; k + 1 < p.size(); ++k)
                        if (m.along[k] > run.points.back().along + 1e-6 &&
                            m.along[k] < kept[next].along - 1e-6) {
                            CorridorPoint c = pointAtAlong(lane, m, m.along[k]);
                            c.pos = p[k];
                            run.points.push_back(c);
                        }
                run.points.push_back(kept[next]);
            }
            ++next;
        }
        if (!run.points.empty())
            runs.push_back(std::move(run));
    }
    return runs;
}

} // namespace pf::plan
