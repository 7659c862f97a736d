#include "core/terrain/hillshade.h"

#include <algorithm>
#include <cmath>

namespace pf::terrain {

std::vector<std::uint8_t> hillshade(const HeightGrid& grid, const HillshadeOptions& o) {
    const int cols = grid.cols(), rows = grid.rows();
    std::vector<std::uint8_t> out(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows),
                                  0);
    if (grid.empty())
        return out;
    const double zenith = (90.0 - o.altitudeDeg) * M_PI / 180.0;
    // The azimuth as a mathematical angle (counter-clockwise from east).
    const double azimuth = (90.0 - o.azimuthDeg) * M_PI / 180.0;
    const double cosZ = std::cos(zenith), sinZ = std::sin(zenith);
    const double cell = grid.spacingM() * o.groundMetresPerUnit;
    const double scale = o.zFactor / (8.0 * cell);
    auto at = [&](int c, int r) {
        return static_cast<double>(
            grid.node(std::clamp(c, 0, cols - 1), std::clamp(r, 0, rows - 1)));
    };
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            // a b c / d e f / g h i, row r - 1 to the north.
            const double a = at(c - 1, r - 1), b = at(c, r - 1), cc = at(c + 1, r - 1);
            const double d = at(c - 1, r), e = at(c, r), f = at(c + 1, r);
            const double g = at(c - 1, r + 1), h = at(c, r + 1), i = at(c + 1, r + 1);
            // Rises to the east and to the north.
            const double dzdx = ((cc + 2 * f + i) - (a + 2 * d + g)) * scale;
            const double dzdy = ((a + 2 * b + cc) - (g + 2 * h + i)) * scale;
            if (std::isnan(dzdx) || std::isnan(dzdy) || std::isnan(e))
                continue;
            const double slope = std::atan(std::hypot(dzdx, dzdy));
            // The aspect: the direction the slope faces (downhill), counter-clockwise from east.
            const double aspect = std::atan2(-dzdy, -dzdx);
            const double v = 255.0 * (cosZ * std::cos(slope) +
                                      sinZ * std::sin(slope) * std::cos(azimuth - aspect));
            out[static_cast<std::size_t>(r) * cols + c] =
                static_cast<std::uint8_t>(std::clamp(std::lround(v), 1L, 255L));
        }
    return out;
}

} // namespace pf::terrain
