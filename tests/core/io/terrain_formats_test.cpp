// Exports and the mission file of routes planned over a terrain model: the MAVLink frames and
// QGroundControl's altitude keys, KML absolute heights, GPX elevations above sea level, Litchi
// altitudes above take-off, and mission file version 4 (terrain options, ground heights).
#include "core/io/gpx.h"
#include "core/io/kml_export.h"
#include "core/io/litchi_csv.h"
#include "core/io/mission_file.h"
#include "core/io/mission_items.h"
#include "core/io/qgc_plan.h"
#include "core/io/qgc_wpl.h"

#include "tests/core/io/formats_test_util.h"

#include <cpl_json.h>
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <tuple>

namespace pf::io {
namespace {

constexpr double kHome = 112.5; // the take-off point's ground above sea level

// A route over terrain: seeded ground heights, every waypoint 40 m above its ground.
route::Route terrainRoute() {
    std::mt19937 rng(18);
    std::uniform_real_distribution<double> ground(95.0, 150.0), dlon(0.0, 0.004), dlat(0.0, 0.002);
    route::Route r;
    r.aircraft = "Quad";
    r.home = geo::LonLat{8.3270554, 49.010741};
    r.homeElevationM = kHome;
    for (int i = 0; i < 12; ++i) {
        const double g = ground(rng);
        route::Waypoint w({8.3275 + dlon(rng), 49.0110 + dlat(rng)}, g + 40.0 - kHome, 90.0,
                          i % 3 == 2 ? route::WaypointKind::Turn : route::WaypointKind::Photo, g);
        r.waypoints.push_back(w);
    }
    return r;
}

ExportContext context() { return makeExportContext(test::demoMission(), {terrainRoute()}); }

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(TerrainFormats, MavlinkAltitudesInEachFrame) {
    const ExportContext ctx = context();
    const auto& r = ctx.routes[0];
    struct Case {
        AltitudeFrame f;
        int frame;
    } cases[] = {{AltitudeFrame::Auto, mav::kFrameGlobal},
                 {AltitudeFrame::AboveSeaLevel, mav::kFrameGlobal},
                 {AltitudeFrame::AboveTerrain, mav::kFrameGlobalTerrainAlt},
                 {AltitudeFrame::RelativeToHome, mav::kFrameGlobalRelativeAlt}};
    for (const auto& c : cases) {
        ExportOptions o;
        o.altitudeFrame = c.f;
        auto items = missionItems(ctx, 0, o);
        ASSERT_TRUE(items.ok()) << items.error().message;
        std::size_t k = 0;
        for (const auto& it : *items) {
            if (it.command == mav::kNavTakeoff) {
                EXPECT_EQ(it.frame, c.frame);
            }
            if (it.command != mav::kNavWaypoint)
                continue;
            ASSERT_LT(k, r.waypoints.size());
            const auto& w = r.waypoints[k++];
            EXPECT_EQ(it.frame, c.frame);
            const double want = c.frame == mav::kFrameGlobal            ? kHome + w.altitudeM
                                : c.frame == mav::kFrameGlobalTerrainAlt ? 40.0
                                                                         : w.altitudeM;
            EXPECT_NEAR(it.params[6], want, 1e-9);
        }
        EXPECT_EQ(k, r.waypoints.size());
        EXPECT_NEAR(homeItem(ctx, 0, o).params[6], kHome, 1e-9);
    }
    // A flat route has no ground: above terrain is refused, above sea level needs the home's elevation.
    ExportContext flat = makeExportContext(test::demoMission(), {route::Route{"Flat", {}, 5.0, terrainRoute().waypoints}});
    for (auto& w : flat.routes[0].waypoints)
        w.groundM.reset();
    ExportOptions o;
    o.altitudeFrame = AltitudeFrame::AboveTerrain;
    auto bad = missionItems(flat, 0, o);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("altitudes above terrain need a route planned over a terrain model"),
              std::string::npos);
    o.altitudeFrame = AltitudeFrame::AboveSeaLevel;
    bad = missionItems(flat, 0, o);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("need the home's elevation"), std::string::npos);
    o.homeElevationM = 50.0;
    auto ok = missionItems(flat, 0, o);
    ASSERT_TRUE(ok.ok());
    o.altitudeFrame = AltitudeFrame::Auto; // flat: relative, as always
    ok = missionItems(flat, 0, o);
    ASSERT_TRUE(ok.ok());
    for (const auto& it : *ok)
        if (it.command == mav::kNavWaypoint) {
            EXPECT_EQ(it.frame, mav::kFrameGlobalRelativeAlt);
        }
}

TEST(TerrainFormats, QgcPlanAltitudeKeysAndWaypointsFrames) {
    const ExportContext ctx = context();
    for (const auto& [f, mode, frame] : {std::tuple{AltitudeFrame::AboveSeaLevel, 2, 0},
                                         std::tuple{AltitudeFrame::AboveTerrain, 4, 10}}) {
        ExportOptions o;
        o.altitudeFrame = f;
        auto text = qgcPlanJson(ctx, 0, o);
        ASSERT_TRUE(text.ok()) << text.error().message;
        CPLJSONDocument doc;
        ASSERT_TRUE(doc.LoadMemory(*text));
        const CPLJSONObject mission = doc.GetRoot().GetObj("mission");
        EXPECT_NEAR(mission.GetArray("plannedHomePosition")[2].ToDouble(), kHome, 1e-9);
        int waypoints = 0;
        for (const auto& item : mission.GetArray("items")) {
            if (item.GetInteger("command") != mav::kNavWaypoint)
                continue;
            ++waypoints;
            EXPECT_EQ(item.GetInteger("frame"), frame);
            EXPECT_EQ(item.GetInteger("AltitudeMode"), mode);
            EXPECT_NEAR(item.GetDouble("Altitude"), item.GetArray("params")[6].ToDouble(), 1e-9);
            if (frame == 10) {
                EXPECT_NEAR(item.GetDouble("Altitude"), 40.0, 1e-9);
            }
        }
        EXPECT_EQ(waypoints, 12);
        auto wpl = qgcWplText(ctx, 0, o);
        ASSERT_TRUE(wpl.ok());
        std::istringstream lines(*wpl);
        std::string line;
        std::getline(lines, line); // QGC WPL 110
        std::getline(lines, line); // home: frame 0 at the home's elevation
        EXPECT_NE(line.find("\t0\t16\t"), std::string::npos) << line;
        int framed = 0;
        while (std::getline(lines, line))
            framed += line.find("\t" + std::to_string(frame) + "\t16\t") != std::string::npos;
        EXPECT_EQ(framed, 12);
    }
    // Above sea level reads back as altitudes above take-off; the terrain frame cannot.
    ExportOptions amsl;
    amsl.altitudeFrame = AltitudeFrame::AboveSeaLevel;
    auto back = parseQgcPlan(*qgcPlanJson(ctx, 0, amsl), "amsl.plan");
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->routes[0].waypoints.size(), 12u);
    for (std::size_t i = 0; i < 12; ++i)
        EXPECT_NEAR(back->routes[0].waypoints[i].altitudeM, ctx.routes[0].waypoints[i].altitudeM, 1e-6);
    ExportOptions terrain;
    terrain.altitudeFrame = AltitudeFrame::AboveTerrain;
    auto refused = parseQgcPlan(*qgcPlanJson(ctx, 0, terrain), "terrain.plan");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("frame 10 (altitude above terrain) cannot be read back"), std::string::npos);
}

TEST(TerrainFormats, KmlAbsoluteGpxAboveSeaLevelLitchiAboveTakeOff) {
    const ExportContext ctx = context();
    const auto dir = std::filesystem::temp_directory_path() / "pf_terrain_formats";
    std::filesystem::create_directories(dir);
    const auto& wps = ctx.routes[0].waypoints;

    const std::string kml = (dir / "t.kml").string();
    ASSERT_TRUE(writeKml(ctx, {0}, kml).ok());
    const std::string k = slurp(kml);
    EXPECT_NE(k.find("<altitudeMode>absolute</altitudeMode>"), std::string::npos);
    // Every photo placemark's height: the DEM's ground plus 40 m above it, within 0.1 m.
    std::regex point("<Point>\\s*(<extrude>0</extrude>\\s*)?<altitudeMode>absolute</altitudeMode>\\s*<coordinates>\\s*"
                     "([-0-9.]+),([-0-9.]+),([-0-9.]+)");
    std::vector<double> heights;
    for (auto it = std::sregex_iterator(k.begin(), k.end(), point); it != std::sregex_iterator(); ++it)
        heights.push_back(std::stod((*it)[4]));
    std::vector<double> want;
    for (const auto& w : wps)
        if (w.kind == route::WaypointKind::Photo)
            want.push_back(*w.groundM + 40.0);
    ASSERT_EQ(heights.size(), want.size()) << k.substr(k.find("Photo 1"), 900);
    for (std::size_t i = 0; i < want.size(); ++i)
        EXPECT_NEAR(heights[i], want[i], 0.1);

    const std::string gpx = (dir / "t.gpx").string();
    ASSERT_TRUE(writeGpx(ctx, {0}, gpx).ok());
    const std::string g = slurp(gpx);
    EXPECT_NE(g.find(kGpxAmslNote), std::string::npos);
    std::smatch ele;
    ASSERT_TRUE(std::regex_search(g, ele, std::regex("<ele>([-0-9.]+)</ele>"))) << g;
    EXPECT_NEAR(std::stod(ele[1]), kHome + wps[0].altitudeM, 0.01); // above sea level
    auto back = readGpx(gpx);
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->routes[0].waypoints.size(), wps.size());
    for (std::size_t i = 0; i < wps.size(); ++i)
        EXPECT_NEAR(back->routes[0].waypoints[i].altitudeM, wps[i].altitudeM, 1e-3);

    auto csv = litchiCsvText(ctx, 0);
    ASSERT_TRUE(csv.ok());
    auto lit = parseLitchiCsv(*csv, "t.csv");
    ASSERT_TRUE(lit.ok()) << lit.error().message;
    for (std::size_t i = 0; i < wps.size(); ++i) // above take-off: AMSL minus the home's elevation
        EXPECT_NEAR(lit->routes[0].waypoints[i].altitudeM, *wps[i].groundM + 40.0 - kHome, 1e-3);
}

mission::Mission fileMission() {
    mission::Mission m = test::demoMission();
    mission::AircraftConfig a;
    a.name = "Quad";
    a.camera.hfovDeg = 60;
    a.camera.vfovDeg = 45;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = 40;
    m.aircraft.push_back(a);
    m.options.planner = mission::PlannerKind::Stride;
    return m;
}

int versionOf(const std::string& json) {
    CPLJSONDocument doc;
    EXPECT_TRUE(doc.LoadMemory(json));
    return doc.GetRoot().GetInteger("version");
}

TEST(TerrainFormats, MissionFileVersionIsTheOldestThatHoldsTheContent) {
    mission::Mission m = fileMission();
    EXPECT_EQ(versionOf(missionToJson(m)), 1);
    m.aircraft[0].accelerationMps2 = 4.0;
    EXPECT_EQ(versionOf(missionToJson(m)), 3);
    m.terrain.mode = mission::TerrainMode::Follow;
    m.terrain.demPath = "/data/site_dem.tif";
    m.terrain.minClearanceM = 12.5;
    m.terrain.homeElevationM = 101.25;
    const std::string v4 = missionToJson(m);
    EXPECT_EQ(versionOf(v4), 4); // versions 3 and 4 together: the higher
    auto back = parseMissionJson(v4, "v4.json");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(*back == m);
    EXPECT_EQ(back->terrain.demPath, "/data/site_dem.tif");
    EXPECT_EQ(back->terrain.minClearanceM, 12.5);
    m.aircraft[0].accelerationMps2 = plan::kDefaultAccelerationMps2;
    EXPECT_EQ(versionOf(missionToJson(m)), 4); // terrain alone

    // Edited routes with ground heights: version 4 as well, read back exactly.
    mission::Mission r = fileMission();
    r.editedRoutes.push_back(terrainRoute());
    const std::string withRoutes = missionToJson(r);
    EXPECT_EQ(versionOf(withRoutes), 4);
    auto rb = parseMissionJson(withRoutes, "routes.json");
    ASSERT_TRUE(rb.ok()) << rb.error().message;
    EXPECT_TRUE(*rb == r);
    r.editedRoutes[0].homeElevationM.reset();
    for (auto& w : r.editedRoutes[0].waypoints)
        w.groundM.reset();
    EXPECT_EQ(versionOf(missionToJson(r)), 2);

    // A file claiming an older version with terrain in it is refused, naming the field.
    std::string old = v4;
    old.replace(old.find("\"version\":4"), 11, "\"version\":3");
    auto refused = parseMissionJson(old, "old.json");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("old.json: terrain: terrain following needs version 4"), std::string::npos)
        << refused.error().message;
    std::string badMode = v4;
    badMode.replace(badMode.find("\"follow\""), 8, "\"hover\"");
    auto bm = parseMissionJson(badMode, "mode.json");
    ASSERT_FALSE(bm.ok());
    EXPECT_NE(bm.error().message.find("terrain.mode: unknown terrain mode \"hover\""), std::string::npos);
}

TEST(TerrainFormats, RelativeDemPathIsBesideTheMissionFile) {
    const auto dir = std::filesystem::temp_directory_path() / "pf_terrain_mission_dir";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "site.tif") << "x"; // only its existence matters here
    mission::Mission m = fileMission();
    m.terrain.mode = mission::TerrainMode::Follow;
    m.terrain.demPath = "site.tif";
    const std::string path = (dir / "m.json").string();
    ASSERT_TRUE(writeMissionFile(m, path).ok());
    auto back = readMissionFile(path);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->terrain.demPath, (dir / "site.tif").string());
    m.terrain.demPath = "demo_dem.tif"; // not beside it: left for the bundled maps
    ASSERT_TRUE(writeMissionFile(m, path).ok());
    EXPECT_EQ(readMissionFile(path)->terrain.demPath, "demo_dem.tif");
}

} // namespace
} // namespace pf::io
