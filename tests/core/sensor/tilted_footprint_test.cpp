// A camera tilted forward: its footprint (the rectangle inside the trapezoid it sees) against the
// ground points of its image corners and edge midpoints found by casting rays from a rotated camera,
// and the tilts it refuses.
#include "core/sensor/camera.h"
#include "core/sensor/footprint.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace pf::sensor;

namespace {

Camera phantom4Pro() {
    Camera c;
    c.name = "Phantom 4 Pro";
    c.sensorWidthMm = 13.2;
    c.sensorHeightMm = 8.8;
    c.focalLengthMm = 8.8;
    c.imageWidthPx = 5472;
    c.imageHeightPx = 3648;
    return c;
}

// Where the ray through image point (x, y) (each in [-1, 1]: x across the track, y along it,
// forward positive) meets flat ground `h` below a camera pitched forward by `tiltDeg`; x east
// (across), y north (the direction of flight).
Eigen::Vector2d groundPoint(const Camera& c, double h, double tiltDeg, double x, double y) {
    const double tx = c.sensorWidthMm / (2 * c.focalLengthMm), ty = c.sensorHeightMm / (2 * c.focalLengthMm);
    // Straight down the ray is (x tx, y ty, -1); the tilt turns it about the across axis.
    const Eigen::Vector3d nadir(x * tx, y * ty, -1.0);
    const Eigen::Vector3d ray = Eigen::AngleAxisd(tiltDeg * M_PI / 180.0, Eigen::Vector3d::UnitX()) * nadir;
    const double s = h / -ray.z();
    return {ray.x() * s, ray.y() * s};
}

TEST(TiltedFootprint, NadirCameraIsUnchanged) {
    Camera c = phantom4Pro();
    auto fp = footprintAt(c, 60.0);
    ASSERT_TRUE(fp.ok());
    EXPECT_NEAR(fp->longSideM, 60.0 * 13.2 / 8.8, 1e-9);
    EXPECT_NEAR(fp->shortSideM, 60.0, 1e-9);
    EXPECT_EQ(fp->aheadM, 0.0);
}

TEST(TiltedFootprint, IsTheRectangleInsideTheTrapezoidTheRaysReach) {
    Camera c = phantom4Pro();
    for (double tilt : {10.0, 20.0, 30.0, 45.0}) {
        c.tiltDeg = tilt;
        const double h = 70.0;
        auto fp = footprintAt(c, h);
        ASSERT_TRUE(fp.ok()) << fp.error().message;
        const auto nearLeft = groundPoint(c, h, tilt, -1, -1), nearRight = groundPoint(c, h, tilt, 1, -1);
        const auto farLeft = groundPoint(c, h, tilt, -1, 1), farRight = groundPoint(c, h, tilt, 1, 1);
        // The near edge is the narrower one: the rectangle's width; its depth from near to far.
        EXPECT_LT(nearRight.x() - nearLeft.x(), farRight.x() - farLeft.x());
        EXPECT_NEAR(fp->longSideM, nearRight.x() - nearLeft.x(), 1e-6) << tilt;
        EXPECT_NEAR(fp->shortSideM, farLeft.y() - nearLeft.y(), 1e-6) << tilt;
        EXPECT_NEAR(fp->aheadM, (farLeft.y() + nearLeft.y()) / 2, 1e-6) << tilt;
        // Every corner of the rectangle is seen: within the trapezoid at its depth.
        const auto seen = [&](double across, double along) {
            const double f = (along - nearLeft.y()) / (farLeft.y() - nearLeft.y());
            const double half = (nearRight.x() + f * (farRight.x() - nearRight.x()));
            return std::abs(across) <= half + 1e-9;
        };
        for (double sx : {-0.5, 0.5})
            for (double sy : {-0.5, 0.5})
                EXPECT_TRUE(seen(sx * fp->longSideM, fp->aheadM + sy * fp->shortSideM));
    }
}

TEST(TiltedFootprint, PhotoCentreLiesAheadAlongTheHeading) {
    const Footprint fp{40.0, 50.0, 30.0};
    const auto east = photoCentre(pf::geo::Vec2(10, 20), 90.0, fp);
    EXPECT_NEAR(east.x(), 40.0, 1e-9);
    EXPECT_NEAR(east.y(), 20.0, 1e-9);
    const PhotoFootprint taken = photoTakenFrom(pf::geo::Vec2(0, 0), 180.0, fp, 0.5);
    EXPECT_NEAR(taken.pos.y(), -15.0, 1e-9);
    EXPECT_NEAR(taken.acrossM, 20.0, 1e-9);
    EXPECT_NEAR(taken.alongM, 25.0, 1e-9);
}

TEST(TiltedFootprint, RefusesTiltsOutOfRangeOrNearTheHorizon) {
    Camera c = phantom4Pro(); // 53 degrees along the track
    EXPECT_TRUE(checkTilt(c, 0.0).ok());
    EXPECT_TRUE(checkTilt(c, 45.0).ok());
    for (double bad : {-5.0, 46.0, std::nan("")}) {
        auto s = checkTilt(c, bad);
        ASSERT_FALSE(s.ok()) << bad;
        EXPECT_NE(s.error().message.find("between 0"), std::string::npos) << s.error().message;
    }
    Camera wide;
    wide.name = "wide";
    wide.hfovDeg = 110;
    wide.vfovDeg = 90; // 45 + 45 reaches 90 degrees from straight down
    wide.imageWidthPx = 4000;
    wide.imageHeightPx = 3000;
    auto s = checkTilt(wide, 45.0);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("horizon"), std::string::npos) << s.error().message;
    wide.tiltDeg = 45.0;
    EXPECT_FALSE(footprintAt(wide, 50.0).ok());
}

} // namespace
