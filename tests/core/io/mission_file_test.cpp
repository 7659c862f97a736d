// Mission file: the demo loads, random missions round-trip exactly, bad files give field-path errors,
// and a failed save leaves the old file untouched.
#include "core/io/mission_file.h"

#include "core/io/catalog.h"
#include "core/sensor/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace pf;
using namespace pf::io;

namespace {

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string makeTempDir() {
    std::string tmpl = ::testing::TempDir() + "pf_mission_XXXXXX";
    char* dir = ::mkdtemp(tmpl.data());
    return dir ? std::string(dir) : std::string();
}

std::vector<std::string> listDir(const std::string& dir) {
    std::vector<std::string> names;
    if (DIR* d = ::opendir(dir.c_str())) {
        while (dirent* e = ::readdir(d))
            if (std::string(e->d_name) != "." && std::string(e->d_name) != "..")
                names.emplace_back(e->d_name);
        ::closedir(d);
    }
    return names;
}

// A random mission exercising every field, with doubles of full precision.
mission::Mission randomMission(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> lon(-180.0, 180.0), lat(-90.0, 90.0), unit(0.0, 1.0),
        pos(0.001, 1000.0);
    std::uniform_int_distribution<int> count(3, 12), small(0, 3), px(100, 20000);
    auto coin = [&] { return (rng() & 1) != 0; };
    auto ring = [&] {
        geo::GeoRing r;
        const int n = count(rng);
        for (int i = 0; i < n; ++i)
            r.push_back({lon(rng), lat(rng)});
        return r;
    };
    auto polygon = [&] {
        geo::GeoPolygon p;
        p.outer = ring();
        for (int i = small(rng); i > 0; --i)
            p.holes.push_back(ring());
        return p;
    };
    const char* names[] = {"Field \"north\"", "Zone/1", "back\\slash", "Ünïcödé 北", "", "tab\there"};
    auto name = [&] { return std::string(names[rng() % 6]) + std::to_string(rng() % 1000); };

    mission::Mission m;
    m.name = name();
    m.area = polygon();
    for (int i = small(rng); i > 0; --i)
        m.noFlyZones.push_back({name(), polygon()});
    if (coin())
        m.home = geo::LonLat{lon(rng), lat(rng)};
    if (coin())
        m.landing = geo::LonLat{lon(rng), lat(rng)};
    for (int i = small(rng) + 1; i > 0; --i) {
        mission::AircraftConfig a;
        a.name = name();
        a.model = coin() ? "custom" : name();
        a.camera.name = name();
        a.camera.imageWidthPx = px(rng);
        a.camera.imageHeightPx = std::max(1, static_cast<int>(a.camera.imageWidthPx * (0.5 + 0.5 * unit(rng))));
        const int kind = static_cast<int>(rng() % 3); // optics, FOV, or both (optics win)
        if (kind != 1) {
            a.camera.sensorWidthMm = pos(rng);
            a.camera.sensorHeightMm = a.camera.sensorWidthMm * (0.3 + 0.7 * unit(rng));
            a.camera.focalLengthMm = pos(rng);
        }
        if (kind != 0) {
            a.camera.hfovDeg = 1.0 + 178.0 * unit(rng);
            a.camera.vfovDeg = a.camera.hfovDeg * (0.1 + 0.9 * unit(rng));
        }
        const int drive = static_cast<int>(rng() % 3);
        if (drive != 1)
            a.altitudeM = pos(rng);
        if (drive != 0)
            a.gsdCm = pos(rng);
        a.overlap = {unit(rng), unit(rng)};
        a.cruiseSpeedMps = pos(rng);
        a.turnRateDegS = pos(rng);
        if (coin())
            a.accelerationMps2 = pos(rng);
        a.enduranceMin = pos(rng);
        a.maxAltitudeM = pos(rng);
        char colour[8];
        std::snprintf(colour, sizeof colour, "#%06x", static_cast<unsigned>(rng() & 0xffffff));
        a.colour = colour;
        if (coin())
            a.home = geo::LonLat{lon(rng), lat(rng)};
        m.aircraft.push_back(a);
    }
    m.options.planner = static_cast<mission::PlannerKind>(rng() % 3);
    if (coin())
        m.options.gridAngleDeg = 360.0 * unit(rng) - 180.0;
    m.options.safetyMarginM = pos(rng);
    m.options.keepInsideArea = coin();
    m.options.insideMarginM = pos(rng);
    m.options.altitudeSeparationM = pos(rng);
    m.options.batteryReserve = unit(rng);
    m.options.maxCells = 1 + rng() % 1'000'000'000ULL;
    // Hand-edited routes in about half of the missions (so both file versions are written).
    if (coin()) {
        std::uniform_real_distribution<double> alt(-50.0, 500.0), heading(0.0, 360.0);
        for (int i = small(rng) + 1; i > 0; --i) {
            route::Route r;
            r.aircraft = coin() ? m.aircraft[rng() % m.aircraft.size()].name : name();
            if (coin())
                r.home = geo::LonLat{lon(rng), lat(rng)};
            r.cruiseSpeedMps = pos(rng);
            for (int k = static_cast<int>(rng() % 40); k > 0; --k) {
                route::Waypoint w;
                w.position = {lon(rng), lat(rng)};
                w.altitudeM = alt(rng);
                w.headingDeg = heading(rng);
                w.kind = static_cast<route::WaypointKind>(rng() % 3);
                r.waypoints.push_back(w);
            }
            m.editedRoutes.push_back(r);
        }
    }
    return m;
}

// A minimal valid mission; tests break one field at a time.
const char* const kMinimal = R"({
  "format": "photoflight-mission",
  "version": 1,
  "name": "t",
  "area": {"outer": [[8.0, 49.0], [8.001, 49.0], [8.001, 49.001]], "holes": []},
  "aircraft": [
    {"name": "A", "camera": {"hfov_deg": 60.0, "vfov_deg": 45.0, "image_width_px": 4000, "image_height_px": 3000},
     "altitude_m": 50.0},
    {"name": "B", "camera": {"sensor_width_mm": 13.2, "sensor_height_mm": 8.8, "focal_length_mm": 8.8,
     "image_width_px": 5472, "image_height_px": 3648}, "altitude_m": 60.0, "colour": "#3cb44b"}
  ],
  "planner": {"planner": "stride", "grid_angle_deg": "auto"}
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

TEST(MissionFile, MinimalMissionUsesDocumentedDefaults) {
    auto m = parseMissionJson(kMinimal, "x.json");
    ASSERT_TRUE(m) << m.error().message;
    EXPECT_EQ(m->area.outer.size(), 3u);
    ASSERT_EQ(m->aircraft.size(), 2u);
    const mission::AircraftConfig defaults;
    EXPECT_EQ(m->aircraft[0].model, "custom");
    EXPECT_EQ(m->aircraft[0].overlap.front, defaults.overlap.front);
    EXPECT_EQ(m->aircraft[0].colour, defaults.colour);
    EXPECT_EQ(m->aircraft[1].colour, "#3cb44b");
    EXPECT_EQ(m->aircraft[1].camera.focalLengthMm, 8.8);
    EXPECT_FALSE(m->options.gridAngleDeg.has_value());
    EXPECT_EQ(m->options.maxCells, mission::PlannerOptions{}.maxCells);
    EXPECT_FALSE(m->home.has_value());
}

TEST(MissionFile, DemoMissionLoads) {
    auto m = readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    ASSERT_TRUE(m) << m.error().message;
    EXPECT_EQ(m->name, "Rheinhafen training ground");
    EXPECT_EQ(m->area.outer.size(), 6u);
    EXPECT_EQ(m->area.outer[0], (geo::LonLat{8.3272608, 49.0109209}));
    ASSERT_EQ(m->noFlyZones.size(), 2u);
    EXPECT_EQ(m->noFlyZones[0].name, "Warehouse");
    EXPECT_EQ(m->noFlyZones[0].polygon.outer.size(), 4u);
    EXPECT_EQ(m->noFlyZones[1].name, "Radio mast");
    EXPECT_EQ(m->noFlyZones[1].polygon.outer.size(), 16u);
    ASSERT_TRUE(m->home);
    EXPECT_EQ(*m->home, (geo::LonLat{8.3270554, 49.010741}));
    ASSERT_EQ(m->aircraft.size(), 2u);
    EXPECT_EQ(m->aircraft[0].name, "Falcon 8");
    EXPECT_EQ(m->aircraft[0].altitudeM, 40.0);
    EXPECT_EQ(m->aircraft[1].altitudeM, 60.0);
    for (const auto& a : m->aircraft) {
        EXPECT_EQ(a.overlap.front, 0.75);
        EXPECT_EQ(a.overlap.side, 0.65);
    }
    EXPECT_EQ(m->options.planner, mission::PlannerKind::Auto);
    EXPECT_EQ(m->options.safetyMarginM, 5.0);

    // The aircraft carry exactly the catalog's cameras and figures.
    auto cat = loadCatalog(std::string(PF_RESOURCES_DIR) + "/catalog.json");
    ASSERT_TRUE(cat) << cat.error().message;
    for (const auto& a : m->aircraft) {
        const auto* cam = cat->findCamera(a.camera.name);
        ASSERT_NE(cam, nullptr) << a.camera.name;
        EXPECT_EQ(*cam, a.camera);
        const auto* spec = cat->findAircraft(a.model);
        ASSERT_NE(spec, nullptr) << a.model;
        EXPECT_EQ(spec->cruiseSpeedMps, a.cruiseSpeedMps);
        EXPECT_EQ(spec->enduranceMin, a.enduranceMin);
        EXPECT_EQ(spec->defaultCamera, a.camera.name);
    }
    // Falcon 8 camera at 40 m: 120 x 90 m at 100 m scaled by 0.4 = 48 x 36 m.
    auto fp = sensor::footprintAt(m->aircraft[0].camera, *m->aircraft[0].altitudeM);
    ASSERT_TRUE(fp);
    EXPECT_NEAR(fp->longSideM, 48.0, 1e-9);
    EXPECT_NEAR(fp->shortSideM, 36.0, 1e-9);
}

TEST(MissionFile, RandomMissionsRoundTripExactly) {
    std::mt19937_64 rng(4242);
    for (int i = 0; i < 300; ++i) {
        const mission::Mission m = randomMission(rng);
        const std::string text = missionToJson(m);
        auto back = parseMissionJson(text, "random.json");
        ASSERT_TRUE(back) << back.error().message << "\n" << text;
        ASSERT_TRUE(*back == m) << "mission " << i << " changed in a write/read cycle:\n" << text;
        // Writing again gives the same text: nothing drifts over repeated saves.
        EXPECT_EQ(missionToJson(*back), text);
    }
}

TEST(MissionFile, WriteAndReadFileRoundTrip) {
    const std::string dir = makeTempDir();
    ASSERT_FALSE(dir.empty());
    std::mt19937_64 rng(7);
    const std::string path = dir + "/m.json";
    for (int i = 0; i < 20; ++i) {
        const mission::Mission m = randomMission(rng);
        ASSERT_TRUE(writeMissionFile(m, path));
        auto back = readMissionFile(path);
        ASSERT_TRUE(back) << back.error().message;
        EXPECT_TRUE(*back == m);
    }
    // No temporary file is left behind.
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"m.json"});
    std::remove(path.c_str());
    ::rmdir(dir.c_str());
}

TEST(MissionFile, FailedWriteLeavesTheOldFileIntact) {
    const std::string dir = makeTempDir();
    ASSERT_FALSE(dir.empty());
    std::mt19937_64 rng(11);
    const mission::Mission oldMission = randomMission(rng);
    mission::Mission newMission = randomMission(rng);

    // A file name of 250 characters is legal, but the temporary name beside it is too long (> 255),
    // so the save fails before the target is touched - even when the tests run as root, where
    // permissions would not stop the write.
    const std::string path = dir + "/" + std::string(245, 'm') + ".json";
    {
        std::ofstream out(path, std::ios::binary); // the old file, written by other means
        out << missionToJson(oldMission);
    }
    const std::string before = readText(path);
    ASSERT_FALSE(before.empty());
    auto s = writeMissionFile(newMission, path);
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().code, ErrorCode::IoError);
    EXPECT_NE(s.error().message.find("cannot save the mission: cannot create a temporary file beside it"),
              std::string::npos)
        << s.error().message;
    EXPECT_EQ(readText(path), before);

    // A value that could not be read back is refused, again without touching the old file.
    newMission.aircraft[0].altitudeM = std::nan("");
    s = writeMissionFile(newMission, path);
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().message, path + ": not saved: aircraft[0].altitude_m is not a finite number");
    EXPECT_EQ(readText(path), before);
    EXPECT_EQ(listDir(dir).size(), 1u);

    // Saving into a folder that does not exist says so.
    s = writeMissionFile(oldMission, dir + "/missing/m.json");
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message.find("No such file or directory"), std::string::npos) << s.error().message;

    std::remove(path.c_str());
    ::rmdir(dir.c_str());
}

TEST(MissionFile, ClosedRingsAreStoredOpen) {
    auto m = parseMissionJson(
        with(kMinimal, R"([[8.0, 49.0], [8.001, 49.0], [8.001, 49.001]])",
             R"([[8.0, 49.0], [8.001, 49.0], [8.001, 49.001], [8.0, 49.0]])"),
        "x.json");
    ASSERT_TRUE(m);
    EXPECT_EQ(m->area.outer.size(), 3u);
}

// ---- bad input: each with the message the user sees ----

TEST(MissionFileErrors, MissingFile) {
    auto r = readMissionFile("/nonexistent/dir/mission.json");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::IoError);
    EXPECT_EQ(r.error().message, "/nonexistent/dir/mission.json: cannot open the mission file: No such file or directory");
}

TEST(MissionFileErrors, NotJson) {
    EXPECT_EQ(errorOf("{\n  \"format\": \"photoflight-mission\",\n  \"version\": 1,,\n}"),
              "x.json: not valid JSON: JSON parsing error: quoted object property name expected at line 3, column 16");
    EXPECT_EQ(errorOf("[1, 2]"), "x.json: expected a JSON object but found an array");
}

TEST(MissionFileErrors, WrongOrMissingFormat) {
    EXPECT_EQ(errorOf(with(kMinimal, "\"photoflight-mission\"", "\"FeatureCollection\"")),
              "x.json: format: not a Photoflight mission file (format is \"FeatureCollection\", expected "
              "\"photoflight-mission\")");
    EXPECT_EQ(errorOf(with(kMinimal, "\"format\": \"photoflight-mission\",", "")),
              "x.json: not a Photoflight mission file (no \"format\" field; expected \"photoflight-mission\")");
}

TEST(MissionFileErrors, UnknownVersion) {
    const std::string newest = std::to_string(mission::kMissionFileVersion);
    const std::string next = std::to_string(mission::kMissionFileVersion + 1);
    EXPECT_EQ(errorOf(with(kMinimal, "\"version\": 1", "\"version\": " + next)),
              "x.json: version: the file has version " + next + ", newer than the version " + newest +
                  " this Photoflight reads; please update Photoflight");
    EXPECT_EQ(errorOf(with(kMinimal, "\"version\": 1", "\"version\": 0")),
              "x.json: version: unknown version 0 (expected 1 to " + newest + ")");
    // Version 2 without routes is fine too (a hand-written file, or one whose edits were removed).
    EXPECT_EQ(errorOf(with(kMinimal, "\"version\": 1", "\"version\": 2")), "<parsed>");
    EXPECT_EQ(errorOf(with(kMinimal, "\"version\": 1", "\"version\": \"1\"")),
              "x.json: version: expected a number but found a string");
    EXPECT_EQ(errorOf(with(kMinimal, "\"version\": 1,", "")), "x.json: version: missing required field");
}

TEST(MissionFileErrors, MissingRequiredFields) {
    EXPECT_EQ(errorOf(with(kMinimal, "\"area\"", "\"areas\"")), "x.json: area: missing required field");
    EXPECT_EQ(errorOf(with(kMinimal, "\"outer\"", "\"outside\"")), "x.json: area.outer: missing required field");
    EXPECT_EQ(errorOf(with(kMinimal, "\"aircraft\"", "\"planes\"")), "x.json: aircraft: missing required field");
    EXPECT_EQ(errorOf(with(kMinimal, "\"name\": \"B\",", "")), "x.json: aircraft[1].name: missing required field");
    EXPECT_EQ(errorOf(with(kMinimal, "\"image_height_px\": 3000", "\"image_h\": 3000")),
              "x.json: aircraft[0].camera.image_height_px: missing required field");
    EXPECT_EQ(errorOf(with(kMinimal, ", \"altitude_m\": 60.0", "")),
              "x.json: aircraft[1]: needs altitude_m or gsd_cm (the flight altitude or the wanted ground sample "
              "distance)");
}

TEST(MissionFileErrors, WrongTypes) {
    EXPECT_EQ(errorOf(with(kMinimal, "\"altitude_m\": 60.0", "\"altitude_m\": \"60\"")),
              "x.json: aircraft[1].altitude_m: expected a number but found a string");
    EXPECT_EQ(errorOf(with(kMinimal, "\"name\": \"t\"", "\"name\": 5")),
              "x.json: name: expected a string but found a number");
    EXPECT_EQ(errorOf(with(kMinimal, "\"aircraft\": [", "\"aircraft\": 3, \"unused\": [")),
              "x.json: aircraft: expected an array but found a number");
    EXPECT_EQ(errorOf(with(kMinimal, "\"planner\": {", "\"planner\": {\"keep_inside_area\": 1, ")),
              "x.json: planner.keep_inside_area: expected true or false but found a number");
}

TEST(MissionFileErrors, WrongContainerTypes) {
    EXPECT_EQ(errorOf(with(kMinimal, "\"holes\": []", "\"holes\": {}")),
              "x.json: area.holes: expected an array but found an object");
    EXPECT_EQ(errorOf(with(kMinimal, "\"planner\": {\"planner\": \"stride\", \"grid_angle_deg\": \"auto\"}",
                           "\"planner\": \"stride\"")),
              "x.json: planner: expected an object but found a string");
}

TEST(MissionFileErrors, MisspeltFieldsAreNotIgnored) {
    EXPECT_EQ(errorOf(with(kMinimal, "\"planner\": \"stride\"", "\"planner\": \"stride\", \"safety_margin\": 20")),
              "x.json: planner.safety_margin: unknown field (known here: planner, grid_angle_deg, safety_margin_m, "
              "keep_inside_area, inside_margin_m, altitude_separation_m, battery_reserve, max_cells, double_grid, "
              "camera_tilt_deg)");
    EXPECT_EQ(errorOf(with(kMinimal, "\"altitude_m\": 50.0",
                           "\"altitude_m\": 50.0, \"front_overlpa\": 0.8")),
              "x.json: aircraft[0].front_overlpa: unknown field (known here: name, model, kind, "
              "camera, altitude_m, gsd_cm, front_overlap, side_overlap, cruise_speed_mps, "
              "turn_rate_deg_s, acceleration_mps2, endurance_min, max_altitude_m, plane, colour, "
              "home, dji_drone_enum, dji_drone_sub_enum)");
    // "note" is allowed anywhere for the user's remarks.
    EXPECT_EQ(errorOf(with(kMinimal, "\"name\": \"t\",", "\"name\": \"t\", \"note\": \"surveyed twice\",")),
              "<parsed>");
}

TEST(MissionFileErrors, NonFiniteNumbers) {
    EXPECT_EQ(errorOf(with(kMinimal, "\"altitude_m\": 50.0", "\"altitude_m\": NaN")),
              "x.json: aircraft[0].altitude_m: expected a finite number but found NaN");
    EXPECT_EQ(errorOf(with(kMinimal, "[8.001, 49.0]", "[Infinity, 49.0]")),
              "x.json: area.outer[1][0]: expected a finite number but found infinity");
}

TEST(MissionFileErrors, BadCoordinates) {
    EXPECT_EQ(errorOf(with(kMinimal, "[8.001, 49.0]", "[8.001]")),
              "x.json: area.outer[1]: expected a [longitude, latitude] array but found 1 values");
    EXPECT_EQ(errorOf(with(kMinimal, "[8.001, 49.001]", "[8.001, 95.0]")),
              "x.json: area.outer[2][1]: latitude 95.0 is out of range (-90 to 90)");
    EXPECT_EQ(errorOf(with(kMinimal, "\"name\": \"t\",", "\"name\": \"t\", \"home\": \"here\",")),
              "x.json: home: expected a [longitude, latitude] array but found a string");
}

TEST(MissionFileErrors, BadValues) {
    EXPECT_EQ(errorOf(with(kMinimal, "\"image_width_px\": 4000", "\"image_width_px\": 4000.5")),
              "x.json: aircraft[0].camera.image_width_px: expected a whole number but found 4000.5");
    EXPECT_EQ(errorOf(with(kMinimal, "\"#3cb44b\"", "\"green\"")),
              "x.json: aircraft[1].colour: expected a colour like \"#e6194b\" but found \"green\"");
    EXPECT_EQ(errorOf(with(kMinimal, "\"planner\": \"stride\"", "\"planner\": \"spiral\"")),
              "x.json: planner.planner: unknown planner \"spiral\" (expected auto, sweep, stride, raster, wavefront or "
              "lawnmower)");
    EXPECT_EQ(errorOf(with(kMinimal, "\"grid_angle_deg\": \"auto\"", "\"grid_angle_deg\": \"north\"")),
              "x.json: planner.grid_angle_deg: expected a number of degrees or \"auto\" but found \"north\"");
    EXPECT_EQ(errorOf(with(kMinimal, "\"hfov_deg\": 60.0", "\"hfov_deg\": 190.0")),
              "x.json: aircraft[0].camera: camera: horizontal field of view must be between 0 and 180 degrees, "
              "exclusive (got 190 degrees)");
}

// ---- hand-edited routes (version 2) ----

namespace {

// kMinimal as version 2 with one edited route of three waypoints; tests break one field at a time.
std::string withRoutes() {
    std::string t = with(kMinimal, "\"version\": 1", "\"version\": 2");
    return with(t, "\"planner\": {\"planner\": \"stride\", \"grid_angle_deg\": \"auto\"}",
                R"("planner": {"planner": "stride", "grid_angle_deg": "auto"},
  "routes": [
    {"aircraft": "A", "cruise_speed_mps": 8.0, "waypoints": []},
    {"aircraft": "Falcon 8", "home": [8.0, 49.0], "cruise_speed_mps": 12.5, "waypoints": [
      {"position": [8.0005, 49.0005], "altitude_m": 40.0, "heading_deg": 90.0, "kind": "transit"},
      {"position": [8.0006, 49.0005], "altitude_m": 40.5, "heading_deg": 90.0, "kind": "photo"},
      {"position": [8.0007, 49.0005], "altitude_m": 41.0, "kind": "turn"}
    ]}
  ])");
}

route::Route sampleRoute() {
    route::Route r;
    r.aircraft = "Falcon 8";
    r.home = geo::LonLat{8.0, 49.0};
    r.cruiseSpeedMps = 7.25;
    for (int i = 0; i < 5; ++i)
        r.waypoints.push_back({{8.0 + i * 1e-4, 49.0 + 1e-7 * i}, 40.0 + 0.1 * i, 45.0 * i,
                               static_cast<route::WaypointKind>(i % 3)});
    return r;
}

} // namespace

TEST(MissionFileRoutes, ReadsEveryFieldOfEveryWaypoint) {
    auto m = parseMissionJson(withRoutes(), "x.json");
    ASSERT_TRUE(m) << m.error().message;
    ASSERT_EQ(m->editedRoutes.size(), 2u);
    EXPECT_EQ(m->editedRoutes[0].aircraft, "A");
    EXPECT_FALSE(m->editedRoutes[0].home);
    EXPECT_TRUE(m->editedRoutes[0].waypoints.empty());
    const auto& r = m->editedRoutes[1];
    EXPECT_EQ(r.aircraft, "Falcon 8");
    ASSERT_TRUE(r.home);
    EXPECT_EQ(*r.home, (geo::LonLat{8.0, 49.0}));
    EXPECT_EQ(r.cruiseSpeedMps, 12.5);
    ASSERT_EQ(r.waypoints.size(), 3u);
    EXPECT_EQ(r.waypoints[0].kind, route::WaypointKind::Transit);
    EXPECT_EQ(r.waypoints[1].kind, route::WaypointKind::Photo);
    EXPECT_EQ(r.waypoints[2].kind, route::WaypointKind::Turn);
    EXPECT_EQ(r.waypoints[1].position, (geo::LonLat{8.0006, 49.0005}));
    EXPECT_EQ(r.waypoints[1].altitudeM, 40.5);
    EXPECT_EQ(r.waypoints[0].headingDeg, 90.0);
    EXPECT_EQ(r.waypoints[2].headingDeg, 0.0); // optional, north by default
}

// An aircraft's own acceleration needs version 3; the default is not written, so the file stays at the
// oldest version that holds the rest.
TEST(MissionFile, AccelerationOnlyWrittenWhenSetAndThenVersion3) {
    auto m = parseMissionJson(kMinimal, "x.json");
    ASSERT_TRUE(m);
    EXPECT_EQ(m->aircraft[0].accelerationMps2, plan::kDefaultAccelerationMps2);
    std::string text = missionToJson(*m);
    EXPECT_EQ(text.find("acceleration_mps2"), std::string::npos) << text;
    m->aircraft[0].accelerationMps2 = 4.5;
    text = missionToJson(*m);
    EXPECT_NE(text.find("\"version\":3,"), std::string::npos) << text;
    auto back = parseMissionJson(text, "x.json");
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_EQ(back->aircraft[0].accelerationMps2, 4.5);
}

TEST(MissionFileRoutes, VersionOneUnlessThereAreEditedRoutes) {
    auto m = parseMissionJson(kMinimal, "x.json");
    ASSERT_TRUE(m);
    // Without edits the file stays readable by releases that only know version 1.
    std::string text = missionToJson(*m);
    EXPECT_NE(text.find("\"version\":1,"), std::string::npos) << text;
    EXPECT_EQ(text.find("\"routes\""), std::string::npos);
    m->editedRoutes.push_back(sampleRoute());
    text = missionToJson(*m);
    EXPECT_NE(text.find("\"version\":2,"), std::string::npos) << text;
    auto back = parseMissionJson(text, "x.json");
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == *m);
    ASSERT_EQ(back->editedRoutes.size(), 1u);
    EXPECT_TRUE(mission::sameRoute(back->editedRoutes[0], sampleRoute()));
}

TEST(MissionFileRoutes, EqualityLooksAtEveryWaypointField) {
    mission::Mission a;
    a.editedRoutes.push_back(sampleRoute());
    const mission::Mission b = a;
    EXPECT_TRUE(a == b);
    auto changed = [&](auto edit) {
        mission::Mission c = b;
        edit(c.editedRoutes[0]);
        return c != b;
    };
    EXPECT_TRUE(changed([](route::Route& r) { r.aircraft += "x"; }));
    EXPECT_TRUE(changed([](route::Route& r) { r.home.reset(); }));
    EXPECT_TRUE(changed([](route::Route& r) { r.cruiseSpeedMps += 1e-12; }));
    EXPECT_TRUE(changed([](route::Route& r) { r.waypoints[3].position.lat = std::nextafter(r.waypoints[3].position.lat, 90.0); }));
    EXPECT_TRUE(changed([](route::Route& r) { r.waypoints[3].altitudeM += 1e-9; }));
    EXPECT_TRUE(changed([](route::Route& r) { r.waypoints[3].headingDeg += 1e-9; }));
    EXPECT_TRUE(changed([](route::Route& r) { r.waypoints[3].kind = route::WaypointKind::Turn; }));
    EXPECT_TRUE(changed([](route::Route& r) { r.waypoints.pop_back(); }));
    mission::Mission none = b;
    none.editedRoutes.clear();
    EXPECT_TRUE(none != b);
}

TEST(MissionFileRoutes, BadRoutesNameTheRouteAndTheWaypoint) {
    const std::string t = withRoutes();
    EXPECT_EQ(errorOf(with(t, "\"altitude_m\": 40.5, ", "")),
              "x.json: routes[1] (\"Falcon 8\"): waypoint 2: altitude_m: missing required field");
    EXPECT_EQ(errorOf(with(t, "\"altitude_m\": 40.5", "\"altitude_m\": \"high\"")),
              "x.json: routes[1] (\"Falcon 8\"): waypoint 2: altitude_m: expected a number but found a string");
    EXPECT_EQ(errorOf(with(t, "\"altitude_m\": 41.0", "\"altitude_m\": NaN")),
              "x.json: routes[1] (\"Falcon 8\"): waypoint 3: altitude_m: expected a finite number but found NaN");
    EXPECT_EQ(errorOf(with(t, "\"kind\": \"turn\"", "\"kind\": \"hover\"")),
              "x.json: routes[1] (\"Falcon 8\"): waypoint 3: kind: unknown kind \"hover\" (expected photo, turn or "
              "transit)");
    EXPECT_EQ(errorOf(with(t, ", \"kind\": \"turn\"", "")),
              "x.json: routes[1] (\"Falcon 8\"): waypoint 3: kind: missing required field");
    EXPECT_EQ(errorOf(with(t, "[8.0006, 49.0005]", "[8.0006, 91.0]")),
              "x.json: routes[1] (\"Falcon 8\"): waypoint 2: position[1]: latitude 91.0 is out of range (-90 to 90)");
    EXPECT_EQ(errorOf(with(t, "\"position\": [8.0005, 49.0005], ", "")),
              "x.json: routes[1] (\"Falcon 8\"): waypoint 1: position: missing required field");
    EXPECT_EQ(errorOf(with(t, "\"heading_deg\": 90.0, \"kind\": \"photo\"", "\"heading_deg\": 90.0, \"kind\": \"photo\", \"gimbal\": -90")),
              "x.json: routes[1] (\"Falcon 8\"): waypoint 2: gimbal: unknown field (known here: position, altitude_m, "
              "heading_deg, kind, ground_m)");
    EXPECT_EQ(errorOf(with(t, "{\"position\": [8.0007, 49.0005], \"altitude_m\": 41.0, \"kind\": \"turn\"}", "[8.0007, 49.0005]")),
              "x.json: routes[1] (\"Falcon 8\"): waypoint 3: expected an object but found an array");
    EXPECT_EQ(errorOf(with(t, "\"aircraft\": \"Falcon 8\", ", "")), "x.json: routes[1].aircraft: missing required field");
    EXPECT_EQ(errorOf(with(t, "\"cruise_speed_mps\": 12.5", "\"cruise_speed_mps\": 0")),
              "x.json: routes[1] (\"Falcon 8\").cruise_speed_mps: the cruise speed must be greater than 0 but is 0");
    EXPECT_EQ(errorOf(with(t, "\"cruise_speed_mps\": 8.0, \"waypoints\": []", "\"cruise_speed_mps\": 8.0")),
              "x.json: routes[0] (\"A\").waypoints: missing required field");
    EXPECT_EQ(errorOf(with(t, "\"waypoints\": []", "\"waypoints\": {}")),
              "x.json: routes[0] (\"A\").waypoints: expected an array but found an object");
    EXPECT_EQ(errorOf(with(t, "\"home\": [8.0, 49.0]", "\"hom\": [8.0, 49.0]")),
              "x.json: routes[1] (\"Falcon 8\").hom: unknown field (known here: aircraft, home, cruise_speed_mps, "
              "waypoints, home_elevation_m)");
    EXPECT_EQ(errorOf(with(t, "{\"aircraft\": \"A\", \"cruise_speed_mps\": 8.0, \"waypoints\": []}", "7")),
              "x.json: routes[0]: expected an object but found a number");
    // A version 1 file cannot hold routes: the releases reading version 1 refuse the field.
    EXPECT_EQ(errorOf(with(t, "\"version\": 2", "\"version\": 1")),
              "x.json: routes: hand-edited routes need version 2 of the mission file, but the file says version 1");
}

TEST(MissionFileRoutes, RandomDamageNeverCrashesAndAlwaysExplains) {
    // Every prefix and every single-byte change of a file with routes either parses or gives a message
    // naming the file, and what parses writes and reads back.
    const std::string t = withRoutes();
    std::mt19937_64 rng(99);
    const char junk[] = "{}[],:\"0-.e9aZ \n";
    for (int i = 0; i < 400; ++i) {
        std::string s = t;
        if (i % 2 == 0)
            s.resize(rng() % s.size());
        else
            s[rng() % s.size()] = junk[rng() % (sizeof junk - 1)];
        auto r = parseMissionJson(s, "x.json");
        if (!r) {
            EXPECT_EQ(r.error().message.rfind("x.json: ", 0), 0u) << r.error().message;
            continue;
        }
        auto back = parseMissionJson(missionToJson(*r), "again.json");
        ASSERT_TRUE(back) << back.error().message;
        EXPECT_TRUE(*back == *r);
    }
}

TEST(MissionFileRoutes, WriterRefusesWhatCouldNotBeReadBack) {
    const std::string dir = makeTempDir();
    ASSERT_FALSE(dir.empty());
    const std::string path = dir + "/m.json";
    auto m = parseMissionJson(withRoutes(), "x.json");
    ASSERT_TRUE(m);
    ASSERT_TRUE(writeMissionFile(*m, path));
    const std::string before = readText(path);

    auto refused = [&](auto edit) {
        mission::Mission bad = *m;
        edit(bad.editedRoutes[1]);
        EXPECT_FALSE(checkWritable(bad, path));
        auto s = writeMissionFile(bad, path);
        EXPECT_EQ(readText(path), before); // the good file stays
        return s ? std::string("<saved>") : s.error().message;
    };
    EXPECT_EQ(refused([](route::Route& r) { r.waypoints[1].position.lon = 181.0; }),
              path + ": not saved: routes[1] (\"Falcon 8\"): waypoint 2: the position is not a valid longitude/latitude");
    EXPECT_EQ(refused([](route::Route& r) { r.waypoints[2].altitudeM = std::nan(""); }),
              path + ": not saved: routes[1] (\"Falcon 8\"): waypoint 3: the altitude is not a finite number");
    EXPECT_EQ(refused([](route::Route& r) { r.waypoints[0].headingDeg = HUGE_VAL; }),
              path + ": not saved: routes[1] (\"Falcon 8\"): waypoint 1: the heading is not a finite number");
    EXPECT_EQ(refused([](route::Route& r) { r.cruiseSpeedMps = 0.0; }),
              path + ": not saved: routes[1] (\"Falcon 8\"): the cruise speed is not a number greater than 0");
    EXPECT_EQ(refused([](route::Route& r) { r.home = geo::LonLat{0.0, -95.0}; }),
              path + ": not saved: routes[1] (\"Falcon 8\"): the home is not a valid longitude/latitude");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"m.json"});
    std::remove(path.c_str());
    ::rmdir(dir.c_str());
}

// `photoflight-cli validate` says in one line which edited routes it read.
TEST(MissionFileRoutes, ValidateMentionsTheEditedRoutes) {
    const std::string cmd = std::string("'") + PF_CLI_PATH + "' validate '" + PF_TEST_DATA_DIR +
                            "/corpus/route_edited_mission.json' 2>/dev/null";
    FILE* p = ::popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string out;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;)
        out.append(buf, n);
    const int status = ::pclose(p);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
    EXPECT_NE(out.find("Edited routes:    1 hand-edited route (Test copter: 52 waypoints), read but not checked "
                       "here; 'plan' does not use them\n"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("OK: 0 errors"), std::string::npos) << out;
}
