// Placing photos: camera from the catalog or EXIF, altitude and yaw from wherever the file or the
// plan has them, matching to the plan's photo points, and the reasons a photo cannot be placed.
#include "core/geo/geodesic.h"
#include "core/io/catalog.h"
#include "core/mosaic/pose_resolver.h"

#include <gtest/gtest.h>

namespace pf::mosaic {
namespace {

const geo::LonLat kOrigin{8.3291, 49.0118};

// A line of planned photos eastwards, every 20 m.
PlannedFlight linePlan(int n, const std::string& aircraft = "Falcon 8") {
    PlannedFlight f;
    f.source = "test";
    for (int i = 0; i < n; ++i) {
        PlannedPhoto p;
        p.aircraft = aircraft;
        p.seq = i + 1;
        p.position = geo::geodesicDirect(kOrigin, 90.0, 20.0 * i);
        p.altitudeM = 50.0;
        p.headingDeg = 90.0;
        p.footprintAcrossM = 60.0;
        p.footprintAlongM = 45.0;
        f.photos.push_back(p);
    }
    return f;
}

PhotoMetadata photo(int i, bool gps = true) {
    PhotoMetadata m;
    m.path = "/photos/IMG_" + std::to_string(1000 + i) + ".JPG";
    m.widthPx = 4000;
    m.heightPx = 3000;
    if (gps)
        m.position = geo::geodesicDirect(kOrigin, 90.0, 20.0 * i);
    m.relativeAltitudeM = 50.0;
    m.make = "DJI";
    m.model = "FC6310";
    char t[32];
    std::snprintf(t, sizeof t, "2024:06:07 10:00:%02d", i);
    m.dateTime = t;
    return m;
}

MosaicOptions withCatalog() {
    MosaicOptions o;
    auto c = io::loadDefaultCatalog();
    EXPECT_TRUE(c.ok());
    if (c)
        o.catalog = c->cameras;
    return o;
}

const PhotoFinding* finding(const ResolvedPoses& r, const std::string& file) {
    for (const auto& f : r.findings)
        if (f.file == file)
            return &f;
    return nullptr;
}

TEST(PoseResolver, CameraFromExifModelOr35mmFocalLength) {
    MosaicOptions o = withCatalog();
    std::vector<PhotoMetadata> photos{photo(0), photo(1), photo(2), photo(3)};
    photos[1].model = "Mystery 1";
    photos[1].focalLength35mmMm = 24.0; // a 24 mm equivalent: 84 degrees across the diagonal
    photos[2].model = "Mystery 2";
    photos[3].make = "Photoflight";
    photos[3].model = "Falcon 8 camera";
    auto r = resolvePoses(photos, o);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->photos.size(), 3u);
    EXPECT_EQ(r->photos[0].camera, "DJI Phantom 4 Pro camera");
    EXPECT_NEAR(r->photos[0].longSideFovDeg, 2 * std::atan(13.2 / 2 / 8.8) * 180 / M_PI, 1e-9);
    const double halfDiag = std::atan(43.2666 / 48.0);
    EXPECT_NEAR(r->photos[1].longSideFovDeg, 2 * std::atan(std::tan(halfDiag) * 0.8) * 180 / M_PI,
                1e-9);
    EXPECT_NEAR(r->photos[1].shortSideFovDeg, 2 * std::atan(std::tan(halfDiag) * 0.6) * 180 / M_PI,
                1e-9);
    EXPECT_EQ(r->photos[2].camera, "Falcon 8 camera");
    const PhotoFinding* unknown = finding(*r, "IMG_1002.JPG");
    ASSERT_TRUE(unknown);
    EXPECT_EQ(unknown->kind, PhotoFinding::Kind::NoCamera);
    EXPECT_NE(unknown->message.find("camera 'DJI Mystery 2' is not in the catalog"),
              std::string::npos)
        << unknown->message;
    EXPECT_NE(unknown->message.find("--camera NAME"), std::string::npos);

    // --camera forces one (its short side follows the photo's 4:3 pixels when the aspect differs).
    o.cameraName = "dji phantom 4 pro camera";
    r = resolvePoses(photos, o);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->photos.size(), 4u);
    for (const auto& p : r->photos)
        EXPECT_EQ(p.camera, "DJI Phantom 4 Pro camera");
    const double longFov = 2 * std::atan(13.2 / 2 / 8.8);
    EXPECT_NEAR(r->photos[0].shortSideFovDeg,
                2 * std::atan(std::tan(longFov / 2) * 0.75) * 180 / M_PI, 1e-9);
    o.cameraName = "Hasselblad 500";
    auto bad = resolvePoses(photos, o);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::NotFound);
    EXPECT_NE(
        bad.error().message.find("--camera: no camera 'Hasselblad 500' in the catalog (known: "),
        std::string::npos);
}

TEST(PoseResolver, YawFollowsTheTrackWhenTheFileHasNone) {
    std::vector<PhotoMetadata> photos;
    for (int i = 0; i < 5; ++i)
        photos.push_back(photo(i));
    auto r = resolvePoses(photos, withCatalog());
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->photos.size(), 5u);
    for (const auto& p : r->photos) {
        EXPECT_NEAR(p.yawDeg, 90.0, 0.01);
        EXPECT_NE(p.poseFrom.find("yaw from the flight track"), std::string::npos);
        EXPECT_NE(p.poseFrom.find("assumed nadir"), std::string::npos);
        EXPECT_DOUBLE_EQ(p.pitchDeg, -90.0);
    }
    bool noted = false;
    for (const auto& n : r->notes)
        noted |= n.find("5 photo(s) without a camera direction") != std::string::npos;
    EXPECT_TRUE(noted);
    // A gimbal yaw in XMP wins over everything.
    photos[2].gimbalYawDeg = 271.0;
    photos[2].gimbalPitchDeg = -85.0;
    photos[2].imageDirectionDeg = 10.0;
    r = resolvePoses(photos, withCatalog());
    ASSERT_TRUE(r.ok());
    EXPECT_DOUBLE_EQ(r->photos[2].yawDeg, 271.0);
    EXPECT_DOUBLE_EQ(r->photos[2].pitchDeg, -85.0);
}

TEST(PoseResolver, TakeoffAltitudeFromThePlanAndGroundShotsLeftOut) {
    MosaicOptions o = withCatalog();
    o.plan = linePlan(6);
    std::vector<PhotoMetadata> photos;
    for (int i = 0; i < 6; ++i) {
        PhotoMetadata m = photo(i);
        m.relativeAltitudeM.reset();
        m.gpsAltitudeM = 152.0 + 50.0 + (i % 2 ? 0.4 : -0.4);
        photos.push_back(m);
    }
    PhotoMetadata ground = photo(0);
    ground.path = "/photos/preflight.JPG";
    ground.relativeAltitudeM = 0.3;
    ground.dateTime = "2024:06:07 09:59:00";
    photos.push_back(ground);
    auto r = resolvePoses(photos, o);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->photos.size(), 6u);
    for (const auto& p : r->photos)
        EXPECT_NEAR(p.altitudeM, 50.0, 0.41);
    bool noted = false;
    for (const auto& n : r->notes)
        noted |= n.find("take-off altitude 152.0 m above sea level, estimated from 6 photos") !=
                 std::string::npos;
    EXPECT_TRUE(noted);
    const PhotoFinding* pre = finding(*r, "preflight.JPG");
    ASSERT_TRUE(pre);
    EXPECT_TRUE(pre->excluded);
    EXPECT_NE(pre->message.find("taken on the ground"), std::string::npos) << pre->message;
    // Without a plan and without --takeoff-alt an absolute altitude is not enough.
    o.plan.reset();
    r = resolvePoses(std::vector<PhotoMetadata>(photos.begin(), photos.begin() + 6), o);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r->photos.empty());
    const PhotoFinding* f = finding(*r, "IMG_1000.JPG");
    ASSERT_TRUE(f);
    EXPECT_EQ(f->kind, PhotoFinding::Kind::NoAltitude);
    EXPECT_NE(f->message.find("give --takeoff-alt M or --plan"), std::string::npos);
    o.takeoffAltitudeM = 152.0;
    r = resolvePoses(std::vector<PhotoMetadata>(photos.begin(), photos.begin() + 6), o);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->photos.size(), 6u);
}

TEST(PoseResolver, PhotosWithoutGpsTakeThePlannedPointsInCaptureOrder) {
    MosaicOptions o = withCatalog();
    o.plan = linePlan(5);
    std::vector<PhotoMetadata> photos;
    for (int i = 0; i < 5; ++i)
        photos.push_back(photo(i, false));
    std::swap(photos[1], photos[3]); // given out of order: the EXIF time decides
    auto r = resolvePoses(photos, o);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->photos.size(), 5u);
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(r->photos[i].planned, i) << r->photos[i].meta.path;
        EXPECT_EQ(r->photos[i].meta.path, "/photos/IMG_" + std::to_string(1000 + i) + ".JPG");
        EXPECT_NEAR(geo::geodesicDistance(r->photos[i].position, o.plan->photos[i].position), 0.0,
                    1e-6);
        EXPECT_DOUBLE_EQ(r->photos[i].yawDeg, 90.0); // the planned heading
        EXPECT_NE(r->photos[i].poseFrom.find("plan (capture order)"), std::string::npos);
    }
    // One fewer photo than points: still matched in order, with a warning that it may be off.
    photos.pop_back();
    r = resolvePoses(photos, o);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->photos.size(), 4u);
    bool warned = false;
    for (const auto& n : r->notes)
        warned |= n.find("4 photos without a GPS position for 5 planned photo points") !=
                  std::string::npos;
    EXPECT_TRUE(warned);
    // Between placed neighbours that leave the wrong number of points, it cannot be placed.
    photos = {photo(0), photo(2, false), photo(3, false), photo(4)};
    photos[1].dateTime = "2024:06:07 10:00:02";
    r = resolvePoses(photos, o);
    ASSERT_TRUE(r.ok());
    const PhotoFinding* f = finding(*r, "IMG_1002.JPG");
    ASSERT_TRUE(f);
    EXPECT_EQ(f->kind, PhotoFinding::Kind::NoPosition);
    EXPECT_NE(f->message.find("leave 3 planned point(s) for 2 photo(s)"), std::string::npos)
        << f->message;
}

TEST(PoseResolver, AircraftFilterAndOtherSitesWithoutAPlan) {
    MosaicOptions o = withCatalog();
    PlannedFlight two = linePlan(3, "Falcon 8");
    for (auto p : linePlan(3, "Phantom").photos)
        two.photos.push_back(p);
    o.plan = two;
    o.planAircraft = "Mavic";
    auto bad = resolvePoses({photo(0)}, o);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message,
              "--aircraft: the plan has no photos of 'Mavic' (its aircraft: Falcon 8, Phantom)");

    o.plan.reset();
    std::vector<PhotoMetadata> photos{photo(0), photo(1), photo(2)};
    PhotoMetadata far = photo(3);
    far.position = geo::geodesicDirect(kOrigin, 0.0, 12000.0);
    photos.push_back(far);
    auto r = resolvePoses(photos, o);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->photos.size(), 3u);
    const PhotoFinding* f = finding(*r, "IMG_1003.JPG");
    ASSERT_TRUE(f);
    EXPECT_EQ(f->kind, PhotoFinding::Kind::OtherSite);
    EXPECT_NE(f->message.find("12.0 km from the other photos"), std::string::npos) << f->message;
}

} // namespace
} // namespace pf::mosaic
