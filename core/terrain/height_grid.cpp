#include "core/terrain/height_grid.h"

#include <cmath>
#include <limits>

namespace pf::terrain {

HeightGrid::HeightGrid(double x0, double y0, double spacingM, int cols, int rows, std::vector<float> heights)
    : m_x0(x0), m_y0(y0), m_spacing(spacingM), m_cols(cols), m_rows(rows), m_h(std::move(heights)) {}

geo::Box HeightGrid::extent() const {
    return {{m_x0, m_y0 - (m_rows - 1) * m_spacing}, {m_x0 + (m_cols - 1) * m_spacing, m_y0}};
}

double HeightGrid::heightOr(const geo::Vec2& p, double unknown) const {
    if (empty())
        return unknown;
    const double fx = (p.x() - m_x0) / m_spacing;
    const double fy = (m_y0 - p.y()) / m_spacing;
    // A point on the last row or column is sampled from the cell before it (weight 1 on the edge).
    if (!(fx >= 0.0 && fy >= 0.0 && fx <= m_cols - 1 && fy <= m_rows - 1))
        return unknown;
    const int c = std::min(static_cast<int>(fx), std::max(m_cols - 2, 0));
    const int r = std::min(static_cast<int>(fy), std::max(m_rows - 2, 0));
    const double tx = fx - c, ty = fy - r;
    const int c1 = std::min(c + 1, m_cols - 1), r1 = std::min(r + 1, m_rows - 1);
    const double h00 = node(c, r), h10 = node(c1, r), h01 = node(c, r1), h11 = node(c1, r1);
    const double h = (h00 * (1 - tx) + h10 * tx) * (1 - ty) + (h01 * (1 - tx) + h11 * tx) * ty;
    return std::isnan(h) ? unknown : h;
}

std::optional<double> HeightGrid::heightAt(const geo::Vec2& p) const {
    const double h = heightOr(p, std::numeric_limits<double>::quiet_NaN());
    if (std::isnan(h))
        return std::nullopt;
    return h;
}

std::pair<double, double> HeightGrid::range() const {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (float h : m_h)
        if (!std::isnan(h)) {
            lo = std::min(lo, static_cast<double>(h));
            hi = std::max(hi, static_cast<double>(h));
        }
    if (lo > hi)
        return {std::nan(""), std::nan("")};
    return {lo, hi};
}

std::vector<ProfileSample> profile(const HeightGrid& grid, const geo::Vec2& a, const geo::Vec2& b, double stepM) {
    std::vector<ProfileSample> out;
    const double len = (b - a).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(len / std::max(stepM, 1e-3))));
    out.reserve(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) {
        const double s = std::min(i * stepM, len);
        const geo::Vec2 p = len > 0 ? geo::Vec2(a + (b - a) * (s / len)) : a;
        out.push_back({s, p, grid.heightOr(p, std::numeric_limits<double>::quiet_NaN())});
    }
    return out;
}

} // namespace pf::terrain
