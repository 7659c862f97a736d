#include "core/io/waypoint_formats.h"

#include "core/geo/geodesic.h"
#include "core/geo/polygon_ops.h"
#include "core/io/gpx.h"
#include "core/io/kml_export.h"
#include "core/io/litchi_csv.h"
#include "core/io/qgc_plan.h"
#include "core/io/qgc_wpl.h"
#include "core/io/waypoint_geojson.h"
#include "core/geo/local_frame.h"
#include "core/mission/route_check.h"
#include "tests/core/io/formats_test_util.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace pf;
using namespace pf::io;

namespace {

ExportContext randomContext(std::mt19937& rng, int routes) {
    std::vector<route::Route> rs;
    for (int i = 0; i < routes; ++i)
        rs.push_back(test::randomRoute(rng, "Falcon 8 #" + std::to_string(i + 1)));
    return makeExportContext(test::demoMission(), rs);
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

} // namespace

// Every importable format gives back the same waypoints, in order, for many random routes.
TEST(WaypointFormats, RoundTripEveryImportableFormat) {
    const std::string dir = test::scratchDir("roundtrip");
    std::mt19937 rng(20261121);
    for (int trial = 0; trial < 12; ++trial) {
        ExportContext ctx = randomContext(rng, 1);
        for (const auto& info : waypointFormats()) {
            // A .kmz needs a DJI Enterprise aircraft (these random routes have none): its round trips
            // on planned missions are in wpml_kmz_test.cpp.
            if (!info.canImport || info.format == WaypointFormat::WpmlKmz)
                continue;
            const std::string path = dir + "/route" + std::to_string(trial) + info.extension;
            ASSERT_TRUE(exportRoute(ctx, 0, info.format, path).ok()) << info.name;
            auto back = importWaypoints(path);
            ASSERT_TRUE(back.ok()) << info.name << ": " << back.error().message;
            ASSERT_EQ(back->routes.size(), 1u) << info.name;
            const bool kindsExact =
                info.format == WaypointFormat::Gpx || info.format == WaypointFormat::GeoJson;
            test::expectSameWaypoints(ctx.routes[0].waypoints, back->routes[0].waypoints,
                                      kindsExact,
                                      std::string(info.name) + " trial " + std::to_string(trial));
        }
    }
}

TEST(WaypointFormats, CombinedFilesKeepEveryAircraftApart) {
    const std::string dir = test::scratchDir("combined");
    std::mt19937 rng(7);
    ExportContext ctx = randomContext(rng, 3);
    for (auto fmt : {WaypointFormat::Gpx, WaypointFormat::GeoJson}) {
        const std::string path = dir + "/all" + formatInfo(fmt).extension;
        ASSERT_TRUE(exportCombined(ctx, fmt, path).ok());
        auto back = importWaypoints(path);
        ASSERT_TRUE(back.ok()) << back.error().message;
        ASSERT_EQ(back->routes.size(), 3u);
        for (std::size_t i = 0; i < 3; ++i) {
            EXPECT_EQ(back->routes[i].aircraft, ctx.routes[i].aircraft);
            test::expectSameWaypoints(ctx.routes[i].waypoints, back->routes[i].waypoints, true,
                                      formatInfo(fmt).name);
        }
    }
    auto single = exportCombined(ctx, WaypointFormat::QgcPlan, dir + "/all.plan");
    ASSERT_FALSE(single.ok());
    EXPECT_EQ(single.error().message,
              "a QGroundControl mission (.plan JSON) file holds one aircraft's mission; write "
              "one file per aircraft");
}

TEST(WaypointFormats, ExportAllWritesOneFilePerAircraftPlusCombined) {
    const std::string dir = test::scratchDir("all");
    std::mt19937 rng(8);
    ExportContext ctx = randomContext(rng, 2);
    auto kml = exportAll(ctx, WaypointFormat::Kml, dir, "mission");
    ASSERT_TRUE(kml.ok()) << kml.error().message;
    ASSERT_EQ(kml->size(), 3u);
    EXPECT_EQ((*kml)[0], dir + "/mission-Falcon_8_1.kml");
    EXPECT_EQ((*kml)[2], dir + "/mission.kml");
    auto plan = exportAll(ctx, WaypointFormat::QgcPlan, dir, "mission");
    ASSERT_TRUE(plan.ok());
    EXPECT_EQ(plan->size(), 2u); // no combined .plan
    for (const auto& p : *kml)
        EXPECT_TRUE(std::filesystem::exists(p)) << p;
}

// File names carry no run of '_' and none at either end; two aircraft whose names read alike in a
// file name never share a file.
TEST(WaypointFormats, FileNamesCollapseUnsafeCharactersAndStayApart) {
    EXPECT_EQ(fileNameSafe("DJI Mavic 3 Enterprise #1"), "DJI_Mavic_3_Enterprise_1");
    EXPECT_EQ(fileNameSafe("  #Falcon 8 (spare) "), "Falcon_8_spare");
    EXPECT_EQ(fileNameSafe("a__b"), "a_b");
    EXPECT_EQ(fileNameSafe("Drohne Süd"), "Drohne_S_d");
    EXPECT_EQ(fileNameSafe("Дрон"), "aircraft");
    std::mt19937 rng(3);
    std::vector<route::Route> rs;
    for (const char* name : {"Falcon 8 #1", "Falcon 8 1", "Phantom", "Falcon_8 1"})
        rs.push_back(test::randomRoute(rng, name));
    const ExportContext ctx = makeExportContext(test::demoMission(), rs);
    EXPECT_EQ(routeFileStem(ctx, 0), "Falcon_8_1");
    EXPECT_EQ(routeFileStem(ctx, 1), "Falcon_8_1_2");
    EXPECT_EQ(routeFileStem(ctx, 2), "Phantom");
    EXPECT_EQ(routeFileStem(ctx, 3), "Falcon_8_1_3");
    EXPECT_EQ(routeFileName(ctx, 1, WaypointFormat::QgcPlan), "Falcon_8_1_2.plan");
}

TEST(WaypointFormats, FormatNamesAndExtensions) {
    EXPECT_EQ(*formatFromName("PLAN"), WaypointFormat::QgcPlan);
    EXPECT_EQ(*formatFromName("json"), WaypointFormat::GeoJson);
    EXPECT_EQ(*formatFromName("litchi"), WaypointFormat::LitchiCsv);
    EXPECT_EQ(*formatFromPath("a/b/Edited.WAYPOINTS"), WaypointFormat::QgcWpl);
    EXPECT_EQ(*formatFromPath("x.json"), WaypointFormat::GeoJson);
    auto bad = formatFromName("shp");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message,
              "unknown waypoint format \"shp\" (known: plan, waypoints, kml, gpx, geojson, csv, kmz)");
    auto noExt = formatFromPath("dir.v2/route");
    ASSERT_FALSE(noExt.ok());
    EXPECT_EQ(noExt.error().message,
              "dir.v2/route: cannot tell the waypoint format from the extension \"\" (use "
              ".plan, .waypoints, .kml, .gpx, .geojson, .json, .csv or .kmz)");
    auto list = formatListFromString("plan, kml,gpx,plan");
    ASSERT_TRUE(list.ok());
    EXPECT_EQ(list->size(), 3u);
    auto badList = formatListFromString("plan,dxf");
    ASSERT_FALSE(badList.ok());
    EXPECT_EQ(badList.error().message,
              "unknown waypoint format \"dxf\" (known: plan, waypoints, kml, gpx, geojson, csv, kmz)");
    auto kml = importWaypoints("x.kml");
    ASSERT_FALSE(kml.ok());
    EXPECT_EQ(kml.error().code, ErrorCode::Unsupported);
}

TEST(WaypointFormats, ExportRejectsMissingOrEmptyRoutes) {
    ExportContext ctx =
        makeExportContext(test::demoMission(), {route::Route{"Empty", {}, 5.0, {}}});
    auto e = qgcPlanJson(ctx, 0);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().message, "Empty: the route has no waypoints to export");
    auto missing = qgcWplText(ctx, 3);
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().message, "there is no route 4 to export");
}

TEST(QgcWpl, WritesTheMissionPlannerLayout) {
    std::mt19937 rng(3);
    ExportContext ctx = randomContext(rng, 1);
    auto text = qgcWplText(ctx, 0);
    ASSERT_TRUE(text.ok());
    std::istringstream in(*text);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "QGC WPL 110");
    std::getline(in, line);
    EXPECT_EQ(line.rfind("0\t1\t0\t16\t", 0), 0u) << line; // home: index 0, current 1, frame 0
    int n = 1, photos = 0, captures = 0;
    while (std::getline(in, line)) {
        int fields = 1;
        for (char c : line)
            fields += c == '\t';
        EXPECT_EQ(fields, 12) << line;
        // Items with a position in frame 3 (above home), commands without one in frame 2
        // (MAV_FRAME_MISSION), exactly as they are uploaded.
        const bool command = line.find("\t2000\t") != std::string::npos ||
                             line.find("\t178\t") != std::string::npos ||
                             line.find("\t205\t") != std::string::npos ||
                             line.find("\t20\t0\t") != std::string::npos;
        EXPECT_EQ(line.rfind(std::to_string(n++) + (command ? "\t0\t2\t" : "\t0\t3\t"), 0), 0u) << line;
        captures += line.find("\t2000\t") != std::string::npos;
    }
    for (const auto& w : ctx.routes[0].waypoints)
        photos += w.kind == route::WaypointKind::Photo;
    EXPECT_EQ(captures, photos);
}

TEST(QgcWpl, ReadsWhatMissionPlannerWrites) {
    // CRLF line endings, home with current = 1 and its AMSL altitude, no final newline, a digicam
    // trigger, one waypoint in frame 0 (AMSL: 157.5 - 112.5 = 45 m above home).
    auto r = readQgcWpl(std::string(PF_TEST_DATA_DIR) + "/formats/mission_planner.waypoints");
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_TRUE(r->home.has_value());
    EXPECT_DOUBLE_EQ(r->home->lat, 49.010741);
    EXPECT_DOUBLE_EQ(r->home->lon, 8.3270554);
    ASSERT_EQ(r->routes.size(), 1u);
    const auto& w = r->routes[0].waypoints;
    ASSERT_EQ(w.size(), 3u);
    EXPECT_DOUBLE_EQ(w[0].position.lon, 8.328);
    EXPECT_DOUBLE_EQ(w[0].altitudeM, 40.0);
    EXPECT_EQ(w[0].kind, route::WaypointKind::Photo); // DO_DIGICAM_CONTROL follows it
    EXPECT_EQ(w[1].kind, route::WaypointKind::Turn);  // between two photos
    EXPECT_DOUBLE_EQ(w[1].altitudeM, 45.5);
    EXPECT_EQ(w[2].kind, route::WaypointKind::Photo); // IMAGE_START_CAPTURE follows it
    EXPECT_NEAR(w[2].altitudeM, 45.0, 1e-9);
    EXPECT_DOUBLE_EQ(w[2].headingDeg, 270.0);
}

TEST(QgcPlan, ReadsAPlanWrittenByQGroundControl) {
    auto r = readQgcPlan(std::string(PF_TEST_DATA_DIR) + "/formats/qgc_written.plan");
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->routes.size(), 1u);
    const auto& w = r->routes[0].waypoints;
    ASSERT_EQ(w.size(), 2u);
    EXPECT_EQ(w[0].kind, route::WaypointKind::Photo);
    EXPECT_EQ(w[1].kind, route::WaypointKind::Transit); // after the last photo
    EXPECT_DOUBLE_EQ(r->routes[0].cruiseSpeedMps, 8.0);
    EXPECT_DOUBLE_EQ(r->home->lon, 8.3270554);
}

TEST(LitchiCsv, HeaderHasTheHubsColumnsAndRowsMatchIt) {
    const std::string h = litchiCsvHeader();
    EXPECT_EQ(
        h.rfind("latitude,longitude,altitude(m),heading(deg),curvesize(m),rotationdir,gimbalmode,"
                "gimbalpitchangle,actiontype1,actionparam1,actiontype2,",
                0),
        0u);
    EXPECT_NE(
        h.find(",actiontype15,actionparam15,altitudemode,speed(m/s),poi_latitude,poi_longitude,"
               "poi_altitude(m),poi_altitudemode,photo_timeinterval,photo_distinterval"),
        std::string::npos);
    std::mt19937 rng(9);
    ExportContext ctx = randomContext(rng, 1);
    auto text = litchiCsvText(ctx, 0);
    ASSERT_TRUE(text.ok());
    std::istringstream in(*text);
    std::string line;
    std::getline(in, line);
    std::size_t i = 0;
    while (std::getline(in, line)) {
        const auto fields = std::count(line.begin(), line.end(), ',') + 1;
        EXPECT_EQ(fields, 46);
        const bool photo = ctx.routes[0].waypoints[i++].kind == route::WaypointKind::Photo;
        // A stop corner's "stay for" (action 0, 1000 ms) comes first, then the photo if any.
        const std::string actions = photo ? "1,0,-1,0," : "-1,0,-1,0,";
        EXPECT_TRUE(line.find(",2,-90," + actions) != std::string::npos ||
                    line.find(",2,-90,0,1000," + actions) != std::string::npos)
            << line;
    }
    EXPECT_EQ(i, ctx.routes[0].waypoints.size());
    auto hub = readLitchiCsv(std::string(PF_TEST_DATA_DIR) + "/formats/litchi_hub.csv");
    ASSERT_TRUE(hub.ok()) << hub.error().message;
    ASSERT_EQ(hub->routes[0].waypoints.size(), 3u);
    EXPECT_DOUBLE_EQ(hub->routes[0].cruiseSpeedMps, 8.0);
    EXPECT_EQ(hub->routes[0].waypoints[2].kind, route::WaypointKind::Transit);
}

TEST(Gpx, PlainWaypointsWithoutHeadingsHeadForTheNextPoint) {
    auto r = readGpx(std::string(PF_TEST_DATA_DIR) + "/formats/plain_waypoints.gpx");
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->routes.size(), 1u);
    const auto& w = r->routes[0].waypoints;
    ASSERT_EQ(w.size(), 2u);
    EXPECT_NEAR(w[0].headingDeg, 90.0, 0.01); // due east
    EXPECT_NEAR(w[1].headingDeg, 90.0, 0.01);
    EXPECT_DOUBLE_EQ(w[1].altitudeM, 41.0);
}

TEST(WaypointGeoJson, HandDrawnPointsTakeTheirAltitudeFromZ) {
    auto r = readWaypointGeoJson(std::string(PF_TEST_DATA_DIR) + "/formats/hand_drawn.geojson");
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->routes.size(), 1u);
    const auto& w = r->routes[0].waypoints;
    ASSERT_EQ(w.size(), 2u);
    EXPECT_DOUBLE_EQ(w[1].altitudeM, 42.0);
    EXPECT_EQ(w[0].kind, route::WaypointKind::Photo);
}

TEST(WaypointGeoJson, KeepsNoFlyZonesAndHome) {
    const std::string dir = test::scratchDir("geojson_zones");
    std::mt19937 rng(10);
    ExportContext ctx = randomContext(rng, 1);
    ASSERT_TRUE(writeWaypointGeoJson(ctx, {0}, dir + "/r.geojson").ok());
    auto r = readWaypointGeoJson(dir + "/r.geojson");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->noFlyZones.size(), 2u);
    EXPECT_EQ(r->noFlyZones[0].name, "Warehouse");
    EXPECT_EQ(r->noFlyZones[1].polygon.outer.size(), 16u);
    ASSERT_TRUE(r->home.has_value());
    EXPECT_NEAR(r->home->lon, 8.3270554, 1e-12);
}

TEST(Kml, FootprintCornersAreTheFootprintTurnedToTheHeading) {
    const geo::LonLat c{8.33, 49.012};
    const sensor::Footprint fp{60.0, 40.0}; // long side across the track
    for (double hdg : {0.0, 37.0, 90.0, 271.5}) {
        const auto ring = footprintCorners(c, hdg, fp);
        ASSERT_EQ(ring.size(), 4u);
        // Sides: along the track the short side, across it the long side.
        EXPECT_NEAR(geo::geodesicDistance(ring[0], ring[1]), 40.0, 0.01);
        EXPECT_NEAR(geo::geodesicDistance(ring[1], ring[2]), 60.0, 0.01);
        EXPECT_NEAR(geo::geodesicDistance(ring[0], ring[3]), 60.0, 0.01);
        // The side from corner 1 to 0 points along the heading.
        EXPECT_LE(test::angleDiffDeg(geo::initialBearingDeg(ring[1], ring[0]), hdg), 0.01);
    }
}

TEST(Kml, HasAFolderPerAircraftAndColouredStyles) {
    const std::string dir = test::scratchDir("kml");
    std::mt19937 rng(12);
    ExportContext ctx = randomContext(rng, 2);
    ctx.mission.aircraft.push_back({});
    ctx.mission.aircraft.back().name = "Falcon 8 #2";
    ctx.mission.aircraft.back().colour = "#12ab34";
    ASSERT_TRUE(exportCombined(ctx, WaypointFormat::Kml, dir + "/m.kml").ok());
    const std::string kml = slurp(dir + "/m.kml");
    EXPECT_NE(kml.find("<Folder"), std::string::npos);
    EXPECT_NE(kml.find("Falcon 8 #1"), std::string::npos);
    EXPECT_NE(kml.find("Falcon 8 #2"), std::string::npos);
    EXPECT_NE(kml.find("Warehouse"), std::string::npos);
    EXPECT_NE(kml.find("<Style"), std::string::npos);
    EXPECT_NE(kml.find("ff34ab12"), std::string::npos); // #12ab34 in KML's aabbggrr order
}

TEST(Kml, DrawsTheSmoothedTrajectoryOutsideTheBufferedZones) {
    const std::string dir = test::scratchDir("kml_traj");
    mission::Mission m = test::demoMission();
    route::Route r{"Falcon 8 #1", std::nullopt, 8.0, {}};
    // A tight, irregular zig-zag under the warehouse whose upper turns lie 0.3 m outside its 5 m
    // safety margin: the unconstrained curve swings into the margin.
    const double lons[] = {8.32920, 8.32930, 8.32934, 8.32950, 8.32952, 8.32966, 8.32970, 8.32990};
    const double lats[] = {49.011772, 49.0112, 49.011772, 49.0114,
                           49.011772, 49.0110, 49.011772, 49.0112};
    for (int i = 0; i < 8; ++i)
        r.waypoints.push_back({{lons[i], lats[i]}, 40, 90, route::WaypointKind::Photo});
    ExportContext ctx = makeExportContext(m, {r});
    ASSERT_TRUE(addTrajectories(ctx).ok());
    ASSERT_EQ(ctx.trajectories.size(), 1u);
    ASSERT_GT(ctx.trajectories[0].size(), r.waypoints.size());
    for (const auto& end :
         {ctx.trajectories[0].front(), ctx.trajectories[0].back()}) { // from home and back
        EXPECT_NEAR(end.lon, m.home->lon, 1e-9);
        EXPECT_NEAR(end.lat, m.home->lat, 1e-9);
    }
    auto frame = geo::LocalFrame::forArea(m.area);
    ASSERT_TRUE(frame.ok());
    const auto keepOut = route::keepOutZones({m.noFlyZones[0].polygon, m.noFlyZones[1].polygon},
                                             *frame, m.options.safetyMarginM);
    route::Route fromHome = r;
    fromHome.home = m.home;
    auto free = route::buildTrajectory(fromHome, *frame, {}, {});
    ASSERT_TRUE(free.ok());
    int freeIntrusions = 0;
    for (std::size_t i = 1; i < free->samples.size(); ++i)
        freeIntrusions +=
            geo::segmentCrossesInterior(keepOut, free->samples[i - 1].pos, free->samples[i].pos);
    ASSERT_GT(freeIntrusions, 0) << "the test needs a curve that would cut in";
    for (std::size_t i = 1; i < ctx.trajectories[0].size(); ++i)
        EXPECT_FALSE(geo::segmentCrossesInterior(keepOut,
                                                 frame->toLocal(ctx.trajectories[0][i - 1]),
                                                 frame->toLocal(ctx.trajectories[0][i])))
            << "sample " << i;
    ASSERT_TRUE(exportRoute(ctx, 0, WaypointFormat::Kml, dir + "/t.kml").ok());
    EXPECT_NE(slurp(dir + "/t.kml").find("Falcon 8 #1 trajectory"), std::string::npos);
}

// A Litchi CSV saved by a spreadsheet in a decimal-comma locale: ';' between fields, ',' in numbers.
TEST(LitchiCsv, ReadsASpreadsheetsSemicolonsAndDecimalCommas) {
    auto r = readLitchiCsv(std::string(PF_TEST_DATA_DIR) + "/formats/litchi_spreadsheet.csv");
    ASSERT_TRUE(r.ok()) << r.error().message;
    const auto& w = r->routes.at(0).waypoints;
    ASSERT_EQ(w.size(), 2u);
    EXPECT_DOUBLE_EQ(w[0].position.lat, 49.0108);
    EXPECT_DOUBLE_EQ(w[0].position.lon, 8.3272);
    EXPECT_DOUBLE_EQ(w[1].position.lat, 49.0109);
    EXPECT_DOUBLE_EQ(w[0].altitudeM, 40.0);
    EXPECT_EQ(w[0].kind, route::WaypointKind::Photo);
    EXPECT_EQ(w[1].kind, route::WaypointKind::Transit);
}

// Litchi takes no two waypoints closer than 0.6 m, so close ones are merged; round a no-fly zone's
// corner that moves the detour's corner waypoint onto the next one (a photo 0.55 m on) and cuts the
// corner into the safety margin: then the route is written as planned, with a note saying why.
TEST(LitchiCsv, CloseWaypointsStayWhenMergingWouldCutIntoAMargin) {
    const auto frame = *geo::LocalFrame::create({8.33, 49.01});
    auto at = [&](double x, double y) { return frame.toGeo(geo::Vec2(x, y)); };
    auto build = [&](bool withZone) {
        mission::Mission m;
        m.area = frame.toGeo(geo::Polygon{{{-40, -40}, {40, -40}, {40, 40}, {-40, 40}}, {}});
        if (withZone)
            m.noFlyZones.push_back({"Warehouse", frame.toGeo(geo::Polygon{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}})});
        m.options.safetyMarginM = 5.0;
        m.home = at(-30, 30);
        route::Route r;
        r.aircraft = "Falcon 8";
        // Round the zone's top-left corner 5.6 m out (a 5.6 m radius, corner at 135 degrees): clear
        // by 5.05 m; the photo 0.55 m past the corner waypoint would leave 4.90 m once merged into it.
        r.waypoints = {route::Waypoint(at(-5.6, 10.0), 30, 0, route::WaypointKind::Transit),
                       route::Waypoint(at(-3.96, 13.96), 30, 45, route::WaypointKind::Transit),
                       route::Waypoint(at(-3.41, 13.96), 30, 90, route::WaypointKind::Photo),
                       route::Waypoint(at(0.0, 15.6), 30, 90, route::WaypointKind::Photo)};
        return makeExportContext(m, {r});
    };
    const std::string dir = test::scratchDir("litchi_margin");
    const ExportContext zoned = build(true);
    ASSERT_EQ(mission::checkRoute(zoned.routes[0], mission::routeLimits(zoned.mission, zoned.routes[0])).noFly, 0);
    auto kept = exportRouteFiles(zoned, 0, WaypointFormat::LitchiCsv, dir + "/zoned.csv");
    ASSERT_TRUE(kept.ok()) << kept.error().message;
    ASSERT_EQ(kept->notes.size(), 1u);
    EXPECT_NE(kept->notes[0].find("kept as planned"), std::string::npos) << kept->notes[0];
    auto back = importWaypoints(dir + "/zoned.csv");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->routes[0].waypoints.size(), 4u);
    // Without the zone the same waypoints merge, as before.
    auto merged = exportRouteFiles(build(false), 0, WaypointFormat::LitchiCsv, dir + "/open.csv");
    ASSERT_TRUE(merged.ok()) << merged.error().message;
    ASSERT_EQ(merged->notes.size(), 1u);
    EXPECT_NE(merged->notes[0].find("merged into it"), std::string::npos) << merged->notes[0];
    back = importWaypoints(dir + "/open.csv");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->routes[0].waypoints.size(), 3u);
}
