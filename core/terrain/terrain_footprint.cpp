#include "core/terrain/terrain_footprint.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pf::terrain {

namespace {

constexpr float kLow = -std::numeric_limits<float>::infinity();

// The running maximum over windows of w = 2r + 1 values (van Herk / Gil-Werman): with the input
// padded by r lows on either side and cut into blocks of w, every window spans at most two blocks, so
// its maximum is the suffix maximum of its first block's part and the prefix maximum of the second's.
// `at(i)` gives value i of the padded sequence (n + 2r values) as whole lines of `width` floats; out
// line i (`outStride` floats apart) = max of padded lines i .. i + 2r. Lines let the same code run
// along rows (width 1) and down strips of columns (every column of the strip at once: sequential
// memory, vectorised).
template <int kFixedWidth = 0, typename At>
void runningMax(At at, int n, int lineWidth, int r, std::vector<float>& prefix, std::vector<float>& suffix, float* out,
                std::size_t outStride) {
    const int width = kFixedWidth ? kFixedWidth : lineWidth; // a constant along rows: tight loops
    const int w = 2 * r + 1, padded = n + 2 * r;
    prefix.resize(static_cast<std::size_t>(padded) * width);
    suffix.resize(prefix.size());
    auto line = [width](std::vector<float>& v, int i) { return v.data() + static_cast<std::size_t>(i) * width; };
    for (int i = 0, inBlock = 0; i < padded; ++i, inBlock = inBlock + 1 == w ? 0 : inBlock + 1) {
        const float* x = at(i);
        float* p = line(prefix, i);
        if (inBlock == 0)
            std::copy(x, x + width, p);
        else
            for (int k = 0; k < width; ++k)
                p[k] = std::max(p[k - width], x[k]);
    }
    for (int i = padded - 1, inBlock = (padded - 1) % w; i >= 0; --i, inBlock = inBlock == 0 ? w - 1 : inBlock - 1) {
        const float* x = at(i);
        float* s = line(suffix, i);
        if (inBlock == w - 1 || i == padded - 1)
            std::copy(x, x + width, s);
        else
            for (int k = 0; k < width; ++k)
                s[k] = std::max(s[k + width], x[k]);
    }
    for (int i = 0; i < n; ++i) {
        const float* s = line(suffix, i);
        const float* p = line(prefix, i + 2 * r);
        float* o = out + i * outStride;
        for (int k = 0; k < width; ++k)
            o[k] = std::max(s[k], p[k]);
    }
}

} // namespace

HeightGrid riseWithin(const HeightGrid& grid, double radiusM) {
    if (grid.empty())
        return {};
    const int cols = grid.cols(), rows = grid.rows();
    const int r = std::max(0, static_cast<int>(std::ceil(radiusM / grid.spacingM())));
    // No data counts as a low (never a rise); the heights along each row, then down the columns.
    std::vector<float> h(static_cast<std::size_t>(cols) * rows), tmp(h.size()), mx(h.size());
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i) {
            const float v = grid.node(i, j);
            h[static_cast<std::size_t>(j) * cols + i] = std::isnan(v) ? kLow : v;
        }
    std::vector<float> prefix, suffix, padded(static_cast<std::size_t>(cols) + 2 * r, kLow);
    for (int j = 0; j < rows; ++j) {
        std::copy_n(&h[static_cast<std::size_t>(j) * cols], cols, padded.begin() + r);
        runningMax<1>([&](int i) { return &padded[static_cast<std::size_t>(i)]; }, cols, 1, r, prefix, suffix,
                   &tmp[static_cast<std::size_t>(j) * cols], 1);
    }
    constexpr int kStrip = 256;
    const std::vector<float> lowLine(kStrip, kLow);
    for (int c0 = 0; c0 < cols; c0 += kStrip) {
        const int width = std::min(kStrip, cols - c0);
        runningMax([&](int j) { return j < r || j >= rows + r ? lowLine.data() : &tmp[static_cast<std::size_t>(j - r) * cols + c0]; },
                   rows, width, r, prefix, suffix, &mx[static_cast<std::size_t>(c0)], static_cast<std::size_t>(cols));
    }
    for (std::size_t k = 0; k < h.size(); ++k)
        mx[k] = h[k] == kLow ? std::numeric_limits<float>::quiet_NaN() : mx[k] - h[k];
    return HeightGrid(grid.x0(), grid.y0(), grid.spacingM(), cols, rows, std::move(mx));
}

double maxRiseWithin(const HeightGrid& grid, double radiusM, const std::function<bool(const geo::Vec2&)>& inside) {
    return maxRiseWithin(riseWithin(grid, radiusM), inside);
}

double maxRiseWithin(const HeightGrid& rises, const std::function<bool(const geo::Vec2&)>& inside) {
    double rise = 0.0;
    for (int j = 0; j < rises.rows(); ++j)
        for (int i = 0; i < rises.cols(); ++i) {
            const float v = rises.node(i, j);
            if (!(v > rise)) // no data (NaN) is neither a rise nor a place
                continue;
            if (inside(rises.nodePosition(i, j)))
                rise = v;
        }
    return rise;
}

double maxRiseAlong(const HeightGrid& rises, const geo::Vec2& a, const geo::Vec2& b) {
    if (rises.empty())
        return std::numeric_limits<double>::infinity();
    // Every node of a cell the segment passes through: sampled at a quarter of the node spacing.
    const double step = 0.25 * rises.spacingM();
    const double len = (b - a).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
    double rise = 0.0;
    for (int s = 0; s <= n; ++s) {
        const geo::Vec2 p = a + (b - a) * (static_cast<double>(s) / n);
        const double fc = (p.x() - rises.x0()) / rises.spacingM(), fr = (rises.y0() - p.y()) / rises.spacingM();
        const int c0 = static_cast<int>(std::floor(fc)), r0 = static_cast<int>(std::floor(fr));
        if (!(fc >= 0 && fr >= 0 && fc <= rises.cols() - 1 && fr <= rises.rows() - 1))
            return std::numeric_limits<double>::infinity(); // ground the grid does not know
        for (int r = r0; r <= r0 + 1; ++r)
            for (int c = c0; c <= c0 + 1; ++c) {
                if (c < 0 || r < 0 || c >= rises.cols() || r >= rises.rows())
                    continue;
                const float v = rises.node(c, r);
                if (v > rise)
                    rise = v;
            }
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
