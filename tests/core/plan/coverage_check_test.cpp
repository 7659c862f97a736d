#include "core/plan/coverage_check.h"

#include "core/geo/polygon_ops.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pf;
using namespace pf::plan;
using geo::Vec2;

namespace {

geo::Polygon square(double x0, double y0, double s) {
    return geo::Polygon{{Vec2(x0, y0), Vec2(x0 + s, y0), Vec2(x0 + s, y0 + s), Vec2(x0, y0 + s)}, {}};
}

// 20 m square footprints tiling [0, 100]^2 exactly, optionally leaving one out.
std::vector<PhotoFootprint> tiles(int skipCol = -1, int skipRow = -1, double heading = 0.0) {
    std::vector<PhotoFootprint> out;
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 5; ++c)
            if (c != skipCol || r != skipRow)
                out.push_back({Vec2(10 + 20 * c, 10 + 20 * r), heading, 20.0, 20.0});
    return out;
}

} // namespace

TEST(FootprintRing, LongSideAcrossTheTrack) {
    // Flying east (90 deg): the 30 m across side lies north-south, the 10 m along side east-west.
    const auto ring = footprintRing({Vec2(0, 0), 90.0, 30.0, 10.0});
    const auto box = geo::bounds(ring);
    EXPECT_NEAR(box.max.x() - box.min.x(), 10.0, 1e-9);
    EXPECT_NEAR(box.max.y() - box.min.y(), 30.0, 1e-9);
    EXPECT_GT(geo::signedArea(ring), 0.0); // counter-clockwise
    EXPECT_NEAR(geo::signedArea(ring), 300.0, 1e-9);
}

TEST(CoverageCheck, FullCoverage) {
    auto rep = checkCoverage({square(0, 0, 100)}, tiles());
    ASSERT_TRUE(rep.ok()) << rep.error().message;
    EXPECT_DOUBLE_EQ(rep->coveredFraction, 1.0);
    EXPECT_EQ(rep->patchCount, 0);
    EXPECT_TRUE(rep->patches.empty());
    EXPECT_NEAR(rep->admissibleAreaM2, 10000.0, 1e-6);
    EXPECT_DOUBLE_EQ(rep->resolutionM, 0.5);
}

TEST(CoverageCheck, MissingPhotoLeavesItsSquare) {
    auto rep = checkCoverage({square(0, 0, 100)}, tiles(2, 2));
    ASSERT_TRUE(rep.ok()) << rep.error().message;
    ASSERT_EQ(rep->patchCount, 1);
    ASSERT_EQ(rep->patches.size(), 1u);
    const auto& p = rep->patches[0];
    EXPECT_NEAR(p.areaM2, 400.0, 0.25 * 80);   // within one pixel row around the 80 m perimeter
    EXPECT_NEAR(geo::area(p.shape), p.areaM2, 1e-6);
    EXPECT_NEAR(p.centroid.x(), 50.0, 0.5);
    EXPECT_NEAR(p.centroid.y(), 50.0, 0.5);
    const auto box = geo::bounds(p.shape);
    EXPECT_NEAR(box.min.x(), 40.0, 0.5);
    EXPECT_NEAR(box.max.y(), 60.0, 0.5);
    EXPECT_NEAR(rep->coveredFraction, 1.0 - 400.0 / 10000.0, 0.002);
    EXPECT_NEAR(rep->uncoveredAreaM2, 400.0, 20.0);
}

TEST(CoverageCheck, RotatedFootprintLeavesFourCornerTriangles) {
    // A diamond |x-50| + |y-50| <= 80 (square side 80 sqrt 2 flown at 45 deg) leaves four right
    // triangles with 20 m legs: 200 m^2 each.
    const double side = 80.0 * std::sqrt(2.0);
    auto rep = checkCoverage({square(0, 0, 100)}, {{Vec2(50, 50), 45.0, side, side}});
    ASSERT_TRUE(rep.ok()) << rep.error().message;
    ASSERT_EQ(rep->patchCount, 4);
    for (const auto& p : rep->patches)
        EXPECT_NEAR(p.areaM2, 200.0, 5.0);
    // Pixel centres on the diagonal edges: at most half a pixel along the 113 m of diagonal edges.
    EXPECT_NEAR(rep->uncoveredAreaM2, 800.0, 0.25 * 113);
    EXPECT_NEAR(rep->coveredFraction, 0.92, 0.003);
}

TEST(CoverageCheck, HolesInTheAdmissibleAreaNeedNoPhoto) {
    geo::Polygon area = square(0, 0, 100);
    area.holes.push_back(square(40, 40, 20).outer); // a no-fly zone
    auto rep = checkCoverage({area}, tiles(2, 2));
    ASSERT_TRUE(rep.ok()) << rep.error().message;
    EXPECT_DOUBLE_EQ(rep->coveredFraction, 1.0);
    EXPECT_NEAR(rep->admissibleAreaM2, 9600.0, 1e-6);
}

TEST(CoverageCheck, PatchesSortedAndCapped) {
    std::vector<PhotoFootprint> photos = tiles(0, 0);
    photos.erase(photos.end() - 1); // also drop (4, 4)
    photos.push_back({Vec2(85, 90), 0.0, 10.0, 20.0}); // the west half of the (4, 4) square back
    CoverageCheckOptions opt;
    opt.maxPatches = 1;
    auto rep = checkCoverage({square(0, 0, 100)}, photos, opt);
    ASSERT_TRUE(rep.ok());
    EXPECT_EQ(rep->patchCount, 2);
    ASSERT_EQ(rep->patches.size(), 1u);
    EXPECT_NEAR(rep->patches[0].areaM2, 400.0, 20.0); // the larger one
    EXPECT_NEAR(rep->uncoveredAreaM2, 400.0 + 200.0, 30.0);
}

TEST(CoverageCheck, PixelBudgetCoarsensTheResolution) {
    CoverageCheckOptions opt;
    opt.maxPixels = 10'000;
    auto rep = checkCoverage({square(0, 0, 100)}, tiles(), opt);
    ASSERT_TRUE(rep.ok());
    EXPECT_GE(rep->resolutionM, 1.0);
    EXPECT_DOUBLE_EQ(rep->coveredFraction, 1.0);
}

TEST(CoverageCheck, BadInputsAreRejectedWithAMessage) {
    auto zero = checkCoverage({square(0, 0, 10)}, {{Vec2(5, 5), 0.0, 0.0, 5.0}});
    ASSERT_FALSE(zero.ok());
    EXPECT_EQ(zero.error().message, "Photo 1 has a footprint side that is not positive.");
    CoverageCheckOptions opt;
    opt.resolutionM = -1;
    auto neg = checkCoverage({square(0, 0, 10)}, {}, opt);
    ASSERT_FALSE(neg.ok());
    EXPECT_EQ(neg.error().message, "The coverage check resolution must be a positive number of metres.");
    opt = {};
    opt.maxPixels = 4;
    auto tiny = checkCoverage({square(0, 0, 10)}, {}, opt);
    ASSERT_FALSE(tiny.ok());
    EXPECT_EQ(tiny.error().message, "The coverage check pixel budget is too small (at least 16).");
}

TEST(CoverageCheck, EmptyAreaIsFullyCovered) {
    auto rep = checkCoverage({}, {});
    ASSERT_TRUE(rep.ok());
    EXPECT_DOUBLE_EQ(rep->coveredFraction, 1.0);
}

TEST(NoFlyViolations, CountsWaypointsAndLegs) {
    const std::vector<geo::Polygon> zones{square(40, 40, 20)};
    // Diagonal across the zone: one leg; a point 3 m from the zone: one waypoint (and its two legs).
    const std::vector<std::vector<Vec2>> paths{
        {Vec2(0, 0), Vec2(100, 100)},
        {Vec2(0, 50), Vec2(37, 50), Vec2(37, 0)},
        {Vec2(0, 30), Vec2(100, 30)}, // 10 m clear
        {Vec2(0, 36), Vec2(100, 36)}, // 4 m: inside the 5 m margin
    };
    const auto v = countNoFlyViolations(paths, zones, 5.0);
    EXPECT_EQ(v.waypoints, 1);
    EXPECT_EQ(v.segments, 1 + 2 + 1);
    EXPECT_EQ(v.total(), 5);
    EXPECT_EQ(countNoFlyViolations(paths, zones, 0.0).total(), 1);
    EXPECT_EQ(countNoFlyViolations(paths, {}, 5.0).total(), 0);
}

// A patch's pixels (box and mask) are its polygon's: the box is the polygon's bounds and a pixel
// centre is the patch's exactly when the polygon contains it; without patchShapes the pixels are
// the same and the polygon is left out.
TEST(CoverageCheck, PatchPixelsMatchTheirPolygon) {
    // A rotated footprint's corner triangles and a courtyard left by a missing tile beside a hole.
    geo::Polygon area = square(0, 0, 100);
    area.holes.push_back({Vec2(45, 45), Vec2(45, 55), Vec2(55, 55), Vec2(55, 45)});
    for (const auto& photos : {std::vector<PhotoFootprint>{{Vec2(50, 50), 37.0, 95.0, 90.0}}, tiles(2, 2), tiles(0, 4, 10.0)}) {
        CoverageCheckOptions o;
        o.resolutionM = 0.7;
        auto rep = checkCoverage({area}, photos, o);
        ASSERT_TRUE(rep.ok()) << rep.error().message;
        ASSERT_FALSE(rep->patches.empty());
        o.patchShapes = false;
        auto bare = checkCoverage({area}, photos, o);
        ASSERT_TRUE(bare.ok());
        ASSERT_EQ(bare->patches.size(), rep->patches.size());
        const double r = rep->resolutionM;
        for (std::size_t k = 0; k < rep->patches.size(); ++k) {
            const auto& p = rep->patches[k];
            const geo::Box b = geo::bounds(p.shape);
            EXPECT_EQ(p.box.min, b.min);
            EXPECT_EQ(p.box.max, b.max);
            const int rows = static_cast<int>(p.mask.size()) / p.columns;
            ASSERT_EQ(static_cast<std::size_t>(rows * p.columns), p.mask.size());
            for (int j = 0; j < rows; ++j)
                for (int i = 0; i < p.columns; ++i) {
                    const Vec2 c = b.min + r * Vec2(i + 0.5, j + 0.5);
                    EXPECT_EQ(p.mask[static_cast<std::size_t>(j * p.columns + i)] != 0, geo::contains(p.shape, c))
                        << "patch " << k << " pixel " << i << ", " << j;
                }
            EXPECT_TRUE(bare->patches[k].shape.empty());
            EXPECT_EQ(bare->patches[k].mask, p.mask);
            EXPECT_EQ(bare->patches[k].box.min, p.box.min);
        }
    }
}

// The raster's word-wide pixel loops against a count pixel by pixel: pixel centres inside the area
// (with a hole) and inside at least one rotated footprint, rows of every length and offset (not
// multiples of eight), photos overlapping each other and the area's edge.
TEST(CoverageCheck, CoveredAreaEqualsPixelByPixelCount) {
    const geo::Polygon area{
        {Vec2(0.3, 0.1), Vec2(97.7, 3.9), Vec2(88.1, 71.3), Vec2(41.9, 93.3), Vec2(2.2, 60.7)},
        {{Vec2(40.1, 30.2), Vec2(40.4, 52.9), Vec2(61.3, 47.1), Vec2(58.2, 29.6)}}};
    std::vector<PhotoFootprint> photos;
    for (int k = 0; k < 23; ++k)
        photos.push_back({Vec2(7.3 + 4.1 * k, 5.9 + 3.7 * (k % 7) + 1.3 * k), 17.0 * k,
                          13.0 + (k % 3), 9.0 + (k % 4)});
    CoverageCheckOptions opt;
    opt.resolutionM = 0.37;
    auto rep = checkCoverage({area}, photos, opt);
    ASSERT_TRUE(rep.ok()) << rep.error().message;
    ASSERT_DOUBLE_EQ(rep->resolutionM, 0.37);
    // The raster's origin is the area's box corner; pixel (i, j) has its centre half a pixel in.
    const geo::Box box = geo::bounds(geo::MultiPolygon{area});
    const double r = rep->resolutionM;
    const int nx = static_cast<int>(std::ceil((box.max.x() - box.min.x()) / r));
    const int ny = static_cast<int>(std::ceil((box.max.y() - box.min.y()) / r));
    std::vector<geo::Polygon> rings;
    for (const auto& p : photos)
        rings.push_back(geo::Polygon{footprintRing(p), {}});
    long inside = 0, covered = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const Vec2 c = box.min + Vec2((i + 0.5) * r, (j + 0.5) * r);
            if (!geo::contains(area, c))
                continue;
            ++inside;
            for (const auto& ring : rings)
                if (geo::contains(ring, c)) {
                    ++covered;
                    break;
                }
        }
    ASSERT_GT(covered, 1000);
    ASSERT_LT(covered, inside); // some ground left uncovered
    // Pixel centres on an edge may fall either way: a handful at most.
    EXPECT_NEAR(rep->admissibleAreaM2 / (r * r), static_cast<double>(inside), 3.0);
    EXPECT_NEAR(rep->coveredAreaM2 / (r * r), static_cast<double>(covered), 3.0);
}
