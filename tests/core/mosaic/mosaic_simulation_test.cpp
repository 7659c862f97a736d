// The mosaic of a simulated flight over the demo map, against the map itself: with exact poses it
// reproduces the map; with pose noise the error grows as far as the misplacement of the photos says.
#include "tests/core/mosaic/mosaic_test_util.h"

#include "core/mosaic/camera_model.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
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

struct Built {
    std::vector<testsim::SimulatedPhoto> photos;
    MosaicReport report;
    testsim::Comparison cmp;
    std::string out;
};

Built buildSimulated(const test::DemoFlight& f, const testsim::SimOptions& sim, const std::string& name) {
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
    // PF_MOSAIC_TEST_KEEP=DIR keeps a copy of each mosaic (the README's pictures are made from them).
    if (const char* keep = std::getenv("PF_MOSAIC_TEST_KEEP")) {
        std::filesystem::create_directories(keep);
        std::filesystem::copy_file(b.out, std::filesystem::path(keep) / (name + ".tif"),
                                   std::filesystem::copy_options::overwrite_existing);
        std::filesystem::copy_file(b.report.vectorPath, std::filesystem::path(keep) / (name + ".gpkg"),
                                   std::filesystem::copy_options::overwrite_existing);
    }
    // PF_MOSAIC_TEST_KEEP=DIR keeps a copy of each mosaic (the README's pictures are made from them).
    if (const char* keep = std::getenv("PF_MOSAIC_TEST_KEEP")) {
        std::filesystem::create_directories(keep);
        std::filesystem::copy_file(b.out, std::filesystem::path(keep) / (name + ".tif"),
                                   std::filesystem::copy_options::overwrite_existing);
        std::filesystem::copy_file(b.report.vectorPath, std::filesystem::path(keep) / (name + ".gpkg"),
                                   std::filesystem::copy_options::overwrite_existing);
    }
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
    std::cout << "exact poses: " << b.photos.size() << " photos, MAE " << b.cmp.meanAbsError << " levels ("
              << 100.0 * b.cmp.meanAbsError / 255.0 << " % of the range), covered " << 100.0 * b.cmp.coveredShare
              << " %, GSD " << b.report.gsdM << " m\n";
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
    EXPECT_EQ(v->GetLayerByName("footprints")->GetFeatureCount(), static_cast<GIntBig>(b.photos.size()));
    EXPECT_GE(v->GetLayerByName("seams")->GetFeatureCount(), static_cast<GIntBig>(b.report.photosUsed));
    EXPECT_EQ(v->GetLayerByName("gaps")->GetFeatureCount(), 0);
    EXPECT_EQ(v->GetLayerByName("missing_photos")->GetFeatureCount(), 0);
    EXPECT_EQ(v->GetLayerByName("camera_positions")->GetFeatureCount(), static_cast<GIntBig>(b.photos.size()));
}

// Where the ground seen at a photo's centre ends up when the mosaic believes the recorded pose
// instead of the true one.
double centreDisplacementM(const testsim::SimulatedPhoto& p, const testsim::SimOptions& sim, const geo::LocalFrame& frame) {
    CameraIntrinsics in{sim.camera.widthPx, sim.camera.heightPx, sim.camera.longSideFovDeg, sim.camera.shortSideFovDeg, 1};
    auto model = [&](const testsim::SimPose& s) {
        const geo::Vec2 xy = frame.toLocal(s.position);
        return CameraModel(in, CameraPose{Vec3(xy.x(), xy.y(), s.altitudeM), s.yawDeg, s.pitchDeg, s.rollDeg});
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
double shiftedMapError(const testsim::GroundImage& g, const std::vector<geo::GeoPolygon>& area, double d) {
    std::mt19937 rng(99);
    geo::Box box{{1e300, 1e300}, {-1e300, -1e300}};
    geo::Polygon poly;
    for (const auto& p : area.front().outer)
        poly.outer.push_back(g.frame().toLocal(p));
    box = geo::bounds(poly);
    std::uniform_real_distribution<double> ux(box.min.x(), box.max.x()), uy(box.min.y(), box.max.y()), ua(0, 2 * M_PI);
    double sum = 0;
    int n = 0;
    while (n < 20000) {
        const geo::Vec2 p(ux(rng), uy(rng));
        if (!geo::contains(poly, p))
            continue;
        const double a = ua(rng);
        std::uint8_t c0[3], c1[3];
        if (!g.sample(p.x(), p.y(), c0) || !g.sample(p.x() + d * std::cos(a), p.y() + d * std::sin(a), c1))
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
    std::cout << "2 m / 2 deg noise: photos misplaced by " << displacement << " m on average; MAE " << b.cmp.meanAbsError
              << " levels (" << 100.0 * b.cmp.meanAbsError / 255.0 << " %), exact poses " << a.cmp.meanAbsError
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

} // namespace
} // namespace pf::mosaic
