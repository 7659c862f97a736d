#include "core/plan/sweep/sweep_routing.h"

#include <algorithm>
#include <cmath>

namespace pf::plan::sweep_detail {

double angleDeg(const Vec2& u, const Vec2& v) { return angleDeg(u, u.norm(), v, v.norm()); }

double angleDeg(const Vec2& u, double nu, const Vec2& v, double nv) {
    if (nu == 0.0 || nv == 0.0)
        return 0.0;
    const double c = std::fabs(u.x() * v.y() - u.y() * v.x()), d = u.dot(v);
    // Lane ends meet along one line (same or opposite directions): what atan2 gives there, without it.
    static const double kOpposite = std::atan2(0.0, -1.0) * 180.0 / M_PI;
    if (c == 0.0 && d != 0.0)
        return d > 0.0 ? 0.0 : kOpposite;
    return std::atan2(c, d) * 180.0 / M_PI;
}

double transitionTime(const FlightTimeModel& m, const Vec2& a, const Vec2& arrive, const std::vector<Vec2>& mid,
                      const Vec2& b, const Vec2& leave) {
    double len = 0.0, t = 0.0;
    Vec2 dir = arrive, p = a;
    auto leg = [&](const Vec2& q) {
        const Vec2 d = q - p;
        const double l = d.norm();
        if (l == 0.0)
            return;
        const Vec2 u = d / l;
        if (dir.squaredNorm() > 0)
            t += turnCostS(angleDeg(dir, u), m);
        dir = u;
        len += l;
        p = q;
    };
    for (const auto& q : mid)
        leg(q);
    leg(b);
    if (leave.squaredNorm() > 0 && dir.squaredNorm() > 0)
        t += turnCostS(angleDeg(dir, leave), m);
    return t + len / m.speedMps;
}

std::vector<std::vector<int>> nearestEndPoints(const Router& router, const std::vector<int>& pts, int k, double h) {
    std::vector<std::vector<int>> out(router.size());
    if (pts.empty())
        return out;
    geo::Box box{router.point(pts.front()).p, router.point(pts.front()).p};
    for (int id : pts) {
        box.min = box.min.cwiseMin(router.point(id).p);
        box.max = box.max.cwiseMax(router.point(id).p);
    }
    const int nx = std::max(1, static_cast<int>((box.max.x() - box.min.x()) / h) + 1);
    const int ny = std::max(1, static_cast<int>((box.max.y() - box.min.y()) / h) + 1);
    std::vector<std::vector<int>> grid(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
    auto cellOf = [&](const Vec2& p, int& cx, int& cy) {
        cx = std::clamp(static_cast<int>((p.x() - box.min.x()) / h), 0, nx - 1);
        cy = std::clamp(static_cast<int>((p.y() - box.min.y()) / h), 0, ny - 1);
    };
    for (int id : pts) {
        int cx, cy;
        cellOf(router.point(id).p, cx, cy);
        grid[static_cast<std::size_t>(cy) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(cx)].push_back(id);
    }
    std::vector<std::pair<double, int>> found;
    for (int id : pts) {
        const Vec2 p = router.point(id).p;
        int cx, cy;
        cellOf(p, cx, cy);
        found.clear();
        // rings of grid cells until k are found and the next ring is farther than the k-th
        for (int r = 0; r <= std::max(nx, ny); ++r) {
            for (int y = cy - r; y <= cy + r; ++y)
                for (int x = cx - r; x <= cx + r; ++x) {
                    if (x < 0 || y < 0 || x >= nx || y >= ny || (std::abs(x - cx) != r && std::abs(y - cy) != r))
                        continue;
                    for (int o : grid[static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(x)])
                        if (o != id)
                            found.emplace_back((router.point(o).p - p).squaredNorm(), o);
                }
            if (static_cast<int>(found.size()) >= k) {
                std::nth_element(found.begin(), found.begin() + (k - 1), found.end());
                const double kth = std::sqrt(found[static_cast<std::size_t>(k - 1)].first);
                if (kth <= r * h)
                    break;
            }
        }
        std::sort(found.begin(), found.end());
        auto& list = out[static_cast<std::size_t>(id)];
        for (std::size_t i = 0; i < found.size() && static_cast<int>(i) < k; ++i)
            list.push_back(found[i].second);
    }
    return out;
}

} // namespace pf::plan::sweep_detail
