// Usage: pf_demo_dem_generator OUTPUT.tif
//
// Writes the SYNTHETIC terrain model of the demo site (the same extent as the demo map): a plain at
// 112 m above sea level rising gently to the north, a hill of 35 m in the north-west of the site and
// a valley 12 m deep along its south-east. EPSG:4326 heights (EGM96 vertical datum, as SRTM's),
// Float32, tiled, about 2 m pixels. Labelled SYNTHETIC in its metadata so that no one mistakes it
// for a survey.
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr double kLonMin = 8.3230, kLonMax = 8.3370, kLatMin = 49.0085, kLatMax = 49.0160;
constexpr double kPi = 3.14159265358979323846;
constexpr double kPixelDeg = 0.00002; // about 1.5 m east-west and 2.2 m north-south

double metresEast(double lon) { return (lon - 8.3300) * 111'320.0 * std::cos(49.012 * kPi / 180.0); }
double metresNorth(double lat) { return (lat - 49.0120) * 111'200.0; }

double height(double lon, double lat) {
    const double x = metresEast(lon), y = metresNorth(lat);
    const double hill = 35.0 * std::exp(-((x + 150) * (x + 150) + (y - 90) * (y - 90)) / (2 * 80.0 * 80.0));
    // The valley runs from south-west to north-east, its floor 12 m below the plain.
    const double d = ((x - 120) - (y + 60)) / std::sqrt(2.0);
    const double valley = -12.0 * std::exp(-d * d / (2 * 35.0 * 35.0));
    return 112.0 + 0.03 * y + hill + valley;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT.tif\n", argv[0]);
        return 2;
    }
    GDALAllRegister();
    const int cols = static_cast<int>(std::ceil((kLonMax - kLonMin) / kPixelDeg));
    const int rows = static_cast<int>(std::ceil((kLatMax - kLatMin) / kPixelDeg));
    GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
    if (!gtiff) {
        std::fprintf(stderr, "pf_demo_dem_generator: GDAL has no GTiff driver\n");
        return 1;
    }
    const char* opts[] = {"TILED=YES", "COMPRESS=DEFLATE", "PREDICTOR=3", nullptr};
    GDALDatasetUniquePtr ds(gtiff->Create(argv[1], cols, rows, 1, GDT_Float32, const_cast<char**>(opts)));
    if (!ds) {
        std::fprintf(stderr, "pf_demo_dem_generator: cannot create %s: %s\n", argv[1], CPLGetLastErrorMsg());
        return 1;
    }
    double gt[6] = {kLonMin, kPixelDeg, 0, kLatMax, 0, -kPixelDeg};
    ds->SetGeoTransform(gt);
    OGRSpatialReference srs;
    srs.SetFromUserInput("EPSG:4326+5773"); // WGS 84 + EGM96 height
    ds->SetSpatialRef(&srs);
    ds->SetMetadataItem("SYNTHETIC", "YES");
    ds->SetMetadataItem("TIFFTAG_IMAGEDESCRIPTION",
                        "SYNTHETIC terrain model of the Photoflight demo site (a hill and a valley), not a survey");
    GDALRasterBand* band = ds->GetRasterBand(1);
    band->SetNoDataValue(-9999.0);
    band->SetUnitType("m");
    std::vector<float> row(static_cast<std::size_t>(cols));
    for (int r = 0; r < rows; ++r) {
        const double lat = kLatMax - (r + 0.5) * kPixelDeg;
        for (int c = 0; c < cols; ++c)
            row[static_cast<std::size_t>(c)] = static_cast<float>(height(kLonMin + (c + 0.5) * kPixelDeg, lat));
        if (band->RasterIO(GF_Write, 0, r, cols, 1, row.data(), cols, 1, GDT_Float32, 0, 0, nullptr) != CE_None) {
            std::fprintf(stderr, "pf_demo_dem_generator: cannot write row %d of %s\n", r, argv[1]);
            return 1;
        }
    }
    return 0;
}
