// The DEM read onto a grid without GDAL's warper: the source window the grid needs read once
// (tiled reads through GDAL's block cache), bilinear interpolation at each node through a lattice
// of exact coordinate transformations. Several times faster than the warper on large grids.
#pragma once

#include "core/result.h"

#include <optional>
#include <string>
#include <vector>

class GDALRasterBand;

namespace pf::terrain::detail {

struct SourceRaster {
    GDALRasterBand* band = nullptr;
    int widthPx = 0, heightPx = 0;
    const double* invGeoTransform = nullptr; // georeferenced -> pixel coordinates (6 numbers)
    std::optional<double> noData;
    bool maskBand = false;     // validity from the band's mask, not a nodata value
    std::string horizontalWkt; // the source's horizontal CRS
};

// Heights at the nodes of a north-up grid in `srs` (node (0, 0) at (x0, y0), `spacingM` apart, row
// 0 the northernmost) into `out` (cols x rows, row by row), in the band's raw values; NaN where the
// DEM has no data or does not reach. Bilinear between the four pixels around a node (no-data pixels
// left out, the others' weights renormalised); where the grid is coarser than the DEM by a factor
// of 2 or more, the window is first read averaged down by GDAL to about the grid's spacing. The
// lattice of exact transformations is refined until linear interpolation between its nodes stays
// within 1 % of a pixel. False (and `out` untouched) when it does not apply: a transformation PROJ
// refuses somewhere over the grid; the caller then uses the warper. Errors: the read failed.
Result<bool> resampleDirect(const SourceRaster& src, const std::string& srs, double x0, double y0,
                            double spacingM, int cols, int rows, std::vector<float>& out);

} // namespace pf::terrain::detail
