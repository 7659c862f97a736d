// Hillshade: the shaded relief of a height grid (Horn's slope, a light from the north-west), the
// picture the map shows under the plan so that the terrain's hills and valleys can be read.
#pragma once

#include "core/terrain/height_grid.h"

#include <cstdint>
#include <vector>

namespace pf::terrain {

struct HillshadeOptions {
    double azimuthDeg = 315.0; // where the light comes from, clockwise from north
    double altitudeDeg = 45.0; // the light's height above the horizon
    // Ground metres per grid unit: heights are in metres, so a grid in Web Mercator metres (which
    // stretch by 1 / cos(latitude)) needs cos(latitude) here to keep the real slopes.
    double groundMetresPerUnit = 1.0;
    double zFactor = 1.0; // vertical exaggeration
};

// One brightness per node, row by row (row 0 the northernmost, as the grid): 1..255 for
//   255 * (cos(zenith) cos(slope) + sin(zenith) sin(slope) cos(azimuth - aspect)),
// clamped to at least 1, with the slope and aspect of Horn's 3 x 3 operator (on the border the
// missing neighbours repeat the border node); 0 where the node or a neighbour has no data (drawn
// transparent). Flat ground is 255 * sin(altitude), 180 for 45°.
std::vector<std::uint8_t> hillshade(const HeightGrid& grid, const HillshadeOptions& options = {});

} // namespace pf::terrain
