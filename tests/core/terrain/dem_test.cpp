// The DEM reader: formats (GeoTIFF, SRTM .hgt, VRT), CRSs, vertical datums, units, and its errors.
#include "core/terrain/dem.h"

#include "tests/core/terrain/terrain_test_util.h"

#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace pf::terrain {
namespace {

const geo::LonLat kOrigin{8.33, 49.012};

geo::LocalFrame frame() { return *geo::LocalFrame::create(kOrigin); }

geo::MultiPolygon rect(double x0, double y0, double x1, double y1) {
    return {{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}}};
}

std::string tmp(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / "pf_dem_test";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

// Largest |grid - fn| over seeded random points of the rectangle.
double maxError(const HeightGrid& g, const test::HeightFn& fn, double offset = 0.0) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(-190, 190), uy(-140, 140);
    double worst = 0;
    for (int i = 0; i < 300; ++i) {
        const geo::Vec2 p(ux(rng), uy(rng));
        const auto h = g.heightAt(p);
        if (!h)
            return 1e9;
        worst = std::max(worst, std::fabs(*h - (fn(p) + offset)));
    }
    return worst;
}

const test::HeightFn kTerrain = test::slopeAndHill(120.0, 0.15, 40.0, geo::Vec2(30, -20), 60.0);

TEST(Dem, GeoTiffInUtmIsResampledBilinearlyIntoTheLocalFrame) {
    const auto f = frame();
    const std::string path = tmp("utm.tif");
    test::DemSpec spec;
    spec.pixel = 2.0;
    ASSERT_EQ(test::writeDem(path, f, kTerrain, spec), "");
    auto dem = Dem::open(path);
    ASSERT_TRUE(dem.ok()) << dem.error().message;
    EXPECT_EQ(dem->info().driver, "GTiff");
    EXPECT_NEAR(dem->info().pixelSizeM, 2.0, 1e-9);
    EXPECT_FALSE(dem->info().ellipsoidal);
    EXPECT_FALSE(dem->info().synthetic);
    auto g = dem->overRegion(f, rect(-200, -150, 200, 150), 20.0);
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_DOUBLE_EQ(g->spacingM(), 2.0);
    // Two bilinear interpolations of a 2 m grid of a smooth surface (15 % plane, 40 m hill).
    EXPECT_LT(maxError(*g, kTerrain), 0.05);
    // A profile every metre along a leg.
    const auto prof = profile(*g, {-100, 0}, {100, 0}, 1.0);
    ASSERT_EQ(prof.size(), 201u);
    EXPECT_NEAR(prof[100].groundM, kTerrain({0, 0}), 0.05);
    EXPECT_DOUBLE_EQ(prof.back().distanceM, 200.0);
}

TEST(Dem, GeographicGeoTiffVrtAndEgm96CompoundGiveTheSameHeights) {
    const auto f = frame();
    const std::string path = tmp("geo.tif");
    test::DemSpec spec;
    spec.srs = "EPSG:4326";
    spec.pixel = 2.0e-5; // about 1.5 x 2.2 m
    ASSERT_EQ(test::writeDem(path, f, kTerrain, spec), "");
    auto dem = Dem::open(path);
    ASSERT_TRUE(dem.ok()) << dem.error().message;
    EXPECT_NEAR(dem->info().pixelSizeM, 2.0e-5 * 111'320 * std::cos(49.012 * M_PI / 180), 0.05);
    auto g = dem->overRegion(f, rect(-200, -150, 200, 150), 0.0);
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_LT(maxError(*g, kTerrain), 0.05);

    // The same pixels through a VRT that states EGM96 heights: read unchanged, datum reported.
    const std::string vrt = tmp("geo_egm96.vrt");
    ASSERT_EQ(test::writeVrtWithSrs(vrt, path, "EPSG:4326+5773"), "");
    auto d2 = Dem::open(vrt);
    ASSERT_TRUE(d2.ok()) << d2.error().message;
    EXPECT_EQ(d2->info().driver, "VRT");
    EXPECT_NE(d2->info().verticalDatum.find("EGM96"), std::string::npos) << d2->info().verticalDatum;
    auto g2 = d2->overRegion(f, rect(-200, -150, 200, 150), 0.0);
    ASSERT_TRUE(g2.ok()) << g2.error().message;
    EXPECT_LT(maxError(*g2, kTerrain), 0.05);
}

TEST(Dem, EllipsoidalHeightsAreConvertedToEgm96ThroughProj) {
    const auto f = frame();
    const std::string path = tmp("ell.tif");
    test::DemSpec spec;
    spec.srs = "EPSG:4326";
    spec.pixel = 4.0e-5;
    ASSERT_EQ(test::writeDem(path, f, kTerrain, spec), "");
    const std::string vrt = tmp("ell.vrt");
    ASSERT_EQ(test::writeVrtWithSrs(vrt, path, "EPSG:4979"), "");
    auto dem = Dem::open(vrt);
    ASSERT_TRUE(dem.ok()) << dem.error().message;
    EXPECT_TRUE(dem->info().ellipsoidal);
    auto g = dem->overRegion(f, rect(-200, -150, 200, 150), 0.0);
    ASSERT_TRUE(g.ok()) << g.error().message;
    // H = h - N; the EGM96 undulation near 49 N 8.3 E is about +47.6 m and varies by centimetres
    // over the site.
    const double n = kTerrain({0, 0}) - *g->heightAt({0, 0});
    EXPECT_GT(n, 45.0);
    EXPECT_LT(n, 50.0);
    EXPECT_LT(maxError(*g, kTerrain, -n), 0.1);
}

TEST(Dem, SrtmHgtTileIsRead) {
    // A 3-arc-second SRTM tile (1201 x 1201, geographic, EGM96, whole metres): a plane rising
    // 1 m every 0.001 degree of longitude.
    GDALAllRegister();
    const std::string path = tmp("N49E008.hgt");
    GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
    GDALDatasetUniquePtr ds(mem->Create("", 1201, 1201, 1, GDT_Int16, nullptr));
    const double px = 1.0 / 1200;
    double gt[6] = {8.0 - px / 2, px, 0, 50.0 + px / 2, 0, -px};
    ds->SetGeoTransform(gt);
    OGRSpatialReference s;
    s.importFromEPSG(4326);
    ds->SetSpatialRef(&s);
    std::vector<std::int16_t> row(1201);
    for (int r = 0; r < 1201; ++r) {
        for (int c = 0; c < 1201; ++c)
            row[c] = static_cast<std::int16_t>(100 + c * px * 1000.0 + 0.5);
        ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, r, 1201, 1, row.data(), 1201, 1, GDT_Int16, 0, 0, nullptr),
                  CE_None);
    }
    GDALDatasetUniquePtr out(GetGDALDriverManager()->GetDriverByName("SRTMHGT")->CreateCopy(path.c_str(), ds.get(),
                                                                                          FALSE, nullptr, nullptr, nullptr));
    ASSERT_TRUE(out);
    out.reset();
    auto dem = Dem::open(path);
    ASSERT_TRUE(dem.ok()) << dem.error().message;
    EXPECT_EQ(dem->info().driver, "SRTMHGT");
    EXPECT_EQ(dem->info().widthPx, 1201);
    const auto f = frame();
    auto g = dem->overRegion(f, rect(-200, -150, 200, 150), 0.0);
    ASSERT_TRUE(g.ok()) << g.error().message;
    for (const geo::Vec2& p : {geo::Vec2(0, 0), geo::Vec2(150, 100), geo::Vec2(-180, -120)}) {
        const geo::LonLat ll = f.toGeo(p);
        EXPECT_NEAR(*g->heightAt(p), 100 + (ll.lon - 8.0) * 1000.0, 0.6) << p.transpose();
    }
}

TEST(Dem, HeightsInFeetAreConvertedToMetres) {
    const auto f = frame();
    const std::string path = tmp("feet.tif");
    test::DemSpec spec;
    spec.pixel = 2.0;
    spec.unit = "ft";
    spec.unitScale = 0.3048;
    ASSERT_EQ(test::writeDem(path, f, kTerrain, spec), "");
    auto dem = Dem::open(path);
    ASSERT_TRUE(dem.ok()) << dem.error().message;
    EXPECT_DOUBLE_EQ(dem->info().unitToMetres, 0.3048);
    auto g = dem->overRegion(f, rect(-200, -150, 200, 150), 0.0);
    ASSERT_TRUE(g.ok());
    EXPECT_LT(maxError(*g, kTerrain), 0.05);
}

TEST(Dem, ADemMissingPartOfTheAreaSaysWhichPart) {
    const auto f = frame();
    const std::string path = tmp("west.tif");
    test::DemSpec spec;
    spec.pixel = 2.0;
    spec.hasData = [](const geo::Vec2& p) { return p.x() < 50.0; }; // nothing east of x = 50 m
    ASSERT_EQ(test::writeDem(path, f, kTerrain, spec), "");
    auto dem = Dem::open(path);
    ASSERT_TRUE(dem.ok());
    auto g = dem->overRegion(f, rect(-200, -150, 200, 150), 0.0);
    ASSERT_FALSE(g.ok());
    const std::string& msg = g.error().message;
    EXPECT_NE(msg.find("does not cover the whole area"), std::string::npos) << msg;
    EXPECT_NE(msg.find("its east part"), std::string::npos) << msg;
    EXPECT_NE(msg.find(" % of the area"), std::string::npos) << msg; // 150 of 400 m
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
}

TEST(Dem, AllNoDataAnUnreadableFileAndAnotherPlaceAreRefused) {
    const auto f = frame();
    const std::string empty = tmp("nodata.tif");
    test::DemSpec spec;
    spec.pixel = 4.0;
    spec.allNoData = true;
    ASSERT_EQ(test::writeDem(empty, f, kTerrain, spec), "");
    auto dem = Dem::open(empty);
    ASSERT_TRUE(dem.ok());
    auto g = dem->overRegion(f, rect(-200, -150, 200, 150), 0.0);
    ASSERT_FALSE(g.ok());
    EXPECT_NE(g.error().message.find("has no heights over the area: every pixel there is no-data"), std::string::npos)
        << g.error().message;

    // A DEM of another place: the area is outside it.
    const auto far = *geo::LocalFrame::create({11.0, 48.0});
    const std::string other = tmp("other.tif");
    spec.allNoData = false;
    ASSERT_EQ(test::writeDem(other, far, kTerrain, spec), "");
    auto d2 = Dem::open(other);
    ASSERT_TRUE(d2.ok());
    auto g2 = d2->overRegion(f, rect(-200, -150, 200, 150), 0.0);
    ASSERT_FALSE(g2.ok());
    EXPECT_NE(g2.error().message.find("the area lies elsewhere"), std::string::npos) << g2.error().message;

    const std::string junk = tmp("junk.tif");
    std::ofstream(junk) << "this is not a raster";
    auto d3 = Dem::open(junk);
    ASSERT_FALSE(d3.ok());
    EXPECT_NE(d3.error().message.find("cannot be read"), std::string::npos) << d3.error().message;
    auto d4 = Dem::open(tmp("missing.tif"));
    ASSERT_FALSE(d4.ok());
    EXPECT_NE(d4.error().message.find("missing.tif\" cannot be read"), std::string::npos) << d4.error().message;
}

// kTerrain written to `path` by `spec` around frame(), then opened.
Result<Dem> writtenDem(const std::string& path, const test::DemSpec& spec) {
    if (const std::string why = test::writeDem(path, frame(), kTerrain, spec); !why.empty())
        return makeError(ErrorCode::IoError, why);
    return Dem::open(path);
}

TEST(Dem, AGridCoarserThanTheDemReadsItAveragedDown) {
    const auto f = frame();
    test::DemSpec spec;
    spec.pixel = 0.5;
    auto dem = writtenDem(tmp("fine.tif"), spec);
    ASSERT_TRUE(dem.ok()) << dem.error().message;
    // 10 DEM pixels per grid step: read averaged down (5 m blocks), then bilinear on the 5 m grid,
    // which smooths the 40 m hill's top (curvature 40 / 60² per metre) by about a decimetre.
    auto g = dem->overRegion(f, rect(-200, -150, 200, 150), 20.0, 5.0);
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_DOUBLE_EQ(g->spacingM(), 5.0);
    EXPECT_LT(maxError(*g, kTerrain), 0.2);
    // The same nodes read at the DEM's own resolution agree as closely.
    auto fine = dem->overRegion(f, rect(-200, -150, 200, 150), 20.0, 0.5);
    ASSERT_TRUE(fine.ok()) << fine.error().message;
    for (const geo::Vec2& p : {geo::Vec2(0, 0), geo::Vec2(30, -20), geo::Vec2(-150, 100), geo::Vec2(180, -130)})
        EXPECT_NEAR(*g->heightAt(p), *fine->heightAt(p), 0.15) << p.transpose();
}

// The grid GDAL's warper makes of `path` for the nodes of `g` (bilinear, 1 % of a pixel).
std::vector<float> warped(const std::string& path, const std::string& srs, const HeightGrid& g) {
    const double s = g.spacingM();
    auto fmt = [](double v) { return std::to_string(v); };
    std::vector<std::string> args = {"-of", "MEM", "-t_srs", srs, "-te", fmt(g.x0() - s / 2),
                                     fmt(g.y0() - (g.rows() - 0.5) * s), fmt(g.x0() + (g.cols() - 0.5) * s),
                                     fmt(g.y0() + s / 2), "-ts", std::to_string(g.cols()), std::to_string(g.rows()),
                                     "-r", "bilinear", "-ot", "Float32", "-dstnodata", "nan", "-et", "0.01", "-q"};
    std::vector<char*> argv;
    for (auto& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    GDALDatasetUniquePtr src(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
    GDALWarpAppOptions* opts = GDALWarpAppOptionsNew(argv.data(), nullptr);
    GDALDatasetH h = GDALDataset::ToHandle(src.get());
    GDALDatasetUniquePtr out(GDALDataset::FromHandle(GDALWarp("", nullptr, 1, &h, opts, nullptr)));
    GDALWarpAppOptionsFree(opts);
    std::vector<float> v(static_cast<std::size_t>(g.cols()) * g.rows());
    if (!out || out->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, g.cols(), g.rows(), v.data(), g.cols(), g.rows(),
                                                GDT_Float32, 0, 0, nullptr) != CE_None)
        v.clear();
    return v;
}

TEST(Dem, TheWindowReadAgreesWithGdalsWarper) {
    // A UTM and a geographic DEM, and one with a no-data hole, read into the local frame: node for
    // node as GDAL's warper.
    const auto f = frame();
    for (const std::string srs : {"EPSG:32632", "EPSG:4326", "hole"}) {
        const std::string path = tmp("agree_" + srs.substr(srs.size() - 4) + ".tif");
        test::DemSpec spec;
        spec.srs = srs == "hole" ? "EPSG:32632" : srs;
        spec.pixel = srs == "EPSG:4326" ? 2.0e-5 : 2.0;
        if (srs == "hole")
            spec.hasData = [](const geo::Vec2& p) { return (p - geo::Vec2(40, 10)).norm() > 35.0; };
        auto dem = writtenDem(path, spec);
        ASSERT_TRUE(dem.ok()) << dem.error().message;
        auto g = srs == "hole" ? dem->resample(f.projString(), -220, 170, 2.0, 221, 171)
                               : dem->overRegion(f, rect(-200, -150, 200, 150), 20.0);
        ASSERT_TRUE(g.ok()) << g.error().message;
        const std::vector<float> w = warped(path, f.projString(), *g);
        ASSERT_EQ(w.size(), static_cast<std::size_t>(g->cols()) * g->rows());
        double worst = 0.0;
        int both = 0;
        for (int r = 0; r < g->rows(); ++r)
            for (int c = 0; c < g->cols(); ++c) {
                const float a = g->node(c, r), b = w[static_cast<std::size_t>(r) * g->cols() + c];
                EXPECT_EQ(std::isnan(a), std::isnan(b)) << srs << " node " << c << ", " << r;
                if (!std::isnan(a) && !std::isnan(b)) {
                    worst = std::max(worst, static_cast<double>(std::fabs(a - b)));
                    ++both;
                }
            }
        EXPECT_GT(both, g->cols() * g->rows() / 2);
        EXPECT_LT(worst, 0.01) << srs;
    }
}

TEST(Dem, OneBandOfHeightsLooksLikeADemAPictureDoesNot) {
    const auto f = frame();
    const std::string heights = tmp("heights.tif");
    ASSERT_TRUE(writtenDem(heights, {}).ok());
    EXPECT_TRUE(Dem::looksLikeDem(heights));
    // An 8-bit georeferenced picture (a base map).
    const std::string picture = tmp("picture.tif");
    {
        GDALDatasetUniquePtr ds(
            GetGDALDriverManager()->GetDriverByName("GTiff")->Create(picture.c_str(), 16, 16, 3, GDT_Byte, nullptr));
        ASSERT_TRUE(ds);
        double gt[6] = {8.33, 1e-5, 0, 49.012, 0, -1e-5};
        ds->SetGeoTransform(gt);
        OGRSpatialReference srs;
        srs.importFromEPSG(4326);
        ds->SetSpatialRef(&srs);
    }
    EXPECT_FALSE(Dem::looksLikeDem(picture));
    // .hgt and .dem by their names (opening them says what is wrong), nothing else.
    EXPECT_TRUE(Dem::looksLikeDem(tmp("N49E008.HGT")));
    EXPECT_TRUE(Dem::looksLikeDem(tmp("site.dem")));
    EXPECT_FALSE(Dem::looksLikeDem(tmp("junk.tif"))); // not a raster
    EXPECT_FALSE(Dem::looksLikeDem(tmp("area.geojson")));
}

} // namespace
} // namespace pf::terrain
