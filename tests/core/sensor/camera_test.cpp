// Camera geometry against values computed by hand from the formulas of papers 001 and 004.
#include "core/sensor/camera.h"
#include "core/sensor/footprint.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

using namespace pf::sensor;

namespace {

// Paper 004, table II: GoPro Hero3, 3840 x 2880 px.
Camera goProMedium() {
    Camera c;
    c.name = "GoPro Hero3 Medium";
    c.hfovDeg = 94.4;
    c.vfovDeg = 55.0;
    c.imageWidthPx = 3840;
    c.imageHeightPx = 2880;
    return c;
}

Camera goProWide() {
    Camera c = goProMedium();
    c.name = "GoPro Hero3 Wide";
    c.hfovDeg = 125.3;
    c.vfovDeg = 69.5;
    return c;
}

// DJI Phantom 4 Pro: 1" sensor 13.2 x 8.8 mm, f = 8.8 mm, 5472 x 3648 px.
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

// Paper 001: the Falcon 8 camera covers about 120 x 90 m at 100 m, so
// FOVh = 2 atan(60 / 100) = 61.9275 deg and FOVv = 2 atan(45 / 100) = 48.4555 deg.
Camera falcon8() {
    Camera c;
    c.name = "Falcon 8 camera";
    c.hfovDeg = 2.0 * std::atan(0.6) * 180.0 / M_PI;
    c.vfovDeg = 2.0 * std::atan(0.45) * 180.0 / M_PI;
    c.imageWidthPx = 4000;
    c.imageHeightPx = 3000;
    return c;
}

std::string messageOf(const pf::Status& s) { return s ? std::string("<ok>") : s.error().message; }
template <class T> std::string messageOf(const pf::Result<T>& r) { return r ? std::string("<ok>") : r.error().message; }

} // namespace

TEST(Camera, GoProHero3MediumFootprintAt50m) {
    // W = 2 * 50 * tan(94.4 / 2) = 100 * tan(47.2 deg) = 100 * 1.0799018 = 107.990 m
    // L = 2 * 50 * tan(55 / 2)   = 100 * tan(27.5 deg) = 100 * 0.5205671 = 52.057 m
    auto fp = footprintAt(goProMedium(), 50.0);
    ASSERT_TRUE(fp) << messageOf(fp);
    EXPECT_NEAR(fp->longSideM, 107.990, 1e-3);
    EXPECT_NEAR(fp->shortSideM, 52.057, 1e-3);
}

TEST(Camera, GoProHero3WideFootprintAt50m) {
    // W = 100 * tan(125.3 / 2 = 62.65 deg) = 100 * 1.9333231 = 193.332 m
    // L = 100 * tan(69.5 / 2 = 34.75 deg) = 100 * 0.6937247 = 69.372 m
    auto fp = footprintAt(goProWide(), 50.0);
    ASSERT_TRUE(fp) << messageOf(fp);
    EXPECT_NEAR(fp->longSideM, 193.332, 1e-3);
    EXPECT_NEAR(fp->shortSideM, 69.372, 1e-3);
}

TEST(Camera, GoProGsdIsFootprintWidthOverPixels) {
    // FOV camera: GSD = W / imageW = 107.990 m / 3840 px = 0.028122 m = 2.8122 cm/px (Medium, 50 m)
    //                               193.332 m / 3840 px = 0.050347 m = 5.0347 cm/px (Wide, 50 m)
    EXPECT_NEAR(*gsdCmAt(goProMedium(), 50.0), 2.8122, 1e-4);
    EXPECT_NEAR(*gsdCmAt(goProWide(), 50.0), 5.0347, 1e-4);
    // Inverse: h = GSD * imageW / (2 tan(FOVh/2)) = 0.028122442 * 3840 / 2.1598035 = 50 m
    EXPECT_NEAR(*altitudeForGsd(goProMedium(), 2.812244182818759), 50.0, 1e-9);
}

TEST(Camera, Falcon8CameraCovers120By90At100m) {
    auto fp = footprintAt(falcon8(), 100.0);
    ASSERT_TRUE(fp);
    // 2 * 100 * tan(atan(0.6)) = 120 m; 2 * 100 * tan(atan(0.45)) = 90 m
    EXPECT_NEAR(fp->longSideM, 120.0, 1e-9);
    EXPECT_NEAR(fp->shortSideM, 90.0, 1e-9);
    // At 40 m (the demo altitude) the footprint scales linearly: 48 x 36 m.
    EXPECT_NEAR(footprintAt(falcon8(), 40.0)->longSideM, 48.0, 1e-9);
    EXPECT_NEAR(footprintAt(falcon8(), 40.0)->shortSideM, 36.0, 1e-9);
}

TEST(Camera, Phantom4ProFromOptics) {
    const Camera c = phantom4Pro();
    // W = h * sensorW / f = 100 * 13.2 / 8.8 = 150 m; L = 100 * 8.8 / 8.8 = 100 m
    auto fp = footprintAt(c, 100.0);
    ASSERT_TRUE(fp);
    EXPECT_NEAR(fp->longSideM, 150.0, 1e-9);
    EXPECT_NEAR(fp->shortSideM, 100.0, 1e-9);
    // GSD = 100 * 13.2 / (8.8 * 5472) = 0.0274123 m = 2.74123 cm/px (DJI publishes H/36.5 = 2.74 cm)
    EXPECT_NEAR(*gsdCmAt(c, 100.0), 2.741228, 1e-6);
    // h for 2 cm/px = 0.02 * 8.8 * 5472 / 13.2 = 72.96 m
    EXPECT_NEAR(*altitudeForGsd(c, 2.0), 72.96, 1e-9);
    // FOVh = 2 atan(13.2 / 17.6) = 2 atan(0.75) = 73.7398 deg; FOVv = 2 atan(0.5) = 53.1301 deg
    EXPECT_NEAR(horizontalFovDeg(c), 73.7398, 1e-4);
    EXPECT_NEAR(verticalFovDeg(c), 53.1301, 1e-4);
}

TEST(Camera, OpticsWinOverFieldOfView) {
    Camera c = phantom4Pro();
    c.hfovDeg = 10.0; // ignored: the optics are complete
    c.vfovDeg = 5.0;
    EXPECT_NEAR(footprintAt(c, 100.0)->longSideM, 150.0, 1e-9);
}

TEST(Camera, EffectiveFootprintPutsTheLongSideAcrossTheTrack) {
    // Falcon 8 camera at 40 m: 48 x 36 m. Side overlap 0.65 on the long side: 48 * 0.35 = 16.8 m
    // track spacing; front overlap 0.75 on the short side: 36 * 0.25 = 9 m photo spacing.
    auto eff = effectiveFootprint(falcon8(), 40.0, Overlap{0.75, 0.65});
    ASSERT_TRUE(eff) << messageOf(eff);
    EXPECT_NEAR(eff->acrossM, 16.8, 1e-9);
    EXPECT_NEAR(eff->alongM, 9.0, 1e-9);
    EXPECT_NEAR(eff->real.longSideM, 48.0, 1e-9);
    // Cell side = longest effective side = 16.8 m (paper 001).
    EXPECT_NEAR(cellSizeFor(*eff), 16.8, 1e-9);
}

TEST(Camera, CellSizeIsTheLongestEffectiveSide) {
    // GoPro Medium at 50 m, no overlap: 107.990 x 52.057 -> cell 107.990 m.
    auto eff = effectiveFootprint(goProMedium(), 50.0, Overlap{0.0, 0.0});
    ASSERT_TRUE(eff);
    EXPECT_NEAR(cellSizeFor(*eff), 107.990, 1e-3);
    // Overlaps that make the along side the longest: 107.990 * 0.1 = 10.799 across,
    // 52.057 * 1.0 = 52.057 along -> cell 52.057 m.
    eff = effectiveFootprint(goProMedium(), 50.0, Overlap{0.0, 0.9});
    ASSERT_TRUE(eff);
    EXPECT_NEAR(cellSizeFor(*eff), 52.057, 1e-3);
}

TEST(Camera, InvariantsOnRandomCameras) {
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> sensor(2.0, 40.0), focal(3.0, 100.0), alt(5.0, 500.0),
        aspect(1.0, 2.0), ov(0.0, 0.95), fov(5.0, 170.0);
    std::uniform_int_distribution<int> px(640, 12000);
    for (int i = 0; i < 500; ++i) {
        Camera c;
        c.imageWidthPx = px(rng);
        c.imageHeightPx = std::max(1, static_cast<int>(c.imageWidthPx / aspect(rng)));
        if (i % 2) {
            c.sensorWidthMm = sensor(rng);
            c.sensorHeightMm = c.sensorWidthMm / aspect(rng);
            c.focalLengthMm = focal(rng);
        } else {
            c.hfovDeg = fov(rng);
            c.vfovDeg = c.hfovDeg / aspect(rng);
        }
        ASSERT_TRUE(validate(c)) << messageOf(validate(c));
        const double h = alt(rng);
        auto fp = footprintAt(c, h);
        ASSERT_TRUE(fp);
        // W = 2 h tan(FOVh/2) whichever way the camera is defined.
        EXPECT_NEAR(fp->longSideM, 2 * h * std::tan(horizontalFovDeg(c) * M_PI / 360.0), 1e-9 * fp->longSideM);
        EXPECT_NEAR(fp->shortSideM, 2 * h * std::tan(verticalFovDeg(c) * M_PI / 360.0), 1e-9 * fp->longSideM);
        EXPECT_GE(fp->longSideM, fp->shortSideM);
        // Footprint is linear in altitude.
        EXPECT_NEAR(footprintAt(c, 2 * h)->longSideM, 2 * fp->longSideM, 1e-9 * fp->longSideM);
        // GSD times pixels is the ground width, and altitudeForGsd inverts gsdCmAt.
        const double gsd = *gsdCmAt(c, h);
        EXPECT_NEAR(gsd / 100.0 * c.imageWidthPx, fp->longSideM, 1e-9 * fp->longSideM);
        EXPECT_NEAR(*altitudeForGsd(c, gsd), h, 1e-9 * h);
        // The effective footprint is never larger than the real one and the cell is its longest side.
        const Overlap o{ov(rng), ov(rng)};
        auto eff = effectiveFootprint(c, h, o);
        ASSERT_TRUE(eff);
        EXPECT_NEAR(eff->acrossM, fp->longSideM * (1 - o.side), 1e-9 * fp->longSideM);
        EXPECT_NEAR(eff->alongM, fp->shortSideM * (1 - o.front), 1e-9 * fp->longSideM);
        EXPECT_LE(cellSizeFor(*eff), fp->longSideM);
        EXPECT_EQ(cellSizeFor(*eff), std::max(eff->acrossM, eff->alongM));
    }
}

// ---- bad input: each with the message the user sees ----

TEST(CameraErrors, AltitudeMustBePositive) {
    EXPECT_EQ(messageOf(footprintAt(goProMedium(), 0.0)), "altitude must be a number greater than 0 m (got 0 m)");
    EXPECT_EQ(messageOf(gsdCmAt(goProMedium(), -5.0)), "altitude must be a number greater than 0 m (got -5 m)");
    EXPECT_EQ(messageOf(footprintAt(goProMedium(), NAN)), "altitude must be a number greater than 0 m (got nan m)");
    EXPECT_EQ(footprintAt(goProMedium(), 0.0).error().code, pf::ErrorCode::InvalidInput);
}

TEST(CameraErrors, FieldOfViewOutOfRange) {
    Camera c = goProMedium();
    c.hfovDeg = 180.0;
    EXPECT_EQ(messageOf(validate(c)), "camera 'GoPro Hero3 Medium': horizontal field of view must be between 0 and "
                                      "180 degrees, exclusive (got 180 degrees)");
    c = goProMedium();
    c.vfovDeg = -1.0;
    EXPECT_EQ(messageOf(footprintAt(c, 10.0)), "camera 'GoPro Hero3 Medium': vertical field of view must be between "
                                               "0 and 180 degrees, exclusive (got -1 degrees)");
    c = goProMedium();
    c.hfovDeg = 40.0; // narrower than the vertical 55
    EXPECT_EQ(messageOf(validate(c)), "camera 'GoPro Hero3 Medium': horizontal field of view is across the long "
                                      "side and must not be smaller than the vertical one (got 40 and 55 degrees)");
}

TEST(CameraErrors, NoDefinitionAtAll) {
    Camera c;
    c.imageWidthPx = 100;
    c.imageHeightPx = 100;
    EXPECT_EQ(messageOf(validate(c)),
              "camera: needs either a sensor size and focal length or horizontal and vertical fields of view "
              "(both fields of view are 0 or missing; each must be between 0 and 180 degrees, exclusive)");
}

TEST(CameraErrors, ZeroSensorSizeIsNotSilentlyIgnored) {
    Camera c = phantom4Pro();
    c.sensorHeightMm = 0.0;
    EXPECT_EQ(messageOf(validate(c)), "camera 'Phantom 4 Pro': sensor height must be greater than 0 mm (got 0 mm)");
    c = phantom4Pro();
    c.sensorWidthMm = 0.0;
    EXPECT_EQ(messageOf(gsdCmAt(c, 50)), "camera 'Phantom 4 Pro': sensor width must be greater than 0 mm (got 0 mm)");
    c = phantom4Pro();
    c.focalLengthMm = -8.8;
    EXPECT_EQ(messageOf(validate(c)), "camera 'Phantom 4 Pro': focal length must be greater than 0 mm (got -8.8 mm)");
}

TEST(CameraErrors, ImageSize) {
    Camera c = phantom4Pro();
    c.imageWidthPx = 0;
    EXPECT_EQ(messageOf(validate(c)), "camera 'Phantom 4 Pro': image size must be positive (got 0 x 3648 px)");
    c = phantom4Pro();
    std::swap(c.imageWidthPx, c.imageHeightPx);
    EXPECT_EQ(messageOf(validate(c)), "camera 'Phantom 4 Pro': image width is the long side and must not be "
                                      "smaller than the height (got 3648 x 5472 px)");
}

TEST(CameraErrors, NonFiniteSize) {
    Camera c = phantom4Pro();
    c.focalLengthMm = INFINITY;
    EXPECT_EQ(messageOf(validate(c)), "camera 'Phantom 4 Pro': every size and angle must be a finite number");
}

TEST(CameraErrors, OverlapOutsideZeroToOne) {
    EXPECT_EQ(messageOf(effectiveFootprint(goProMedium(), 50, Overlap{1.0, 0.6})),
              "front overlap must be at least 0 and less than 1 (got 1)");
    EXPECT_EQ(messageOf(effectiveFootprint(goProMedium(), 50, Overlap{0.7, -0.1})),
              "side overlap must be at least 0 and less than 1 (got -0.1)");
    EXPECT_TRUE(effectiveFootprint(goProMedium(), 50, Overlap{0.0, 0.999}));
}

TEST(CameraErrors, GsdMustBePositive) {
    EXPECT_EQ(messageOf(altitudeForGsd(phantom4Pro(), 0.0)),
              "ground sample distance must be a number greater than 0 cm/px (got 0)");
    EXPECT_EQ(messageOf(altitudeForGsd(phantom4Pro(), -1.5)),
              "ground sample distance must be a number greater than 0 cm/px (got -1.5)");
}

// A camera tilted forward: its footprint (the rectangle inside the trapezoid it sees) against the
// ground points of its image corners found by casting rays from a rotated camera, and the tilts it
// refuses.
namespace {

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
