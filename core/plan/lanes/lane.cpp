#include "core/plan/lanes/lane.h"

#include <algorithm>
#include <cmath>

namespace pf::plan {

std::vector<geo::Vec2> stripPhotos(const geo::Vec2& a, const geo::Vec2& b, double spacing) {
    const geo::Vec2 d = b - a;
    const double len = d.norm();
    if (!(spacing > 0) || !std::isfinite(spacing) || len == 0.0)
        return {0.5 * (a + b)};
    // A tolerance keeps a strip exactly k spacings long at k photos despite rounding.
    const double k = std::ceil(len / spacing - 1e-9);
    const int n = std::max(1, static_cast<int>(std::min(k, 1e9)));
    const geo::Vec2 u = d / len, mid = 0.5 * (a + b);
    std::vector<geo::Vec2> out;
    out.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        out.push_back(mid + ((i - 0.5 * (n - 1)) * spacing) * u);
    return out;
}

Lane makeLane(const geo::Vec2& a, const geo::Vec2& b, double spacing) {
    Lane l;
    l.stripStart = a;
    l.stripEnd = b;
    l.photos = stripPhotos(a, b, spacing);
    const geo::Vec2 d = b - a;
    if (d.squaredNorm() > 0) {
        double h = std::atan2(d.x(), d.y()) * 180.0 / M_PI;
        if (h < 0)
            h += 360.0;
        l.headingDeg = h >= 360.0 ? 0.0 : h;
    }
    return l;
}

Lane makeLane(const geo::Vec2& a, const geo::Vec2& b, double spacing, const geo::Vec2& flyA,
              const geo::Vec2& flyB) {
    Lane l = makeLane(a, b, spacing);
    const geo::Vec2 d = b - a;
    const double len2 = d.squaredNorm();
    if (len2 == 0.0)
        return l;
    const double ta = (flyA - a).dot(d) / len2, tb = (flyB - a).dot(d) / len2;
    std::vector<geo::Vec2> kept;
    kept.reserve(l.photos.size());
    for (const auto& p : l.photos) {
        const double t = (p - a).dot(d) / len2;
        const geo::Vec2 q = t < ta ? flyA : (t > tb ? flyB : p);
        if (kept.empty() || (kept.back() - q).norm() >= 0.01)
            kept.push_back(q);
    }
    l.photos = std::move(kept);
    return l;
}

LaneSpan laneSpan(const geo::Vec2& a, const geo::Vec2& b, double spacing, const geo::Vec2& flyA,
                  const geo::Vec2& flyB) {
    // The same arithmetic as stripPhotos and makeLane, keeping only what the planner needs.
    LaneSpan s;
    const geo::Vec2 d = b - a;
    const double len = d.norm();
    if (len == 0.0) {
        s.first = s.last = 0.5 * (a + b);
        s.photos = 1;
        return s;
    }
    int n = 1;
    if (spacing > 0 && std::isfinite(spacing)) {
        const double k = std::ceil(len / spacing - 1e-9);
        n = std::max(1, static_cast<int>(std::min(k, 1e9)));
    } else {
        spacing = 0.0;
    }
    const double len2 = d.squaredNorm();
    const double ta = (flyA - a).dot(d) / len2, tb = (flyB - a).dot(d) / len2;
    const geo::Vec2 u = d / len, mid = 0.5 * (a + b);
    geo::Vec2 lastKept(0, 0);
    for (int i = 0; i < n; ++i) {
        const geo::Vec2 p = mid + ((i - 0.5 * (n - 1)) * spacing) * u;
        const double t = (p - a).dot(d) / len2;
        const geo::Vec2 q = t < ta ? flyA : (t > tb ? flyB : p);
        if (s.photos == 0 || (lastKept - q).norm() >= 0.01) {
            if (s.photos == 0)
                s.first = q;
            lastKept = q;
            ++s.photos;
        }
    }
    s.last = lastKept;
    return s;
}

} // namespace pf::plan
