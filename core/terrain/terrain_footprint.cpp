#include "core/terrain/terrain_footprint.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

namespace pf::terrain {

namespace {

// out[i] = max of in[i - r .. i + r] (NaN ignored; NaN if all are NaN), `stride` apart.
void runningMax(const float* in, float* out, int n, int stride, int r) {
    std::deque<int> q; // indices of decreasing values
    int next = 0;
    for (int i = 0; i < n; ++i) {
        const int hi = std::min(n - 1, i + r);
        for (; next <= hi; ++next) {
            const float v = in[static_cast<std::size_t>(next) * stride];
            if (std::isnan(v))
                continue;
            while (!q.empty() && in[static_cast<std::size_t>(q.back()) * stride] <= v)
                q.pop_back();
            q.push_back(next);
        }
        while (!q.empty() && q.front() < i - r)
            q.pop_front();
        out[static_cast<std::size_t>(i) * stride] =
            q.empty() ? std::numeric_limits<float>::quiet_NaN() : in[static_cast<std::size_t>(q.front()) * stride];
    }
}

} // namespace

double maxRiseWithin(const HeightGrid& grid, double radiusM, const std::function<bool(const geo::Vec2&)>& inside) {
    if (grid.empty())
        return 0.0;
    const int cols = grid.cols(), rows = grid.rows();
    const int r = std::max(0, static_cast<int>(std::ceil(radiusM / grid.spacingM())));
    std::vector<float> h(static_cast<std::size_t>(cols) * rows), tmp(h.size()), mx(h.size());
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i)
            h[static_cast<std::size_t>(j) * cols + i] = grid.node(i, j);
    for (int j = 0; j < rows; ++j)
        runningMax(&h[static_cast<std::size_t>(j) * cols], &tmp[static_cast<std::size_t>(j) * cols], cols, 1, r);
    for (int i = 0; i < cols; ++i)
        runningMax(&tmp[i], &mx[i], rows, cols, r);
    double rise = 0.0;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * cols + i;
            if (std::isnan(h[k]) || std::isnan(mx[k]) || !(mx[k] - h[k] > rise))
                continue;
            if (inside(grid.nodePosition(i, j)))
                rise = mx[k] - h[k];
        }
    return rise;
}


geo::Vec2 groundPoint(const HeightGrid& grid, const NadirCamera& cam, double u, double v) {
    // Ray direction per metre of descent: right and ahead in the local frame (x east, y north).
    const double hd = cam.headingDeg * M_PI / 180.0;
    const geo::Vec2 ahead(std::sin(hd), std::cos(hd)), right(std::cos(hd), -std::sin(hd));
    const geo::Vec2 d = right * (u * cam.tanHalfAcross) + ahead * (v * cam.tanHalfAlong);
    double known = grid.heightOr(cam.pos, 0.0);
    auto below = [&](double t) { // ray height minus ground at descent t (> 0: above the ground)
        const double g = grid.heightOr(cam.pos + d * t, known);
        known = g;
        return cam.altitudeM - t - g;
    };
    const double clearance = cam.altitudeM - known;
    if (!(clearance > 0))
        return cam.pos;
    // Fixed point t = altitude - ground(t): fast where the ground is gentler than the ray.
    double t = clearance;
    for (int k = 0; k < 30; ++k) {
        const double f = below(t);
        if (std::fabs(f) < 1e-3)
            return cam.pos + d * t;
        t += f;
        if (!(t > 0))
            break;
    }
    // Steep ground: march down the ray for the first crossing, then bisect.
    const double step = std::max(0.25 * grid.spacingM() / std::max(d.norm(), 1e-6), 0.05);
    known = grid.heightOr(cam.pos, 0.0);
    double lo = 0.0, hi = step;
    const double tMax = 4.0 * (cam.altitudeM - grid.range().first + 1.0);
    while (below(hi) > 0 && hi < tMax) {
        lo = hi;
        hi += step;
    }
    for (int k = 0; k < 30; ++k) {
        const double mid = 0.5 * (lo + hi);
        (below(mid) > 0 ? lo : hi) = mid;
    }
    return cam.pos + d * (0.5 * (lo + hi));
}

geo::Ring footprintOnTerrain(const HeightGrid& grid, const NadirCamera& cam, int perSide) {
    perSide = std::max(perSide, 1);
    // Counter-clockwise in x east / y north: right-back, right-front, left-front, left-back, seen
    // from above with the heading up (u right, v ahead).
    const double corners[4][2] = {{1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    geo::Ring ring;
    ring.reserve(static_cast<std::size_t>(4 * perSide));
    for (int s = 0; s < 4; ++s) {
        const double* a = corners[s];
        const double* b = corners[(s + 1) % 4];
        for (int k = 0; k < perSide; ++k) {
            const double t = static_cast<double>(k) / perSide;
            ring.push_back(groundPoint(grid, cam, a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t));
        }
    }
    return ring;
}

} // namespace pf::terrain
