// MosaicCanvas: the mosaic's colour while photos are added (a scratch raster, written tile by
// tile), and its final form, a tiled, compressed GeoTIFF with overviews (cloud-optimised layout).
#pragma once

#include "core/mosaic/output_grid.h"
#include "core/result.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pf::mosaic {

class MosaicCanvas {
public:
    // An empty (transparent) canvas in a scratch GeoTIFF at `scratchPath`, deleted with the canvas.
    static Result<std::unique_ptr<MosaicCanvas>>
    create(const OutputGrid& grid, const std::string& wkt, const std::string& scratchPath);
    ~MosaicCanvas();
    MosaicCanvas(const MosaicCanvas&) = delete;
    MosaicCanvas& operator=(const MosaicCanvas&) = delete;

    // Adds weight x colour to the window's pixels (weights of one pixel over all photos sum to 1)
    // and makes the pixels with `opaque` set visible. Thread-safe.
    Status add(const PixelWindow& window, const std::vector<std::uint8_t>& rgb,
               const std::vector<float>& weight, const std::vector<std::uint8_t>& opaque);

    // Writes the final GeoTIFF (atomically: a temporary file beside it, then a rename): 512 x 512
    // tiles, JPEG (quality 90, transparency as a mask) or DEFLATE (alpha band), overviews down to a
    // few hundred pixels, metadata items in the default domain. `progress` returns false to stop.
    Status writeGeoTiff(const std::string& path, bool jpeg,
                        const std::map<std::string, std::string>& metadata,
                        const std::function<bool(double)>& progress);

private:
    MosaicCanvas() = default;
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace pf::mosaic
