// Dem: a digital elevation model read through GDAL (GeoTIFF, SRTM .hgt, VRT, any raster GDAL reads,
// in any CRS), resampled onto the grids the planner and the mosaic sample.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/types.h"
#include "core/result.h"
#include "core/terrain/height_grid.h"

#include <memory>
#include <optional>
#include <string>

namespace pf::terrain {

// What the file says about itself.
struct DemInfo {
    std::string path;
    std::string driver;           // GDAL driver short name: GTiff, SRTMHGT, VRT, ...
    int widthPx = 0;
    int heightPx = 0;
    std::string crs;              // the horizontal CRS's name
    std::string verticalDatum;    // in words: "EGM96 height", "ellipsoidal (WGS 84), converted to EGM96", ...
    bool ellipsoidal = false;     // heights above the ellipsoid in the file (converted on reading)
    double pixelSizeM = 0.0;      // the ground size of one pixel near the DEM's centre
    double unitToMetres = 1.0;    // the band's unit (metres, feet) to metres
    geo::LonLat southWest, northEast; // the DEM's bounds in WGS84
    bool synthetic = false;       // labelled synthetic in its metadata (the demo DEM)
    std::string description;      // the file's description metadata, if any
};

// Heights in every grid are orthometric metres (above mean sea level): the file's own heights when
// it states a geoid-based datum (EGM96, EGM2008, a national one) or states none, its ellipsoidal
// heights minus the EGM96 geoid undulation (PROJ, egm96_15.gtx) when it says they are ellipsoidal.
// Band scale/offset and a unit in feet are applied. The dataset is read under a lock: one Dem can
// be shared between threads (GDAL's block cache keeps what was read).
class Dem {
public:
    // Opens a DEM. Errors (naming the file): not readable, not a raster, no georeferencing, an
    // unsupported height unit, ellipsoidal heights without a geoid model to convert them.
    static Result<Dem> open(const std::string& path);

    // Whether a file is a terrain model rather than a picture (what dropping it on the map does):
    // .hgt and .dem always; .tif, .tiff and .vrt when GDAL reads them as georeferenced rasters of one
    // band of heights (not 8-bit, no colour table). Other names: false.
    static bool looksLikeDem(const std::string& path);

    Dem(Dem&&) noexcept;
    Dem& operator=(Dem&&) noexcept;
    ~Dem();

    const DemInfo& info() const;

    // Heights at the nodes of a north-up grid in `srs` (a PROJ string, WKT or "EPSG:n"), node (0, 0)
    // at (x0, y0), `cols` x `rows` nodes `spacingM` apart: bilinear resampling by GDAL's warper
    // (error threshold 1 % of a pixel), NaN where the DEM has no data or does not reach.
    Result<HeightGrid> resample(const std::string& srs, double x0, double y0, double spacingM, int cols,
                                int rows) const;

    // Heights over `region` (local metres of `frame`) and `marginM` around it, on a grid of
    // `spacingM` (0: the DEM's pixel size, at most 5 m and at least 0.5 m; coarser if the grid would
    // exceed 16 million nodes). Errors: the DEM does not cover part of the region (the message says
    // which part, where and how much of it) or has only no-data there. Points of the margin outside
    // the DEM stay NaN.
    Result<HeightGrid> overRegion(const geo::LocalFrame& frame, const geo::MultiPolygon& region, double marginM,
                                  double spacingM = 0.0) const;

    struct Impl;

private:
    explicit Dem(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

} // namespace pf::terrain
