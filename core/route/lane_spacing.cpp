#include "core/route/lane_spacing.h"

#include <algorithm>
#include <cmath>

namespace pf::route {

namespace {

constexpr double kAcrossTolM = 0.01;    // off the lane's line
constexpr double kHeadingTolDeg = 0.01; // one heading
constexpr double kAlongTolM = 1e-6;     // backwards along the line (rounding)

geo::Vec2 ahead(double headingDeg) {
    const double h = headingDeg * M_PI / 180.0;
    return {std::sin(h), std::cos(h)};
}

bool sameHeading(double a, double b) {
    const double d = std::fabs(std::remainder(a - b, 360.0));
    return d < kHeadingTolDeg;
}

// Photos a lane of length L needs at trigger distance d (rounding forgiven: a lane exactly k
// trigger distances long takes k + 1).
int photosFor(double L, double d) {
    return static_cast<int>(std::ceil(L / d - 1e-9)) + 1;
}

} // namespace

std::vector<std::pair<int, int>> photoLanes(const std::vector<LocalWaypoint>& w, double maxGapM) {
    std::vector<std::pair<int, int>> lanes;
    const int n = static_cast<int>(w.size());
    for (int i = 0; i < n;) {
        if (w[static_cast<std::size_t>(i)].kind != WaypointKind::Photo) {
            ++i;
            continue;
        }
        const LocalWaypoint& first = w[static_cast<std::size_t>(i)];
        const geo::Vec2 u = ahead(first.headingDeg);
        int j = i;
        while (j + 1 < n) {
            const LocalWaypoint& prev = w[static_cast<std::size_t>(j)];
            const LocalWaypoint& next = w[static_cast<std::size_t>(j + 1)];
            if (next.kind != WaypointKind::Photo || !sameHeading(next.headingDeg, first.headingDeg))
                break;
            const geo::Vec2 d = next.pos - prev.pos;
            const geo::Vec2 off = next.pos - first.pos;
            if (std::fabs(off.x() * u.y() - off.y() * u.x()) > kAcrossTolM ||
                d.dot(u) < -kAlongTolM || d.norm() > maxGapM)
                break;
            ++j;
        }
        lanes.emplace_back(i, j);
        i = j + 1;
    }
    return lanes;
}

std::vector<LocalWaypoint> spaceLanes(const std::vector<LocalWaypoint>& w, double areaSpacingM,
                                      const LaneSpacingFn& spacing, LaneSpacingReport* report) {
    LaneSpacingReport rep;
    if (!(areaSpacingM > 0) || !spacing) {
        if (report)
            *report = rep;
        return w;
    }
    std::vector<LocalWaypoint> out;
    out.reserve(w.size());
    int copied = 0; // w[0, copied) are in out
    for (const auto& [first, last] : photoLanes(w, areaSpacingM * (1.0 + 1e-6) + 1e-6)) {
        if (last == first)
            continue;
        ++rep.lanes;
        const LocalWaypoint& a = w[static_cast<std::size_t>(first)];
        const LocalWaypoint& b = w[static_cast<std::size_t>(last)];
        const double L = (b.pos - a.pos).norm();
        const double d = L > 0 ? spacing(a.pos, b.pos) : 0.0;
        if (!(d > 0) || !std::isfinite(d))
            continue;
        const int had = last - first + 1;
        const int want = std::max(2, photosFor(L, d));
        if (want >= had || want >= photosFor(L, areaSpacingM))
            continue;
        out.insert(out.end(), w.begin() + copied, w.begin() + first);
        const geo::Vec2 u = (b.pos - a.pos) / L;
        int near = first; // the old photo nearest along the lane, for the cell
        for (int k = 0; k < want; ++k) {
            const double s = L * k / (want - 1);
            LocalWaypoint p = a;
            p.pos = k + 1 == want ? b.pos : geo::Vec2(a.pos + u * s);
            while (near < last &&
                   std::fabs((w[static_cast<std::size_t>(near + 1)].pos - a.pos).dot(u) - s) <=
                       std::fabs((w[static_cast<std::size_t>(near)].pos - a.pos).dot(u) - s))
                ++near;
            p.cell = w[static_cast<std::size_t>(near)].cell;
            out.push_back(p);
        }
        copied = last + 1;
        ++rep.respaced;
        rep.photosBefore += had;
        rep.photosAfter += want;
    }
    out.insert(out.end(), w.begin() + copied, w.end());
    if (report)
        *report = rep;
    return out;
}

} // namespace pf::route
