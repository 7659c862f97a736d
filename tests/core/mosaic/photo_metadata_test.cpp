// Reading a photo's EXIF and XMP through GDAL: GPS, altitudes, gimbal angles, camera; damaged
// files.
#include "core/mosaic/photo_metadata.h"
#include "tests/core/mosaic/mosaic_test_util.h"

#include <gtest/gtest.h>

#include <fstream>

namespace pf::mosaic {
namespace {

TEST(PhotoMetadata, ExifNumbersAndDegrees) {
    EXPECT_DOUBLE_EQ(*detail::exifNumber("(140.537)"), 140.537);
    EXPECT_DOUBLE_EQ(*detail::exifNumber("(49) (0) (43.2)", 2), 43.2);
    EXPECT_DOUBLE_EQ(*detail::exifNumber("0x01"), 1.0);
    EXPECT_FALSE(detail::exifNumber("", 0));
    EXPECT_FALSE(detail::exifNumber("(1)", 1));
    EXPECT_NEAR(*detail::exifDegrees("(49) (0) (43.2)", "N"), 49.012, 1e-12);
    EXPECT_NEAR(*detail::exifDegrees("(8) (19) (48.5)", "W"), -(8 + 19 / 60.0 + 48.5 / 3600.0),
                1e-12);
    EXPECT_NEAR(*detail::exifDegrees("(33) (24) (0)", "S"), -33.4, 1e-12);
    EXPECT_FALSE(detail::exifDegrees("", "N"));
}

TEST(PhotoMetadata, XmpPropertiesInAttributeAndElementForm) {
    const std::string xmp =
        "<rdf:Description drone-dji:GimbalYawDegree=\"+45.50\" drone-dji:GimbalYawDegreeX=\"9\" "
        "drone-dji:RelativeAltitude = "
        "'+40.00'><drone-dji:GimbalPitchDegree>-89.9</drone-dji:GimbalPitchDegree>"
        "<Camera:GimbalRollDegree>0.3</Camera:GimbalRollDegree></rdf:Description>";
    EXPECT_DOUBLE_EQ(*detail::xmpNumber(xmp, "GimbalYawDegree"), 45.5);
    EXPECT_DOUBLE_EQ(*detail::xmpNumber(xmp, "RelativeAltitude"), 40.0);
    EXPECT_DOUBLE_EQ(*detail::xmpNumber(xmp, "GimbalPitchDegree"), -89.9);
    EXPECT_DOUBLE_EQ(*detail::xmpNumber(xmp, "GimbalRollDegree"), 0.3);
    EXPECT_FALSE(detail::xmpNumber(xmp, "FlightYawDegree"));
    EXPECT_FALSE(detail::xmpNumber(xmp, "Yaw"));
}

TEST(PhotoMetadata, ReadsWhatTheSimulatorWrote) {
    const auto f = test::demoFlight(100.0);
    PF_REQUIRE_DEMO_MAP(f);
    const std::string dir = test::scratchDir("metadata");
    testsim::SimOptions o;
    o.camera.widthPx = 160;
    o.camera.heightPx = 120;
    testsim::SimPose truth{{8.3291, 49.0118}, 40.0, 123.4, -80.0, 1.5};
    ASSERT_TRUE(testsim::writePhoto(*f.ground, truth, truth, o, 7, dir + "/a.jpg").ok());
    auto m = readPhotoMetadata(dir + "/a.jpg");
    ASSERT_TRUE(m.ok()) << m.error().message;
    EXPECT_EQ(m->widthPx, 160);
    EXPECT_EQ(m->heightPx, 120);
    EXPECT_EQ(m->orientation, 1);
    ASSERT_TRUE(m->position);
    EXPECT_NEAR(m->position->lon, 8.3291, 1e-7);
    EXPECT_NEAR(m->position->lat, 49.0118, 1e-7);
    EXPECT_NEAR(*m->relativeAltitudeM, 40.0, 1e-9);
    EXPECT_NEAR(*m->gpsAltitudeM, 40.0 + o.takeoffAltitudeAmslM, 1e-3);
    EXPECT_NEAR(*m->gimbalYawDeg, 123.4, 1e-9);
    EXPECT_NEAR(*m->gimbalPitchDeg, -80.0, 1e-9);
    EXPECT_NEAR(*m->gimbalRollDeg, 1.5, 1e-9);
    EXPECT_NEAR(*m->imageDirectionDeg, 123.4, 1e-3);
    EXPECT_EQ(m->make, "Photoflight");
    EXPECT_EQ(m->model, "Falcon 8 camera");
    EXPECT_EQ(m->dateTime, "2024:06:07 10:00:14");
    EXPECT_TRUE(checkPhotoDecodes(dir + "/a.jpg").ok());

    // Without GPS and XMP: no position, no altitude, no angles.
    o.writeGps = false;
    o.writeXmp = false;
    o.writeDirection = false;
    ASSERT_TRUE(testsim::writePhoto(*f.ground, truth, truth, o, 8, dir + "/b.jpg").ok());
    m = readPhotoMetadata(dir + "/b.jpg");
    ASSERT_TRUE(m.ok());
    EXPECT_FALSE(m->position);
    EXPECT_FALSE(m->gpsAltitudeM);
    EXPECT_FALSE(m->relativeAltitudeM);
    EXPECT_FALSE(m->gimbalYawDeg);
    EXPECT_FALSE(m->imageDirectionDeg);
    EXPECT_FALSE(m->hasXmp);

    // Damaged: truncated data decodes with an error; a text file is not an image; nothing there.
    {
        std::ifstream in(dir + "/a.jpg", std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream(dir + "/cut.jpg", std::ios::binary)
            .write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
    }
    EXPECT_TRUE(readPhotoMetadata(dir + "/cut.jpg").ok()); // the header is intact
    auto st = checkPhotoDecodes(dir + "/cut.jpg");
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("cut.jpg: the image data is damaged"), std::string::npos)
        << st.error().message;
    std::ofstream(dir + "/text.jpg") << "not a photo";
    auto t = readPhotoMetadata(dir + "/text.jpg");
    ASSERT_FALSE(t.ok());
    EXPECT_NE(t.error().message.find("text.jpg: not an image GDAL can read"), std::string::npos)
        << t.error().message;
    auto none = readPhotoMetadata(dir + "/none.jpg");
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().message, "none.jpg: no such file");
}

} // namespace
} // namespace pf::mosaic
