// HeightGrid: terrain heights on a regular grid in one projected frame, sampled bilinearly.
#pragma once

#include "core/geo/polygon_ops.h"
#include "core/geo/types.h"

#include <optional>
#include <vector>

namespace pf::terrain {

// Heights (metres above mean sea level, orthometric) at the nodes of a north-up grid in a projected
// frame (the mission's local frame, or the mosaic's UTM zone): node (col, row) lies at
// (x0 + col * spacing, y0 - row * spacing), row 0 the northernmost. NaN marks "no data". A read-only
// value: safe to share between threads.
class HeightGrid {
public:
    HeightGrid() = default;
    HeightGrid(double x0, double y0, double spacingM, int cols, int rows, std::vector<float> heights);

    double x0() const { return m_x0; }
    double y0() const { return m_y0; }
    double spacingM() const { return m_spacing; }
    int cols() const { return m_cols; }
    int rows() const { return m_rows; }
    bool empty() const { return m_cols == 0 || m_rows == 0; }
    // The node's height (NaN for no data); col and row must lie in the grid.
    float node(int col, int row) const { return m_h[static_cast<std::size_t>(row) * m_cols + col]; }
    geo::Vec2 nodePosition(int col, int row) const { return {m_x0 + col * m_spacing, m_y0 - row * m_spacing}; }
    // The nodes' extent (first to last node centre).
    geo::Box extent() const;

    // Bilinear height at p; nothing outside the grid or where a surrounding node has no data.
    std::optional<double> heightAt(const geo::Vec2& p) const;
    // The same with a value for "unknown" (NaN by default), for loops that test with std::isnan.
    double heightOr(const geo::Vec2& p, double unknown) const;
    // The lowest and highest node heights (NaN, NaN when every node is no data).
    std::pair<double, double> range() const;

private:
    double m_x0 = 0.0, m_y0 = 0.0, m_spacing = 1.0;
    int m_cols = 0, m_rows = 0;
    std::vector<float> m_h;
};

// The heights along the straight line a -> b, every `stepM` metres from a (and at b).
struct ProfileSample {
    double distanceM = 0.0; // from a
    geo::Vec2 pos{0, 0};
    double groundM = 0.0;   // NaN where the grid has no data
};
std::vector<ProfileSample> profile(const HeightGrid& grid, const geo::Vec2& a, const geo::Vec2& b, double stepM = 1.0);

} // namespace pf::terrain
