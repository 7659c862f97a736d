// photoflight-cli mosaic: the real executable on simulated photos: exit codes 0/2, the report on
// stdout, left-out photos named on stderr, and the options' errors.
#include "core/mission/plan_geojson.h"
#include "tests/core/cli/cli_test_util.h"
#include "tests/core/mosaic/mosaic_test_util.h"

#include <filesystem>
#include <fstream>

namespace pf::mosaic {
namespace {

using pf::cli::test::cli;
using pf::cli::test::CliRun;
using pf::cli::test::expectBadInput;
using pf::cli::test::has;

// A dozen small photos of the demo flight, a damaged one, and the plan as `photoflight-cli plan`
// writes it.
struct CliSet {
    std::string dir;
    std::string photos;
    std::string plan;
};

CliSet makeSet(const test::DemoFlight& f, const std::string& name) {
    CliSet s;
    s.dir = test::scratchDir(name);
    s.photos = s.dir + "/card";
    testsim::SimOptions o;
    o.camera.widthPx = 160;
    o.camera.heightPx = 120;
    std::vector<PlannedPhoto> some(f.planned.photos.begin(), f.planned.photos.begin() + 12);
    auto photos = testsim::simulateFlight(*f.ground, some, o, s.photos);
    EXPECT_TRUE(photos.ok());
    std::ofstream(s.photos + "/IMG_9999.JPG") << "\xFF\xD8\xFF\xE0 truncated";
    s.plan = s.dir + "/plan";
    std::filesystem::create_directories(s.plan);
    std::ofstream(s.plan + "/plan.geojson") << mission::planToGeoJson(f.plan);
    return s;
}

TEST(MosaicCli, MosaicsADirectoryAndNamesTheBadPhoto) {
    const auto f = test::demoFlight(100.0);
    PF_REQUIRE_DEMO_MAP(f);
    const CliSet s = makeSet(f, "cli_good");
    const CliRun r = cli("mosaic '" + s.photos + "' --plan '" + s.plan + "' --out '" + s.dir +
                         "/site.tif' --quiet");
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "photos used, 1 left out")) << r.out;
    EXPECT_TRUE(has(r.out, "UTM zone 32N (EPSG:32632), 75.0 cm/px")) << r.out;
    EXPECT_TRUE(has(r.out, "Left out:\n  IMG_9999.JPG: ")) << r.out;
    EXPECT_TRUE(has(r.err, "photoflight-cli: warning: IMG_9999.JPG: ")) << r.err;
    // Twelve of the plan's photos: the rest of the planned points are missing and the area has
    // gaps.
    EXPECT_TRUE(has(r.out, "Missing: " + std::to_string(f.planned.photos.size() - 12) +
                               " planned photo point(s)"))
        << r.out;
    EXPECT_TRUE(has(r.out, "  Falcon 8 #13-#" + std::to_string(f.planned.photos.size()) + "\n"))
        << r.out;
    EXPECT_TRUE(has(r.out, "Coverage of the planned area: ")) << r.out;
    EXPECT_TRUE(has(r.out, "gap 1: ")) << r.out;
    EXPECT_TRUE(has(r.out, "camera: Falcon 8 camera (12 photo(s))")) << r.out;
    EXPECT_FALSE(has(r.err, "mosaic: warping")) << "--quiet prints no progress";
    EXPECT_TRUE(std::filesystem::exists(s.dir + "/site.tif"));
    EXPECT_TRUE(std::filesystem::exists(s.dir + "/site.gpkg"));
    // Nothing but the two outputs beside them.
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(s.dir))
        files += e.is_regular_file() ? 1 : 0;
    EXPECT_EQ(files, 2);

    // Progress goes to stderr when not quiet; --gsd and --vectors are obeyed.
    const CliRun g = cli("mosaic '" + s.photos + "' --gsd 150 --vectors '" + s.dir +
                         "/fp.gpkg' --out '" + s.dir + "/coarse.tif'");
    EXPECT_EQ(g.code, 0) << g.err;
    EXPECT_TRUE(has(g.err, "mosaic: warping photos, ")) << g.err;
    EXPECT_TRUE(has(g.out, "150.0 cm/px")) << g.out;
    EXPECT_TRUE(std::filesystem::exists(s.dir + "/fp.gpkg"));
}

TEST(MosaicCli, BadInputExitsWithTwoAndSaysWhy) {
    const auto f = test::demoFlight(100.0);
    PF_REQUIRE_DEMO_MAP(f);
    const CliSet s = makeSet(f, "cli_bad");
    const std::string photos = "'" + s.photos + "'";
    const std::string out = " --out '" + s.dir + "/m.tif'";
    expectBadInput("mosaic " + photos, "mosaic needs --out FILE.tif");
    expectBadInput("mosaic" + out, "mosaic needs photos");
    expectBadInput("mosaic " + photos + out + " --dem dem.tif",
                   "--dem: the mosaic does not use terrain models");
    expectBadInput("mosaic " + photos + out + " --gsd 0",
                   "--gsd: expected a positive number but got 0");
    expectBadInput("mosaic " + photos + out + " --camera 'No Such Cam'",
                   "--camera: no camera 'No Such Cam' in the catalog");
    expectBadInput("mosaic " + photos + out + " --plan '" + s.dir + "/nowhere'",
                   "nowhere: no such file (give the plan's directory or its plan.geojson");
    expectBadInput("mosaic " + photos + " --out '" + s.dir + "/m.png'",
                   "m.png: the mosaic is a GeoTIFF: give a .tif file name");
    expectBadInput("mosaic " + photos + " --out '" + s.dir + "/no/such/dir/m.tif'",
                   "does not exist");
    expectBadInput("mosaic '" + s.dir + "/plan'" + out,
                   "plan: no .jpg or .jpeg photos in this directory");
    // Only the damaged photo: nothing to mosaic.
    expectBadInput(
        "mosaic '" + s.photos + "/IMG_9999.JPG'" + out,
        "none of the 1 photo(s) can be placed: IMG_9999.JPG: not an image GDAL can read");
    EXPECT_FALSE(std::filesystem::exists(s.dir + "/m.tif"));
}

} // namespace
} // namespace pf::mosaic
