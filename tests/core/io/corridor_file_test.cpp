// Corridors in files: centre lines imported from every format OGR reads for them, and corridor
// missions in the mission file (version 5) beside the older versions that still read.
#include "core/io/area_import.h"
#include "core/io/mission_file.h"
#include "core/mission/corridor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace pf;
using namespace pf::io;

namespace {

std::string fixture(const std::string& name) {
    return std::string(PF_TEST_DATA_DIR) + "/corridor/" + name;
}

const char* const kCorridorMission = R"({
  "format": "photoflight-mission",
  "version": 5,
  "name": "River",
  "corridor": {"line": [[8.3200, 49.0100], [8.3290, 49.0112], [8.3352, 49.0150]], "width_m": 80},
  "aircraft": [
    {"name": "A", "camera": {"hfov_deg": 60.0, "vfov_deg": 45.0, "image_width_px": 4000, "image_height_px": 3000},
     "altitude_m": 50.0}
  ]
})";

std::string with(std::string text, const std::string& from, const std::string& to) {
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << "test setup: '" << from << "' not in the text";
    if (pos != std::string::npos)
        text.replace(pos, from.size(), to);
    return text;
}

std::string errorOf(const std::string& text) {
    auto r = parseMissionJson(text, "x.json");
    return r ? std::string("<parsed>") : r.error().message;
}

} // namespace

// The same line from GeoJSON, KML, a GPX track, a Shapefile in UTM and a GeoPackage.
TEST(CorridorImport, EveryFormatGivesTheSameLine) {
    auto ref = importLines(fixture("river.geojson"));
    ASSERT_TRUE(ref) << ref.error().message;
    ASSERT_EQ(ref->size(), 1u);
    EXPECT_EQ(ref->front().name, "Alb bank");
    ASSERT_EQ(ref->front().line.size(), 6u);
    for (const char* f : {"river.kml", "river.gpx", "river_25832.shp", "river.gpkg"}) {
        auto r = importLines(fixture(f));
        ASSERT_TRUE(r) << f << ": " << r.error().message;
        ASSERT_EQ(r->size(), 1u) << f;
        ASSERT_EQ(r->front().line.size(), 6u) << f;
        for (std::size_t i = 0; i < 6; ++i) {
            EXPECT_NEAR(r->front().line[i].lon, ref->front().line[i].lon, 1e-7) << f;
            EXPECT_NEAR(r->front().line[i].lat, ref->front().line[i].lat, 1e-7) << f;
        }
    }
}

TEST(CorridorImport, FilesWithoutALineSaySo) {
    auto r = importLines(fixture("no_line.geojson"));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::InvalidGeometry);
    EXPECT_NE(
        r.error().message.find("no line to import: it has 1 feature(s), only points or polygons"),
        std::string::npos)
        << r.error().message;
    EXPECT_EQ(importLines(fixture("missing.geojson")).error().code, ErrorCode::IoError);
    auto two = importLines(fixture("two_lines.geojson"));
    ASSERT_TRUE(two);
    EXPECT_EQ(two->size(), 2u);
}

TEST(CorridorMissionFile, ReadsTheCorridorAndItsGround) {
    auto m = parseMissionJson(kCorridorMission, "x.json");
    ASSERT_TRUE(m) << m.error().message;
    ASSERT_TRUE(m->corridor);
    EXPECT_EQ(m->corridor->line.size(), 3u);
    EXPECT_EQ(m->corridor->widthM, 80.0);
    // The area is the corridor's ground, derived on reading.
    ASSERT_FALSE(m->area.outer.empty());
    EXPECT_GT(geo::groundAreaM2(m->area), 80.0 * 1000.0);
}

TEST(CorridorMissionFile, RoundTripWritesVersion5WithoutTheDerivedArea) {
    auto m = parseMissionJson(kCorridorMission, "x.json");
    ASSERT_TRUE(m);
    const std::string text = missionToJson(*m);
    EXPECT_NE(text.find("\"version\":5"), std::string::npos) << text;
    EXPECT_NE(text.find("\"corridor\""), std::string::npos);
    EXPECT_EQ(text.find("\"area\""), std::string::npos);
    auto back = parseMissionJson(text, "y.json");
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == *m);
    // Without a corridor the file keeps the oldest version that holds it (3: the automatic
    // planner).
    mission::Mission plain = *m;
    mission::applyCorridor(plain, std::nullopt);
    plain.area.outer = {{8.0, 49.0}, {8.001, 49.0}, {8.001, 49.001}};
    EXPECT_NE(missionToJson(plain).find("\"version\":3"), std::string::npos)
        << missionToJson(plain);
}

TEST(CorridorMissionFile, BadCorridorsAreRefusedWithTheField) {
    EXPECT_EQ(errorOf(with(kCorridorMission, "\"version\": 5", "\"version\": 4")),
              "x.json: corridor: a corridor needs version 5 of the mission file, but the file says "
              "version 4");
    EXPECT_EQ(errorOf(with(kCorridorMission, ", \"width_m\": 80", "")),
              "x.json: corridor.width_m: missing required field");
    EXPECT_EQ(errorOf(with(kCorridorMission, "\"width_m\": 80", "\"width_m\": 80, \"widht\": 3")),
              "x.json: corridor.widht: unknown field (known here: line, width_m)");
    EXPECT_EQ(errorOf(with(kCorridorMission, "\"name\": \"River\",",
                           "\"name\": \"River\", \"area\": {\"outer\": []},")),
              "x.json: area: a corridor mission has no area of its own (its ground is the "
              "corridor's): give \"area\" or "
              "\"corridor\", not both");
    EXPECT_NE(
        errorOf(with(kCorridorMission, "[8.3200, 49.0100]", "[8.3200]")).find("corridor.line[0]"),
        std::string::npos);
    // A width of 0 reads (as an altitude of 0 does); validation says what is wrong.
    auto zero =
        parseMissionJson(with(kCorridorMission, "\"width_m\": 80", "\"width_m\": 0"), "x.json");
    ASSERT_TRUE(zero) << zero.error().message;
    EXPECT_TRUE(zero->area.outer.empty());
}

// A version 4 file (terrain following, the newest before corridors) still reads.
TEST(CorridorMissionFile, OlderVersionsStillRead) {
    auto m = readMissionFile(std::string(PF_TEST_DATA_DIR) + "/corridor/mission_v4.json");
    ASSERT_TRUE(m) << m.error().message;
    EXPECT_FALSE(m->corridor);
    EXPECT_EQ(m->area.outer.size(), 4u);
    EXPECT_TRUE(m->terrain.follows());
}

// The double grid is a planner option of version 5, written only when on.
TEST(CorridorMissionFile, DoubleGridNeedsVersion5) {
    auto m = parseMissionJson(with(kCorridorMission, "\"width_m\": 80}",
                                   "\"width_m\": 80},\n  \"planner\": {\"double_grid\": true}"),
                              "x.json");
    ASSERT_TRUE(m) << m.error().message;
    EXPECT_TRUE(m->options.doubleGrid);
    mission::Mission area = *m;
    mission::applyCorridor(area, std::nullopt);
    area.area.outer = {{8.0, 49.0}, {8.001, 49.0}, {8.001, 49.001}};
    const std::string text = missionToJson(area);
    EXPECT_NE(text.find("\"double_grid\":true"), std::string::npos) << text;
    EXPECT_NE(text.find("\"version\":5"), std::string::npos);
    auto back = parseMissionJson(text, "y.json");
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == area);
    area.options.doubleGrid = false;
    EXPECT_EQ(missionToJson(area).find("double_grid"), std::string::npos);
    const std::string v4 = with(with(text, "\"version\":5", "\"version\":4"),
                                "\"planner\":\"auto\"", "\"planner\":\"auto\"");
    EXPECT_EQ(
        errorOf(v4),
        "x.json: planner.double_grid: a double grid needs version 5 of the mission file, but the "
        "file says version 4");
}

// The camera tilt (oblique photos) is a planner option of version 7, written only when set; an
// older file naming it is refused with the version it needs.
TEST(CorridorMissionFile, CameraTiltNeedsVersion7) {
    auto m = parseMissionJson(with(kCorridorMission, "\"width_m\": 80}",
                                   "\"width_m\": 80},\n  \"planner\": {\"double_grid\": true}"),
                              "x.json");
    ASSERT_TRUE(m) << m.error().message;
    mission::Mission area = *m;
    mission::applyCorridor(area, std::nullopt);
    area.area.outer = {{8.0, 49.0}, {8.001, 49.0}, {8.001, 49.001}};
    area.options.cameraTiltDeg = 30.0;
    const std::string text = missionToJson(area);
    EXPECT_NE(text.find("\"camera_tilt_deg\":30"), std::string::npos) << text;
    EXPECT_NE(text.find("\"version\":7"), std::string::npos);
    auto back = parseMissionJson(text, "y.json");
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == area);
    EXPECT_EQ(back->options.cameraTiltDeg, 30.0);
    area.options.cameraTiltDeg = 0.0;
    EXPECT_EQ(missionToJson(area).find("camera_tilt"), std::string::npos);
    EXPECT_EQ(errorOf(with(text, "\"version\":7", "\"version\":6")),
              "x.json: planner.camera_tilt_deg: a camera tilt needs version 7 of the mission file, "
              "but the file says version 6");
}
