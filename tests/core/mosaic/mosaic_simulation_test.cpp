// The mosaic of a simulated flight over the demo map, against the map itself: with exact poses it
// reproduces the map; with pose noise the error grows as far as the misplacement of the photos
// says.
#include "tests/core/mosaic/mosaic_test_util.h"

#include "core/mosaic/camera_model.h"
#include "core/mosaic/utm_projection.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <random>

namespace pf::mosaic {
namespace {

using test::defaultOptions;
using test::demoFlight;
using test::scratchDir;

constexpr double kAltitude = 100.0; // 480 x 360 photos: 25 cm per pixel, as fine as the demo map

// PF_MOSAIC_TEST_KEEP=DIR keeps a copy of each mosaic and its vectors (docs/mosaic.md's pictures
// are made from them).
void keepCopy(const std::string& mosaic, const std::string& name) {
    const char* keep = std::getenv("PF_MOSAIC_TEST_KEEP");
    if (!keep)
        return;
    std::filesystem::create_directories(keep);
    for (const char* ext : {".tif", ".gpkg"})
        std::filesystem::copy_file(std::filesystem::path(mosaic).replace_extension(ext),
                                   std::filesystem::path(keep) / (name + ext),
                                   std::filesystem::copy_options::overwrite_existing);
}

struct Built {
    std::vector<testsim::SimulatedPhoto> photos;
    MosaicReport report;
    testsim::Comparison cmp;
    std::string out;
};

Built buildSimulated(const test::DemoFlight& f, const testsim::SimOptions& sim,
                     const std::string& name) {
    Built b;
    const std::string dir = scratchDir(name);
    auto photos = testsim::simulateFlight(*f.ground, f.planned.photos, sim, dir + "/photos");
    EXPECT_TRUE(photos.ok()) << (photos ? "" : photos.error().message);
    if (!photos)
        return b;
    b.photos = *photos;
    b.out = dir + "/mosaic.tif";
    MosaicOptions o = defaultOptions(test::paths(b.photos), b.out);
    o.plan = f.planned;
    Progress progress;
    auto r = buildMosaic(o, progress);
    EXPECT_TRUE(r.ok()) << (r ? "" : r.error().message);
    if (!r)
        return b;
    b.report = *r;
    keepCopy(b.out, name);
    keepCopy(b.out, name);
    auto cmp = testsim::compareWithMap(b.out, testsim::demoMapPath(), f.planned.area);
    EXPECT_TRUE(cmp.ok());
    if (cmp)
        b.cmp = *cmp;
    return b;
}

// With exact poses the mosaic is the map, resampled twice (into the photos, back onto the grid)
// and JPEG-compressed twice.
void expectExactMosaic(const Built& b) {
    ASSERT_FALSE(b.out.empty());
    std::cout << "exact poses: " << b.photos.size() << " photos, MAE " << b.cmp.meanAbsError
              << " levels (" << 100.0 * b.cmp.meanAbsError / 255.0 << " % of the range), covered "
              << 100.0 * b.cmp.coveredShare << " %, GSD " << b.report.gsdM << " m\n";
    EXPECT_LT(b.cmp.meanAbsError, 0.03 * 255.0);
    EXPECT_GE(b.cmp.coveredShare, 0.99);
    EXPECT_GT(b.cmp.comparedPixels, 100000);
    // The core's own coverage figure agrees with the independent one, and there is no gap.
    EXPECT_NEAR(b.report.coveredRatio, b.cmp.coveredShare, 0.005);
    EXPECT_TRUE(b.report.gaps.empty());
    EXPECT_GT(b.report.areaM2, 80000.0);
    // Every photo matched its planned point and none is missing.
    EXPECT_TRUE(b.report.missing.empty());
    for (const auto& p : b.report.photos) {
        EXPECT_FALSE(p.planned.empty()) << p.file;
        EXPECT_LT(p.planOffsetM, 0.05) << p.file;
    }
    for (const auto& fi : b.report.findings)
        EXPECT_FALSE(fi.excluded) << fi.file << ": " << fi.message;
    EXPECT_EQ(b.report.epsg, 32632);
    EXPECT_NEAR(b.report.gsdM, 0.25, 0.01);

    // A tiled GeoTIFF in the cloud-optimised layout, with overviews and a transparency mask.
    GDALDatasetUniquePtr ds(GDALDataset::Open(b.out.c_str(), GDAL_OF_RASTER));
    ASSERT_TRUE(ds);
    EXPECT_STREQ(ds->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE"), "COG");
    int bx = 0, by = 0;
    ds->GetRasterBand(1)->GetBlockSize(&bx, &by);
    EXPECT_EQ(bx, 512);
    EXPECT_EQ(by, 512);
    EXPECT_GE(ds->GetRasterBand(1)->GetOverviewCount(), 1);
    EXPECT_EQ(ds->GetRasterBand(1)->GetMaskFlags(), GMF_PER_DATASET);
    EXPECT_EQ(ds->GetRasterBand(1)->GetRasterDataType(), GDT_Byte);
    EXPECT_EQ(ds->GetRasterCount(), 3);

    // The vector layers: one footprint and one seam per photo, no gap.
    GDALDatasetUniquePtr v(GDALDataset::Open(b.report.vectorPath.c_str(), GDAL_OF_VECTOR));
    ASSERT_TRUE(v);
    ASSERT_TRUE(v->GetLayerByName("footprints"));
    EXPECT_EQ(v->GetLayerByName("footprints")->GetFeatureCount(),
              static_cast<GIntBig>(b.photos.size()));
    EXPECT_GE(v->GetLayerByName("seams")->GetFeatureCount(),
              static_cast<GIntBig>(b.report.photosUsed));
    EXPECT_EQ(v->GetLayerByName("gaps")->GetFeatureCount(), 0);
    EXPECT_EQ(v->GetLayerByName("missing_photos")->GetFeatureCount(), 0);
    EXPECT_EQ(v->GetLayerByName("camera_positions")->GetFeatureCount(),
              static_cast<GIntBig>(b.photos.size()));
}

// Where the ground seen at a photo's centre ends up when the mosaic believes the recorded pose
// instead of the true one.
double centreDisplacementM(const testsim::SimulatedPhoto& p, const testsim::SimOptions& sim,
                           const geo::LocalFrame& frame) {
    CameraIntrinsics in{sim.camera.widthPx, sim.camera.heightPx, sim.camera.longSideFovDeg,
                        sim.camera.shortSideFovDeg, 1};
    auto model = [&](const testsim::SimPose& s) {
        const geo::Vec2 xy = frame.toLocal(s.position);
        return CameraModel(
            in, CameraPose{Vec3(xy.x(), xy.y(), s.altitudeM), s.yawDeg, s.pitchDeg, s.rollDeg});
    };
    const CameraModel truth = model(p.truth), recorded = model(p.recorded);
    double sum = 0;
    int n = 0;
    // A few pixels around the centre: the part of a photo the seams keep.
    for (double fx : {0.35, 0.5, 0.65})
        for (double fy : {0.35, 0.5, 0.65}) {
            const double col = fx * in.widthPx, row = fy * in.heightPx;
            const Vec3 dt = truth.ray(col, row), dr = recorded.ray(col, row);
            const Vec3 gt = truth.centre() + (-truth.centre().z() / dt.z()) * dt;
            const Vec3 gr = recorded.centre() + (-recorded.centre().z() / dr.z()) * dr;
            sum += (gt - gr).head<2>().norm();
            ++n;
        }
    return sum / n;
}

// The map's own error when it is misplaced by `d` metres in a random direction.
double shiftedMapError(const testsim::GroundImage& g, const std::vector<geo::GeoPolygon>& area,
                       double d) {
    std::mt19937 rng(99);
    geo::Box box{{1e300, 1e300}, {-1e300, -1e300}};
    geo::Polygon poly;
    for (const auto& p : area.front().outer)
        poly.outer.push_back(g.frame().toLocal(p));
    box = geo::bounds(poly);
    std::uniform_real_distribution<double> ux(box.min.x(), box.max.x()),
        uy(box.min.y(), box.max.y()), ua(0, 2 * M_PI);
    double sum = 0;
    int n = 0;
    while (n < 20000) {
        const geo::Vec2 p(ux(rng), uy(rng));
        if (!geo::contains(poly, p))
            continue;
        const double a = ua(rng);
        std::uint8_t c0[3], c1[3];
        if (!g.sample(p.x(), p.y(), c0) ||
            !g.sample(p.x() + d * std::cos(a), p.y() + d * std::sin(a), c1))
            continue;
        for (int k = 0; k < 3; ++k)
            sum += std::abs(int(c0[k]) - int(c1[k]));
        ++n;
    }
    return sum / (3.0 * n);
}

// One test for both flights (rendering the photos is most of the cost): the exact one is the
// reference the noisy one is measured against.
TEST(MosaicSimulation, ExactPosesReproduceTheMapAndPoseNoiseGrowsTheErrorAsExpected) {
    const auto f = demoFlight(kAltitude);
    PF_REQUIRE_DEMO_MAP(f);
    testsim::SimOptions exact;
    testsim::SimOptions noisy;
    noisy.positionNoiseM = 2.0;
    noisy.angleNoiseDeg = 2.0;
    noisy.seed = 7;
    const Built a = buildSimulated(f, exact, "sim_exact");
    {
        SCOPED_TRACE("exact poses");
        expectExactMosaic(a);
    }
    const Built b = buildSimulated(f, noisy, "sim_noisy");
    ASSERT_FALSE(a.out.empty());
    ASSERT_FALSE(b.out.empty());
    SCOPED_TRACE("2 m / 2 degrees of pose noise");

    double displacement = 0;
    for (const auto& p : b.photos)
        displacement += centreDisplacementM(p, noisy, f.ground->frame());
    displacement /= b.photos.size();
    const double expected = shiftedMapError(*f.ground, f.planned.area, displacement);
    std::cout << "2 m / 2 deg noise: photos misplaced by " << displacement << " m on average; MAE "
              << b.cmp.meanAbsError << " levels (" << 100.0 * b.cmp.meanAbsError / 255.0
              << " %), exact poses " << a.cmp.meanAbsError
              << "; the map shifted by that distance differs by " << expected << " levels; covered "
              << 100.0 * b.cmp.coveredShare << " %\n";
    // The photos land metres off, more than the GSD: the error must grow clearly...
    EXPECT_GT(displacement, 2.0);
    EXPECT_GT(b.cmp.meanAbsError, a.cmp.meanAbsError + 0.3 * (expected - a.cmp.meanAbsError));
    // ...and by about what a map misplaced by that much differs from itself (the photos are
    // misplaced by different amounts in different directions, so this is a range, not a value).
    EXPECT_GT(b.cmp.meanAbsError, 0.5 * expected);
    EXPECT_LT(b.cmp.meanAbsError, 1.5 * expected);
    // The overlaps absorb a few metres: the area stays covered.
    EXPECT_GE(b.cmp.coveredShare, 0.98);
    // Recorded within the tolerance of their planned points (2 m noise), all photos still match.
    EXPECT_TRUE(b.report.missing.empty());
}

// Heights on a lattice in the mosaic's grid, bilinear in between: how a terrain model plugs in.
class LatticeGround : public GroundModel {
public:
    LatticeGround(double x0, double y0, double step, int nx, int ny, std::vector<double> h)
        : m_x0(x0), m_y0(y0), m_step(step), m_nx(nx), m_ny(ny), m_h(std::move(h)) {}
    double heightAt(double x, double y) const override {
        const double u = std::clamp((x - m_x0) / m_step, 0.0, m_nx - 1.001);
        const double v = std::clamp((y - m_y0) / m_step, 0.0, m_ny - 1.001);
        const int i = static_cast<int>(u), j = static_cast<int>(v);
        const double fu = u - i, fv = v - j;
        auto at = [&](int a, int b) { return m_h[static_cast<std::size_t>(b) * m_nx + a]; };
        return (at(i, j) * (1 - fu) + at(i + 1, j) * fu) * (1 - fv) +
               (at(i, j + 1) * (1 - fu) + at(i + 1, j + 1) * fu) * fv;
    }

private:
    double m_x0, m_y0, m_step;
    int m_nx, m_ny;
    std::vector<double> m_h;
};

TEST(MosaicSimulation, TerrainModelPutsPhotosOfASlopeInPlace) {
    const auto f = demoFlight(kAltitude);
    PF_REQUIRE_DEMO_MAP(f);
    // The site on a 15 % slope rising to the north with a 30 m hill in the middle: over flat ground
    // the photos' edges land metres from where they belong.
    auto slope = [](double x, double y) {
        return 0.15 * y + 30.0 * std::exp(-(x * x + y * y) / (2 * 60.0 * 60.0));
    };
    testsim::SimOptions sim;
    sim.camera.widthPx = 160;
    sim.camera.heightPx = 120;
    sim.terrain = slope;
    const std::string dir = scratchDir("terrain");
    auto photos = testsim::simulateFlight(*f.ground, f.planned.photos, sim, dir + "/photos");
    ASSERT_TRUE(photos.ok());

    // The same slope as a ground model in the mosaic's UTM grid.
    geo::Box box = geo::bounds(f.ground->frame().toLocal(f.planned.area.front()));
    const geo::LonLat site = f.ground->frame().toGeo(0.5 * (box.min + box.max));
    auto utm = UtmProjection::forSite(site);
    ASSERT_TRUE(utm.ok());
    const geo::Vec2 c = utm->toGrid(site);
    const double step = 5.0;
    const int nx = 161, ny = 141;
    std::vector<double> h;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const geo::Vec2 local = f.ground->frame().toLocal(
                utm->toGeo({c.x() - 400.0 + i * step, c.y() - 350.0 + j * step}));
            h.push_back(slope(local.x(), local.y()));
        }
    auto ground = std::make_shared<LatticeGround>(c.x() - 400.0, c.y() - 350.0, step, nx, ny, h);

    auto build = [&](std::shared_ptr<const GroundModel> g, const std::string& name) {
        MosaicOptions o = defaultOptions(test::paths(*photos), dir + "/" + name + ".tif");
        o.plan = f.planned;
        o.ground = std::move(g);
        Progress progress;
        auto r = buildMosaic(o, progress);
        EXPECT_TRUE(r.ok()) << (r ? "" : r.error().message);
        keepCopy(dir + "/" + name + ".tif", "slope_" + name);
        auto cmp = testsim::compareWithMap(dir + "/" + name + ".tif", testsim::demoMapPath(),
                                           f.planned.area);
        EXPECT_TRUE(cmp.ok());
        return cmp ? *cmp : testsim::Comparison{};
    };
    const auto onTerrain = build(ground, "terrain");
    const auto onFlat = build(nullptr, "flat");
    std::cout << "15 % slope and a 30 m hill: MAE " << onTerrain.meanAbsError
              << " levels with the terrain model, " << onFlat.meanAbsError << " on flat ground\n";
    EXPECT_LT(onTerrain.meanAbsError, 0.03 * 255.0);
    EXPECT_GE(onTerrain.coveredShare, 0.99);
    EXPECT_GT(onFlat.meanAbsError, 1.5 * onTerrain.meanAbsError);
}

// Mean signed difference and the share of pixels differing by 3 levels or more, between two mosaics
// on the same grid (valid in both).
std::pair<double, double> differences(const std::string& a, const std::string& b) {
    GDALDatasetUniquePtr da(GDALDataset::Open(a.c_str(), GDAL_OF_RASTER));
    GDALDatasetUniquePtr db(GDALDataset::Open(b.c_str(), GDAL_OF_RASTER));
    EXPECT_TRUE(da && db);
    if (!da || !db)
        return {0, 0};
    const int w = da->GetRasterXSize(), h = da->GetRasterYSize();
    EXPECT_EQ(w, db->GetRasterXSize());
    EXPECT_EQ(h, db->GetRasterYSize());
    std::vector<std::uint8_t> pa(std::size_t(w) * h * 3), pb(pa.size()), ma(std::size_t(w) * h),
        mb(ma.size());
    EXPECT_EQ(da->RasterIO(GF_Read, 0, 0, w, h, pa.data(), w, h, GDT_Byte, 3, nullptr, 3, 3 * w, 1,
                           nullptr),
              CE_None);
    EXPECT_EQ(db->RasterIO(GF_Read, 0, 0, w, h, pb.data(), w, h, GDT_Byte, 3, nullptr, 3, 3 * w, 1,
                           nullptr),
              CE_None);
    EXPECT_EQ(da->GetRasterBand(1)->GetMaskBand()->RasterIO(GF_Read, 0, 0, w, h, ma.data(), w, h,
                                                            GDT_Byte, 0, 0, nullptr),
              CE_None);
    EXPECT_EQ(db->GetRasterBand(1)->GetMaskBand()->RasterIO(GF_Read, 0, 0, w, h, mb.data(), w, h,
                                                            GDT_Byte, 0, 0, nullptr),
              CE_None);
    double sum = 0;
    long long n = 0, differ = 0;
    for (std::size_t i = 0; i < ma.size(); ++i) {
        if (ma[i] < 128 || mb[i] < 128)
            continue;
        int d = 0;
        for (int k = 0; k < 3; ++k) {
            const int dk = int(pa[i * 3 + k]) - int(pb[i * 3 + k]);
            sum += dk;
            d = std::max(d, std::abs(dk));
        }
        ++n;
        differ += d >= 3 ? 1 : 0;
    }
    return {n ? sum / (3.0 * n) : 0.0, n ? double(differ) / n : 0.0};
}

TEST(MosaicSimulation, FeatheringBlendsAcrossSeamsWithoutShiftingTheColours) {
    const auto f = demoFlight(kAltitude);
    PF_REQUIRE_DEMO_MAP(f);
    // Misplaced photos (2 m / 2 degrees) so that neighbours disagree at every seam.
    testsim::SimOptions sim;
    sim.camera.widthPx = 240;
    sim.camera.heightPx = 180;
    sim.positionNoiseM = 2.0;
    sim.angleNoiseDeg = 2.0;
    sim.seed = 11;
    const std::string dir = scratchDir("feather");
    auto photos = testsim::simulateFlight(*f.ground, f.planned.photos, sim, dir + "/photos");
    ASSERT_TRUE(photos.ok());
    auto build = [&](double feather, const std::string& name) {
        MosaicOptions o = defaultOptions(test::paths(*photos), dir + "/" + name + ".tif");
        o.plan = f.planned;
        o.featherM = feather;
        Progress progress;
        auto r = buildMosaic(o, progress);
        EXPECT_TRUE(r.ok()) << (r ? "" : r.error().message);
        keepCopy(dir + "/" + name + ".tif", "feather_" + name);
        auto cmp = testsim::compareWithMap(dir + "/" + name + ".tif", testsim::demoMapPath(),
                                           f.planned.area);
        EXPECT_TRUE(cmp.ok());
        return cmp ? *cmp : testsim::Comparison{};
    };
    const auto hard = build(0.0, "hard");
    const auto soft = build(6.0, "soft");
    const auto [meanDiff, changed] = differences(dir + "/soft.tif", dir + "/hard.tif");
    std::cout << "feathering 6 m: MAE " << soft.meanAbsError << " levels (sharp seams "
              << hard.meanAbsError << "), " << 100 * changed
              << " % of the pixels changed, mean shift " << meanDiff << " levels\n";
    // The blend bands change a clear share of the mosaic, but not most of it...
    EXPECT_GT(changed, 0.02);
    EXPECT_LT(changed, 0.6);
    // ...the weights of each pixel sum to one, so the colours do not drift...
    EXPECT_LT(std::abs(meanDiff), 0.3);
    // ...and averaging two misplaced photos is no worse than cutting between them.
    EXPECT_LT(soft.meanAbsError, hard.meanAbsError * 1.05);
    EXPECT_GE(soft.coveredShare, 0.98);
}

} // namespace
} // namespace pf::mosaic
