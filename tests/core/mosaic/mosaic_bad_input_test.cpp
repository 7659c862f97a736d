// Bad photos in a set (no position, damaged, another site, not an image) are named with the reason
// and the rest is still mosaicked; against a plan, missing, extra, far-off and unplaced photos are
// listed and the parts of the area no photo covers are reported as gaps.
#include "tests/core/mosaic/mosaic_test_util.h"

#include "core/geo/polygon_ops.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

namespace pf::mosaic {
namespace {

using test::defaultOptions;
using test::demoFlight;
using test::findingFor;
using test::scratchDir;

testsim::SimOptions smallPhotos() {
    testsim::SimOptions o;
    o.camera.widthPx = 240;
    o.camera.heightPx = 180;
    return o;
}

void truncateCopy(const std::string& from, const std::string& to, double keep) {
    std::ifstream in(from, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(to, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() * keep));
}

TEST(MosaicBadInput, BadPhotosAreNamedAndTheRestIsMosaicked) {
    const auto f = demoFlight(100.0);
    PF_REQUIRE_DEMO_MAP(f);
    const std::string dir = scratchDir("bad_set");
    const testsim::SimOptions sim = smallPhotos();
    auto photos = testsim::simulateFlight(*f.ground, f.planned.photos, sim, dir + "/good");
    ASSERT_TRUE(photos.ok());
    std::vector<std::string> files = test::paths(*photos);

    // A photo without any position (no GPS, no XMP), and no plan to place it by.
    testsim::SimOptions bare = sim;
    bare.writeGps = false;
    bare.writeXmp = false;
    const auto& p10 = (*photos)[10];
    ASSERT_TRUE(
        testsim::writePhoto(*f.ground, p10.truth, p10.recorded, bare, 900, dir + "/nogps.jpg")
            .ok());
    // A truncated copy (the card was pulled while writing).
    truncateCopy((*photos)[20].path, dir + "/damaged.jpg", 0.6);
    // A photo of another site, 5 km east.
    testsim::SimPose far = p10.recorded;
    far.position.lon += 5000.0 / (111320.0 * std::cos(far.position.lat * M_PI / 180.0));
    ASSERT_TRUE(
        testsim::writePhoto(*f.ground, p10.truth, far, sim, 901, dir + "/elsewhere.jpg").ok());
    // Not an image at all.
    std::ofstream(dir + "/notes.jpg") << "flight notes: wind 4 m/s from the west\n";
    for (const char* bad : {"/nogps.jpg", "/damaged.jpg", "/elsewhere.jpg", "/notes.jpg"})
        files.push_back(dir + bad);

    MosaicOptions o = defaultOptions(files, dir + "/mosaic.tif");
    Progress progress;
    auto r = buildMosaic(o, progress);
    ASSERT_TRUE(r.ok()) << r.error().message;

    const PhotoFinding* nogps = findingFor(*r, "nogps.jpg");
    ASSERT_TRUE(nogps);
    EXPECT_TRUE(nogps->excluded);
    EXPECT_EQ(nogps->kind, PhotoFinding::Kind::NoPosition);
    EXPECT_NE(nogps->message.find("no GPS position"), std::string::npos) << nogps->message;
    const PhotoFinding* damaged = findingFor(*r, "damaged.jpg");
    ASSERT_TRUE(damaged);
    EXPECT_TRUE(damaged->excluded);
    EXPECT_EQ(damaged->kind, PhotoFinding::Kind::Unreadable);
    EXPECT_NE(damaged->message.find("damaged"), std::string::npos) << damaged->message;
    const PhotoFinding* elsewhere = findingFor(*r, "elsewhere.jpg");
    ASSERT_TRUE(elsewhere);
    EXPECT_TRUE(elsewhere->excluded);
    EXPECT_EQ(elsewhere->kind, PhotoFinding::Kind::OtherSite);
    EXPECT_NE(elsewhere->message.find("km from the other photos: a photo of another site"),
              std::string::npos)
        << elsewhere->message;
    const PhotoFinding* notes = findingFor(*r, "notes.jpg");
    ASSERT_TRUE(notes);
    EXPECT_TRUE(notes->excluded);
    EXPECT_NE(notes->message.find("not an image"), std::string::npos) << notes->message;
    int excluded = 0;
    for (const auto& fi : r->findings)
        excluded += fi.excluded ? 1 : 0;
    EXPECT_EQ(excluded, 4);

    // The good photos still make the whole mosaic, in the right place.
    EXPECT_GE(r->photosUsed, static_cast<int>(photos->size()) * 9 / 10);
    auto cmp = testsim::compareWithMap(r->outputPath, testsim::demoMapPath(), f.planned.area);
    ASSERT_TRUE(cmp.ok());
    EXPECT_LT(cmp->meanAbsError, 0.03 * 255.0);
    EXPECT_GE(cmp->coveredShare, 0.99);
    // The other site did not stretch the mosaic over 5 km.
    EXPECT_LT(r->widthPx * r->gsdM, 1000.0);
}

TEST(MosaicBadInput, NothingUsableIsAnErrorThatSaysWhy) {
    const auto f = demoFlight(100.0);
    PF_REQUIRE_DEMO_MAP(f);
    const std::string dir = scratchDir("nothing_usable");
    testsim::SimOptions bare = smallPhotos();
    bare.writeGps = false;
    bare.writeXmp = false;
    std::vector<std::string> files;
    for (int i = 0; i < 3; ++i) {
        const auto& p = f.planned.photos[i];
        testsim::SimPose pose{p.position, p.altitudeM, p.headingDeg};
        files.push_back(dir + "/p" + std::to_string(i) + ".jpg");
        ASSERT_TRUE(testsim::writePhoto(*f.ground, pose, pose, bare, i, files.back()).ok());
    }
    Progress progress;
    auto r = buildMosaic(defaultOptions(files, dir + "/mosaic.tif"), progress);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(r.error().message.find("none of the 3 photo(s) can be placed"), std::string::npos)
        << r.error().message;
    EXPECT_NE(r.error().message.find("p0.jpg: no GPS position"), std::string::npos)
        << r.error().message;
    EXPECT_FALSE(std::filesystem::exists(dir + "/mosaic.tif"));
}

TEST(MosaicBadInput, PlanListsMissingExtraFarAndPlacesUnpositionedPhotos) {
    const auto f = demoFlight(100.0);
    PF_REQUIRE_DEMO_MAP(f);
    const std::string dir = scratchDir("plan_match");
    const testsim::SimOptions sim = smallPhotos();
    auto photos = testsim::simulateFlight(*f.ground, f.planned.photos, sim, dir + "/photos");
    ASSERT_TRUE(photos.ok());
    ASSERT_GT(photos->size(), 60u);

    // Photos 5, 6 and 50 were never taken; 20 has no GPS (placed between its neighbours); 30 was
    // recorded 30 m off its point; 40 was taken twice.
    std::vector<std::string> files;
    const std::set<std::size_t> skipped{5, 6, 50};
    for (std::size_t i = 0; i < photos->size(); ++i)
        if (!skipped.count(i) && i != 20 && i != 30)
            files.push_back((*photos)[i].path);
    testsim::SimOptions bare = sim;
    bare.writeGps = false;
    bare.writeXmp = false;
    const auto& p20 = (*photos)[20];
    ASSERT_TRUE(testsim::writePhoto(*f.ground, p20.truth, p20.recorded, bare, 20,
                                    dir + "/photos/IMG_0021.JPG")
                    .ok());
    files.push_back(dir + "/photos/IMG_0021.JPG");
    // 30 m in the direction that takes it furthest from every planned point.
    const auto& p30 = (*photos)[30];
    const geo::LocalFrame& frame = f.ground->frame();
    testsim::SimPose off = p30.recorded;
    double offDistance = 0;
    for (int k = 0; k < 16; ++k) {
        const geo::Vec2 at = frame.toLocal(p30.recorded.position) +
                             30.0 * geo::Vec2(std::cos(k * M_PI / 8), std::sin(k * M_PI / 8));
        double nearest = 1e300;
        for (const auto& q : f.planned.photos)
            nearest = std::min(nearest, (frame.toLocal(q.position) - at).norm());
        if (nearest > offDistance) {
            offDistance = nearest;
            off.position = frame.toGeo(at);
        }
    }
    ASSERT_GT(offDistance, 15.0);
    ASSERT_TRUE(
        testsim::writePhoto(*f.ground, p30.truth, off, sim, 30, dir + "/photos/IMG_0031.JPG").ok());
    files.push_back(dir + "/photos/IMG_0031.JPG");
    const auto& p40 = (*photos)[40];
    ASSERT_TRUE(testsim::writePhoto(*f.ground, p40.truth, p40.recorded, sim, 40,
                                    dir + "/photos/IMG_0041b.JPG")
                    .ok());
    files.push_back(dir + "/photos/IMG_0041b.JPG");

    MosaicOptions o = defaultOptions(files, dir + "/mosaic.tif");
    o.plan = f.planned;
    Progress progress;
    auto r = buildMosaic(o, progress);
    ASSERT_TRUE(r.ok()) << r.error().message;

    std::set<std::string> missing;
    for (const auto& m : r->missing)
        missing.insert(m.label);
    // Point 31 has the far photo nowhere near it, so it is missing as well.
    const std::string a = f.planned.photos[0].aircraft;
    EXPECT_EQ(missing, (std::set<std::string>{a + " #6", a + " #7", a + " #51", a + " #31"}));

    bool placed = false;
    for (const auto& p : r->photos)
        if (p.file == "IMG_0021.JPG") {
            placed = true;
            EXPECT_EQ(p.planned, a + " #21");
            EXPECT_NE(p.poseFrom.find("capture order"), std::string::npos) << p.poseFrom;
        }
    EXPECT_TRUE(placed);
    const PhotoFinding* farOff = findingFor(*r, "IMG_0031.JPG");
    ASSERT_TRUE(farOff);
    EXPECT_EQ(farOff->kind, PhotoFinding::Kind::FarFromPlan);
    EXPECT_FALSE(farOff->excluded);
    char expected[64];
    std::snprintf(expected, sizeof expected, "%.1f m from the nearest planned point", offDistance);
    EXPECT_NE(farOff->message.find(expected), std::string::npos) << farOff->message;
    const PhotoFinding* twice = findingFor(*r, "IMG_0041b.JPG");
    if (!twice)
        twice = findingFor(*r, "IMG_0041.JPG");
    ASSERT_TRUE(twice);
    EXPECT_EQ(twice->kind, PhotoFinding::Kind::Duplicate);
    EXPECT_NE(twice->message.find("a second photo at planned point " + a + " #41"),
              std::string::npos)
        << twice->message;
}

TEST(MosaicBadInput, GapsInTheAreaAreReportedByArea) {
    const auto f = demoFlight(100.0);
    PF_REQUIRE_DEMO_MAP(f);
    const std::string dir = scratchDir("gaps");
    const testsim::SimOptions sim = smallPhotos();
    // Leave out every photo taken within 70 m of a point inside the area: its ground is unseen.
    const geo::LocalFrame& frame = f.ground->frame();
    geo::Polygon area;
    for (const auto& p : f.planned.area.front().outer)
        area.outer.push_back(frame.toLocal(p));
    const geo::Box box = geo::bounds(area);
    const geo::Vec2 hole = 0.5 * (box.min + box.max) + geo::Vec2(-40, -30);
    ASSERT_TRUE(geo::contains(area, hole));
    std::vector<PlannedPhoto> kept;
    for (const auto& p : f.planned.photos)
        if ((frame.toLocal(p.position) - hole).norm() > 70.0)
            kept.push_back(p);
    ASSERT_LT(kept.size(), f.planned.photos.size());
    auto photos = testsim::simulateFlight(*f.ground, kept, sim, dir + "/photos");
    ASSERT_TRUE(photos.ok());

    MosaicOptions o = defaultOptions(test::paths(*photos), dir + "/mosaic.tif");
    o.plan = f.planned;
    Progress progress;
    auto r = buildMosaic(o, progress);
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_FALSE(r->gaps.empty());
    // The largest gap lies around the hole, and the areas agree with an independent count.
    const geo::Vec2 c = frame.toLocal(r->gaps.front().centre);
    EXPECT_LT((c - hole).norm(), 25.0);
    EXPECT_EQ(r->missing.size(), f.planned.photos.size() - kept.size());
    auto cmp = testsim::compareWithMap(r->outputPath, testsim::demoMapPath(), f.planned.area);
    ASSERT_TRUE(cmp.ok());
    const double uncovered = (1.0 - cmp->coveredShare) * r->areaM2;
    EXPECT_GT(uncovered, 100.0);
    EXPECT_NEAR(r->gapAreaM2, uncovered, 0.1 * uncovered + 5.0);
    EXPECT_NEAR(r->coveredRatio, cmp->coveredShare, 0.002);
    // The gaps layer holds them.
    GDALDatasetUniquePtr v(GDALDataset::Open(r->vectorPath.c_str(), GDAL_OF_VECTOR));
    ASSERT_TRUE(v);
    EXPECT_EQ(v->GetLayerByName("gaps")->GetFeatureCount(), static_cast<GIntBig>(r->gaps.size()));

    // A dozen photos cover a corner: most of the area lies outside the mosaic itself, and still
    // counts as uncovered.
    o.photos.resize(12);
    o.outputPath = dir + "/corner.tif";
    auto corner = buildMosaic(o, progress);
    ASSERT_TRUE(corner.ok()) << corner.error().message;
    auto cornerCmp =
        testsim::compareWithMap(corner->outputPath, testsim::demoMapPath(), f.planned.area);
    ASSERT_TRUE(cornerCmp.ok());
    EXPECT_LT(corner->coveredRatio, 0.5);
    EXPECT_NEAR(corner->coveredRatio, cornerCmp->coveredShare, 0.01);
    EXPECT_NEAR(corner->gapAreaM2, (1.0 - corner->coveredRatio) * corner->areaM2,
                0.01 * corner->areaM2);
}

TEST(MosaicBadInput, CancelLeavesNoFileBehind) {
    const auto f = demoFlight(100.0);
    PF_REQUIRE_DEMO_MAP(f);
    const std::string dir = scratchDir("cancel");
    std::vector<PlannedPhoto> some(f.planned.photos.begin(), f.planned.photos.begin() + 20);
    auto photos = testsim::simulateFlight(*f.ground, some, smallPhotos(), dir + "/photos");
    ASSERT_TRUE(photos.ok());
    const std::string out = dir + "/out";
    std::filesystem::create_directories(out);
    Progress* self = nullptr;
    std::vector<std::string> stages;
    Progress progress([&](double, const std::string& stage) {
        if (stages.empty() || stages.back() != stage)
            stages.push_back(stage);
        if (stage == "warping photos")
            self->cancel();
    });
    self = &progress;
    auto r = buildMosaic(defaultOptions(test::paths(*photos), out + "/mosaic.tif"), progress);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Cancelled);
    EXPECT_TRUE(std::filesystem::is_empty(out)) << "scratch or output files left in " << out;
    EXPECT_EQ(stages,
              (std::vector<std::string>{"reading photos", "drawing seams", "warping photos"}));
}

} // namespace
} // namespace pf::mosaic
