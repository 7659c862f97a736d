// PhotoWarper: one photo resampled onto a window of the output grid by GDAL's warper, through a
// camera-model transformer (the perspective of a tilted photo over the ground model).
#pragma once

#include "core/mosaic/ground_model.h"
#include "core/mosaic/output_grid.h"
#include "core/mosaic/photo_geometry.h"
#include "core/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pf::mosaic {

struct WarpedWindow {
    PixelWindow window;
    std::vector<std::uint8_t> rgb; // pixel-interleaved, window.w x window.h x 3
    int level = 0;                 // the JPEG reduction used: the photo was decoded at 1/2^level
};

enum class Resampling { Bilinear, Cubic, Lanczos };

// Decodes the part of the photo the window needs, at the coarsest reduction that is still at least
// as fine as the output, and warps it. Pixels the photo does not hold stay 0. Thread-safe (every
// call opens its own dataset).
Result<WarpedWindow> warpPhoto(const std::string& path, const PhotoGeometry& photo,
                               const GroundModel& ground, const OutputGrid& grid,
                               const PixelWindow& window,
                               Resampling resampling = Resampling::Bilinear);

} // namespace pf::mosaic
