// SeamMap: which photo every mosaic pixel comes from (the one that sees it most from above) and,
// near seams when feathering, the runner-up; kept in a scratch raster so memory stays bounded.
#pragma once

#include "core/geo/types.h"
#include "core/mosaic/output_grid.h"
#include "core/mosaic/photo_geometry.h"
#include "core/result.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pf::mosaic {

class SeamMap {
public:
    // Labels every pixel of `grid` and writes the labels to a scratch GeoTIFF at `scratchPath`
    // (deleted with the map). `area` (grid metres, may be empty) is only counted: how much of it
    // the photos cover. `progress` receives the fraction done and returns false to stop (then
    // Cancelled).
    static Result<std::unique_ptr<SeamMap>>
    compute(const std::vector<PhotoGeometry>& photos, const GroundModel& ground,
            const OutputGrid& grid, const geo::MultiPolygon& area, double featherM, int threads,
            const std::string& scratchPath, const std::function<bool(double)>& progress);
    ~SeamMap();
    SeamMap(const SeamMap&) = delete;
    SeamMap& operator=(const SeamMap&) = delete;

    // Per photo: the pixels it gives colour to (empty if none).
    const std::vector<PixelWindow>& windows() const { return m_windows; }
    // The labels of a window, row by row: photo index + 1 (0: no photo). `second` is the photo
    // blended in near a seam (0: none). Thread-safe.
    Status read(const PixelWindow& w, std::vector<std::uint16_t>* best,
                std::vector<std::uint16_t>* second) const;
    // The part of the mosaic taken from each photo, grid metres (polygons along pixel edges).
    Result<std::vector<geo::MultiPolygon>> seamPolygons(int photoCount) const;

    long long coveredPixels() const { return m_covered; }
    // Pixels of `area` a photo covers.
    long long coveredAreaPixels() const { return m_coveredArea; }
    const OutputGrid& grid() const { return m_grid; }

    struct Impl;

private:
    SeamMap() = default;
    std::unique_ptr<Impl> m_impl;
    std::vector<PixelWindow> m_windows;
    OutputGrid m_grid;
    long long m_covered = 0;
    long long m_coveredArea = 0;
};

} // namespace pf::mosaic
