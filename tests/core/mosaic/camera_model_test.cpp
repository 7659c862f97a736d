// The camera model (projection and rays for every EXIF orientation and gimbal angle), the ground
// model hook, footprints and the UTM grid's convergence and scale.
#include "core/geo/geodesic.h"
#include "core/mosaic/camera_model.h"
#include "core/mosaic/ground_model.h"
#include "core/mosaic/photo_geometry.h"
#include "core/mosaic/utm_projection.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf::mosaic {
namespace {

CameraIntrinsics falcon(int orientation = 1) {
    return {4000, 3000, 61.92751306414704, 48.45549063590834, orientation};
}

TEST(CameraModel, NadirPhotoSeesItsFootprintAndTopPointsAlongYaw) {
    // Straight down from 100 m, the image's top towards the east.
    const CameraModel cam(falcon(), CameraPose{Vec3(1000, 2000, 100), 90.0, -90.0, 0.0});
    double c = 0, r = 0;
    ASSERT_TRUE(cam.project(Vec3(1000, 2000, 0), &c, &r));
    EXPECT_NEAR(c, 2000, 1e-9);
    EXPECT_NEAR(r, 1500, 1e-9);
    // The footprint is 120 x 90 m at 100 m, its long side across the yaw: 45 m east is the middle
    // of the top edge...
    ASSERT_TRUE(cam.project(Vec3(1045, 2000, 0), &c, &r));
    EXPECT_NEAR(r, 0.0, 1e-6);
    EXPECT_NEAR(c, 2000, 1e-6);
    // ...and, looking down with the top to the east, the right edge is 60 m south.
    ASSERT_TRUE(cam.project(Vec3(1000, 1940, 0), &c, &r));
    EXPECT_NEAR(c, 4000, 1e-6);
    EXPECT_NEAR(r, 1500, 1e-6);
    EXPECT_NEAR(cam.nadirGsdM(100.0), 120.0 / 4000.0, 1e-9);
    EXPECT_NEAR(cam.offNadirDeg(), 0.0, 1e-9);
}

TEST(CameraModel, RayAndProjectionAreInverseForEveryOrientationAndAttitude) {
    for (int o = 1; o <= 8; ++o) {
        for (double pitch : {-90.0, -75.0, -60.0}) {
            const CameraModel cam(falcon(o), CameraPose{Vec3(0, 0, 80), 33.0, pitch, 4.0});
            const double w = cam.storedWidth(), h = cam.storedHeight();
            for (double fx : {0.1, 0.5, 0.9})
                for (double fy : {0.2, 0.5, 0.8}) {
                    const Vec3 d = cam.ray(fx * w, fy * h);
                    const auto g = intersectGround(FlatGround(0.0), cam.centre(), d);
                    ASSERT_TRUE(g) << "orientation " << o << " pitch " << pitch;
                    double c = 0, r = 0;
                    ASSERT_TRUE(cam.project(*g, &c, &r));
                    EXPECT_NEAR(c, fx * w, 1e-6) << "orientation " << o;
                    EXPECT_NEAR(r, fy * h, 1e-6) << "orientation " << o;
                }
        }
    }
}

TEST(CameraModel, OrientationTurnsTheStoredPixels) {
    // Orientation 3: stored upside down; the ground under the display's top edge is at the stored
    // bottom edge.
    const CameraModel upright(falcon(1), CameraPose{Vec3(0, 0, 100), 0.0, -90.0, 0.0});
    const CameraModel turned(falcon(3), CameraPose{Vec3(0, 0, 100), 0.0, -90.0, 0.0});
    double c1, r1, c3, r3;
    ASSERT_TRUE(upright.project(Vec3(10, 40, 0), &c1, &r1));
    ASSERT_TRUE(turned.project(Vec3(10, 40, 0), &c3, &r3));
    EXPECT_NEAR(c3, 4000 - c1, 1e-9);
    EXPECT_NEAR(r3, 3000 - r1, 1e-9);
    // Orientation 6 (stored turned a quarter, 3000 x 4000 as in the file): still 120 m across the
    // long side.
    CameraIntrinsics portrait{3000, 4000, 61.92751306414704, 48.45549063590834, 6};
    const CameraModel six(portrait, CameraPose{Vec3(0, 0, 100), 0.0, -90.0, 0.0});
    const auto east = intersectGround(FlatGround(0.0), six.centre(), six.ray(1500, 0));
    const auto west = intersectGround(FlatGround(0.0), six.centre(), six.ray(1500, 4000));
    ASSERT_TRUE(east && west);
    EXPECT_NEAR((*east - *west).norm(), 120.0, 1e-6);
}

TEST(CameraModel, PitchLooksForwardAndRollBanksTheView) {
    // Pitch -60 (30 degrees forward of nadir), yaw north: the centre of the image is 100 tan 30 m
    // north.
    const CameraModel pitched(falcon(), CameraPose{Vec3(0, 0, 100), 0.0, -60.0, 0.0});
    auto g = intersectGround(FlatGround(0.0), pitched.centre(), pitched.ray(2000, 1500));
    ASSERT_TRUE(g);
    EXPECT_NEAR(g->x(), 0.0, 1e-9);
    EXPECT_NEAR(g->y(), 100.0 * std::tan(30.0 * M_PI / 180.0), 1e-9);
    EXPECT_NEAR(pitched.offNadirDeg(), 30.0, 1e-9);
    // Roll 10 (right side down, a right bank): a camera looking down turns with the belly, to the
    // left: 100 tan 10 m west for yaw 0.
    const CameraModel rolled(falcon(), CameraPose{Vec3(0, 0, 100), 0.0, -90.0, 10.0});
    g = intersectGround(FlatGround(0.0), rolled.centre(), rolled.ray(2000, 1500));
    ASSERT_TRUE(g);
    EXPECT_NEAR(g->x(), -100.0 * std::tan(10.0 * M_PI / 180.0), 1e-9);
    EXPECT_NEAR(g->y(), 0.0, 1e-9);
}

// A plane rising 20 % to the north: the hook for terrain models.
class Slope : public GroundModel {
public:
    double heightAt(double, double y) const override { return 0.2 * y; }
};

TEST(GroundModel, RaysMeetTheTerrainWhereItIs) {
    const Slope slope;
    const Vec3 origin(0, 0, 100);
    const Vec3 dir = Vec3(0, 0.5, -1).normalized();
    const auto g = intersectGround(slope, origin, dir);
    ASSERT_TRUE(g);
    // Exact: y = 0.5 t', z = 100 - t' = 0.2 y -> t' = 100 / 1.1.
    EXPECT_NEAR(g->y(), 0.5 * 100 / 1.1, 0.02);
    EXPECT_NEAR(g->z(), slope.heightAt(g->x(), g->y()), 0.01);
    EXPECT_FALSE(intersectGround(slope, origin, Vec3(0, 1, 0.1).normalized()));
    EXPECT_FALSE(intersectGround(FlatGround(0.0), origin, Vec3(0, 1, 0)));
}

TEST(PhotoGeometry, FootprintFollowsTheViewAngleLimit) {
    const auto nadir = photoGeometry(
        CameraModel(falcon(), CameraPose{Vec3(0, 0, 100), 0.0, -90.0, 0.0}), FlatGround(0.0), 60.0);
    ASSERT_TRUE(nadir.seesGround);
    EXPECT_NEAR(geo::area(geo::Polygon{nadir.footprint, {}}), 120.0 * 90.0, 1.0);
    EXPECT_NEAR(nadir.nadirGsdM, 0.03, 1e-9);
    EXPECT_TRUE(nadir.sees(50, 40, 0));
    EXPECT_FALSE(nadir.sees(70, 0, 0));
    // Looking at the horizon, nothing within 60 degrees of the vertical is in the photo.
    const auto horizon = photoGeometry(
        CameraModel(falcon(), CameraPose{Vec3(0, 0, 100), 0.0, 0.0, 0.0}), FlatGround(0.0), 60.0);
    EXPECT_FALSE(horizon.seesGround);
    // 45 degrees forward: the far part of the view is cut at 60 degrees (100 tan 60 = 173 m).
    const auto oblique = photoGeometry(
        CameraModel(falcon(), CameraPose{Vec3(0, 0, 100), 0.0, -45.0, 0.0}), FlatGround(0.0), 60.0);
    ASSERT_TRUE(oblique.seesGround);
    EXPECT_LE(oblique.footprintBox.max.y(), 100.0 * std::tan(60.0 * M_PI / 180.0) + 1e-6);
    EXPECT_FALSE(oblique.sees(0, 180, 0));
    EXPECT_TRUE(oblique.sees(0, 150, 0));
}

TEST(UtmProjection, ZoneConvergenceAndScale) {
    auto utm = UtmProjection::forSite({8.33, 49.012});
    ASSERT_TRUE(utm.ok());
    EXPECT_EQ(utm->zone(), 32);
    EXPECT_TRUE(utm->north());
    EXPECT_EQ(utm->epsg(), 32632);
    EXPECT_EQ(utm->name(), "UTM zone 32N (EPSG:32632)");
    // West of the central meridian (9 E) grid north lies west of true north, so a true bearing
    // reads larger on the grid: by (9 - 8.33) sin(49.01) degrees, to first order.
    EXPECT_NEAR(utm->gridFromTrueDeg({8.33, 49.012}),
                (9.0 - 8.33) * std::sin(49.012 * M_PI / 180.0), 0.005);
    EXPECT_NEAR(utm->scaleFactor({9.0, 49.0}), 0.9996, 1e-6);
    // A point and its image round-trip to the millimetre.
    const geo::LonLat p{8.3291, 49.0118};
    const geo::LonLat q = utm->toGeo(utm->toGrid(p));
    EXPECT_LT(geo::geodesicDistance(p, q), 1e-3);
    EXPECT_EQ(UtmProjection::forSite({-70.6, -33.4})->epsg(), 32719);
    EXPECT_FALSE(UtmProjection::forSite({0.0, 89.0}).ok());
}

} // namespace
} // namespace pf::mosaic
