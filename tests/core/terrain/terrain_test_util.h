// Synthetic DEMs for the terrain tests and the benchmark: heights from a function of the mission's
// local metres, written through GDAL in any CRS and format.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/types.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pf::terrain::test {

using HeightFn = std::function<double(const geo::Vec2& local)>;

// A plane rising `slope` (0.15: 15 %) towards the east from `base` metres, plus a Gaussian hill of
// `hillM` metres and sigma `sigmaM` centred at `hill` (local metres).
inline HeightFn slopeAndHill(double base, double slope, double hillM, geo::Vec2 hill, double sigmaM) {
    return [=](const geo::Vec2& p) {
        const double d2 = (p - hill).squaredNorm();
        return base + slope * p.x() + hillM * std::exp(-d2 / (2 * sigmaM * sigmaM));
    };
}

struct DemSpec {
    std::string srs = "EPSG:32632";  // any definition OGR reads
    std::string driver = "GTiff";
    double pixel = 1.0;              // in the CRS's units
    double marginM = 150.0;          // around the frame's box
    geo::Vec2 boxMin{-200, -150}, boxMax{200, 150}; // local metres covered
    double noData = -9999.0;
    bool allNoData = false;
    std::function<bool(const geo::Vec2&)> hasData; // unset: every pixel
    std::string unit;                // band unit type ("ft" converts)
    double unitScale = 1.0;          // heights written = metres / unitScale
};

// Writes a Float32 DEM of fn over the spec's box (grown by its margin) around `frame` and returns
// "" or GDAL's complaint.
inline std::string writeDem(const std::string& path, const geo::LocalFrame& frame, const HeightFn& fn,
                            const DemSpec& spec = {}) {
    GDALAllRegister();
    OGRSpatialReference srs, geo;
    srs.SetFromUserInput(spec.srs.c_str());
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    geo.SetWellKnownGeogCS("WGS84");
    geo.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> fromGeo(OGRCreateCoordinateTransformation(&geo, &srs));
    std::unique_ptr<OGRCoordinateTransformation> toGeo(OGRCreateCoordinateTransformation(&srs, &geo));
    if (!fromGeo || !toGeo)
        return "no transformation for " + spec.srs;
    // The box's corners in the DEM's CRS.
    double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
    const geo::Vec2 lo = spec.boxMin - geo::Vec2(spec.marginM, spec.marginM);
    const geo::Vec2 hi = spec.boxMax + geo::Vec2(spec.marginM, spec.marginM);
    for (const geo::Vec2& c : {lo, hi, geo::Vec2(lo.x(), hi.y()), geo::Vec2(hi.x(), lo.y())}) {
        const geo::LonLat g = frame.toGeo(c);
        double x = g.lon, y = g.lat;
        fromGeo->Transform(1, &x, &y);
        xmin = std::min(xmin, x), ymin = std::min(ymin, y), xmax = std::max(xmax, x), ymax = std::max(ymax, y);
    }
    const int cols = static_cast<int>(std::ceil((xmax - xmin) / spec.pixel));
    const int rows = static_cast<int>(std::ceil((ymax - ymin) / spec.pixel));
    // Written to a MEM dataset first, then copied (SRTMHGT and VRT only support CreateCopy).
    GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
    GDALDatasetUniquePtr ds(mem->Create("", cols, rows, 1, GDT_Float32, nullptr));
    double gt[6] = {xmin, spec.pixel, 0, ymax, 0, -spec.pixel};
    ds->SetGeoTransform(gt);
    ds->SetSpatialRef(&srs);
    std::vector<float> row(static_cast<std::size_t>(cols));
    std::vector<double> xs(static_cast<std::size_t>(cols)), ys(static_cast<std::size_t>(cols));
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            xs[c] = xmin + (c + 0.5) * spec.pixel;
            ys[c] = ymax - (r + 0.5) * spec.pixel;
        }
        toGeo->Transform(cols, xs.data(), ys.data());
        for (int c = 0; c < cols; ++c) {
            const geo::Vec2 p = frame.toLocal(geo::LonLat{xs[c], ys[c]});
            const bool data = !spec.allNoData && (!spec.hasData || spec.hasData(p));
            row[c] = data ? static_cast<float>(fn(p) / spec.unitScale) : static_cast<float>(spec.noData);
        }
        if (ds->GetRasterBand(1)->RasterIO(GF_Write, 0, r, cols, 1, row.data(), cols, 1, GDT_Float32, 0, 0, nullptr) !=
            CE_None)
            return "cannot write row " + std::to_string(r);
    }
    ds->GetRasterBand(1)->SetNoDataValue(spec.noData);
    if (!spec.unit.empty())
        ds->GetRasterBand(1)->SetUnitType(spec.unit.c_str());
    GDALDriver* drv = GetGDALDriverManager()->GetDriverByName(spec.driver.c_str());
    if (!drv)
        return "no driver " + spec.driver;
    const char* tiled[] = {"TILED=YES", nullptr};
    GDALDatasetUniquePtr out(
        drv->CreateCopy(path.c_str(), ds.get(), FALSE, spec.driver == "GTiff" ? const_cast<char**>(tiled) : nullptr,
                        nullptr, nullptr));
    return out ? std::string() : "cannot write " + path + ": " + CPLGetLastErrorMsg();
}

// A VRT that shows `source` with its CRS replaced by `srs` (e.g. a 3D CRS for ellipsoidal heights).
inline std::string writeVrtWithSrs(const std::string& path, const std::string& source, const std::string& srs) {
    GDALAllRegister();
    GDALDatasetUniquePtr src(GDALDataset::Open(source.c_str(), GDAL_OF_RASTER));
    if (!src)
        return "cannot open " + source;
    GDALDriver* vrt = GetGDALDriverManager()->GetDriverByName("VRT");
    GDALDatasetUniquePtr out(vrt->CreateCopy(path.c_str(), src.get(), FALSE, nullptr, nullptr, nullptr));
    if (!out)
        return "cannot write " + path;
    OGRSpatialReference s;
    s.SetFromUserInput(srs.c_str());
    out->SetSpatialRef(&s);
    return "";
}

// The fraction of the line through ca and cb (on through both footprints) that lies in both rings,
// over its part in a: the front overlap of two photos measured on the line through their centres,
// from their footprints on the terrain.
inline double overlapAlong(const geo::Ring& a, const geo::Ring& b, const geo::Vec2& ca, const geo::Vec2& cb) {
    const geo::Polygon pa{a, {}}, pb{b, {}};
    const geo::Vec2 dir = (cb - ca).normalized();
    int inA = 0, inBoth = 0;
    for (double s = -150.0; s <= 150.0 + (cb - ca).norm(); s += 0.05) {
        const geo::Vec2 p = ca + dir * s;
        if (!geo::contains(pa, p))
            continue;
        ++inA;
        inBoth += geo::contains(pb, p);
    }
    return inA ? static_cast<double>(inBoth) / inA : 0.0;
}

} // namespace pf::terrain::test
