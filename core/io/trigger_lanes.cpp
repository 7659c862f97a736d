#include "core/io/trigger_lanes.h"

#include "core/geo/geodesic.h"
#include "core/geo/local_frame.h"

#include <algorithm>
#include <cmath>

namespace pf::io {

namespace {

constexpr double kSpacingTolM = 0.01;
constexpr double kLineTolM = 0.05;
constexpr double kAltTolM = 0.01;
constexpr double kHeadingTolDeg = 0.5;

double headingDiff(double a, double b) {
    double d = std::fmod(std::abs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

bool sameLaneAttributes(const route::Waypoint& a, const route::Waypoint& b) {
    return a.kind == route::WaypointKind::Photo && b.kind == route::WaypointKind::Photo &&
           std::abs(a.altitudeM - b.altitudeM) <= kAltTolM &&
           headingDiff(a.headingDeg, b.headingDeg) <= kHeadingTolDeg;
}

// Whether points first..last lie within kLineTolM of the straight line first -> last, in order.
bool collinear(const std::vector<geo::Vec2>& p, std::size_t first, std::size_t last) {
    const geo::Vec2 d = p[last] - p[first];
    const double len = d.norm();
    if (len <= 0)
        return false;
    for (std::size_t k = first + 1; k < last; ++k) {
        const geo::Vec2 q = p[k] - p[first];
        const double along = q.dot(d) / len;
        const double across = std::abs(d.x() * q.y() - d.y() * q.x()) / len;
        if (across > kLineTolM || along <= 0 || along >= len)
            return false;
    }
    return true;
}

} // namespace

std::vector<TriggerLane> findTriggerLanes(const std::vector<route::Waypoint>& w) {
    std::vector<TriggerLane> lanes;
    if (w.size() < 3)
        return lanes;
    // One local frame for the whole route: its scale error over a few kilometres is far below the
    // centimetre tolerances.
    auto frame = geo::LocalFrame::create(w.front().position);
    if (!frame)
        return lanes;
    std::vector<geo::Vec2> p;
    p.reserve(w.size());
    for (const auto& x : w)
        p.push_back(frame->toLocal(x.position));
    std::size_t i = 0;
    while (i + 2 < w.size()) {
        if (!sameLaneAttributes(w[i], w[i + 1])) {
            ++i;
            continue;
        }
        const double d = (p[i + 1] - p[i]).norm();
        if (d < 0.1) {
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        while (j + 1 < w.size() && sameLaneAttributes(w[j], w[j + 1]) &&
               std::abs((p[j + 1] - p[j]).norm() - d) <= kSpacingTolM && collinear(p, i, j + 1))
            ++j;
        if (j - i + 1 >= 3) {
            const double len = geo::geodesicDistance(w[i].position, w[j].position);
            lanes.push_back({i, j, len / static_cast<double>(j - i)});
            i = j + 1;
        } else {
            ++i;
        }
    }
    return lanes;
}

std::vector<route::Waypoint> mergeCloseWaypoints(const std::vector<route::Waypoint>& in,
                                                 double minDistanceM, std::size_t* merged) {
    std::vector<route::Waypoint> out;
    out.reserve(in.size());
    std::size_t n = 0;
    for (const auto& w : in) {
        if (!out.empty() && geo::geodesicDistance(out.back().position, w.position) < minDistanceM) {
            route::Waypoint& kept = out.back();
            const double alt = std::max(kept.altitudeM, w.altitudeM);
            if (w.kind == route::WaypointKind::Photo && kept.kind != route::WaypointKind::Photo)
                kept = w;
            kept.altitudeM = alt;
            ++n;
            continue;
        }
        out.push_back(w);
    }
    if (merged)
        *merged = n;
    return out;
}

} // namespace pf::io
