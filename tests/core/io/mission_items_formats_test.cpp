// Mission items shared by .plan, .waypoints and the upload: speed and gimbal items, distance
// triggering of lanes (lanes found in the geometry, photos rebuilt on reading), close waypoints.
#include "core/io/mission_items.h"

#include "core/geo/geodesic.h"
#include "core/geo/local_frame.h"
#include "core/io/qgc_plan.h"
#include "core/io/litchi_csv.h"
#include "core/io/qgc_wpl.h"
#include "core/io/trigger_lanes.h"
#include "tests/core/io/formats_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace pf;
using namespace pf::io;

namespace {

// Three lanes of photos exactly `spacing` apart along `headingDeg` and back, joined by turn
// waypoints; the second lane ends with an odd photo 7 m after its last regular one (moved out of a
// no-fly margin). Photos per lane: 9, 12 (+1 odd), 6.
route::Route laneRoute(double spacing, double headingDeg) {
    auto frame = *geo::LocalFrame::create({8.3290, 49.0115});
    const double h = headingDeg * 3.14159265358979323846 / 180.0;
    const geo::Vec2 dir{std::sin(h), std::cos(h)};
    const geo::Vec2 across{dir.y(), -dir.x()};
    route::Route r;
    r.aircraft = "Falcon 8";
    r.cruiseSpeedMps = 8;
    auto add = [&](geo::Vec2 p, route::WaypointKind k, double hdg) {
        route::Waypoint w;
        w.position = frame.toGeo(p);
        w.altitudeM = 40;
        w.headingDeg = hdg;
        w.kind = k;
        r.waypoints.push_back(w);
    };
    const int counts[] = {9, 12, 6};
    geo::Vec2 start{-100, -60};
    for (int lane = 0; lane < 3; ++lane) {
        const bool back = lane % 2 == 1;
        const geo::Vec2 d = back ? geo::Vec2(-dir) : dir;
        const double hdg = std::fmod(headingDeg + (back ? 180.0 : 0.0), 360.0);
        add(start - d * 10.0, route::WaypointKind::Turn, hdg);
        for (int k = 0; k < counts[lane]; ++k)
            add(start + d * (k * spacing), route::WaypointKind::Photo, hdg);
        geo::Vec2 end = start + d * ((counts[lane] - 1) * spacing);
        if (lane == 1) {
            end += d * 7.0;
            add(end, route::WaypointKind::Photo, hdg);
        }
        add(end + d * 10.0, route::WaypointKind::Turn, hdg);
        start = end + across * 25.0;
    }
    return r;
}

std::vector<route::Waypoint> photosOf(const route::Route& r) {
    std::vector<route::Waypoint> out;
    for (const auto& w : r.waypoints)
        if (w.kind == route::WaypointKind::Photo)
            out.push_back(w);
    return out;
}

int count(const std::vector<MissionItem>& items, int command) {
    int n = 0;
    for (const auto& it : items)
        n += it.command == command;
    return n;
}

} // namespace

TEST(TriggerLanes, FindsTheLanesAndLeavesTheOddLastPhotoOut) {
    const route::Route r = laneRoute(19.9, 33.0);
    const auto lanes = findTriggerLanes(r.waypoints);
    ASSERT_EQ(lanes.size(), 3u);
    EXPECT_EQ(lanes[0].photos(), 9u);
    EXPECT_EQ(lanes[1].photos(), 12u);
    EXPECT_EQ(lanes[2].photos(), 6u);
    for (const auto& l : lanes)
        EXPECT_NEAR(l.spacingM, 19.9, 0.005);
    // The odd photo follows lane 2 and is not in it.
    EXPECT_EQ(r.waypoints[lanes[1].last + 1].kind, route::WaypointKind::Photo);
}

TEST(TriggerLanes, AKinkOrUnequalSpacingIsNotALane) {
    route::Route r = laneRoute(20.0, 90.0);
    auto frame = *geo::LocalFrame::create(r.waypoints[1].position);
    // Lane 1 photo 5 moves 20 cm sideways: the lane breaks around it.
    geo::Vec2 p = frame.toLocal(r.waypoints[5].position);
    r.waypoints[5].position = frame.toGeo(p + geo::Vec2(0, 0.2));
    // Lane 3: one spacing 3 cm longer.
    const auto lanes0 = findTriggerLanes(laneRoute(20.0, 90.0).waypoints);
    const std::size_t l3 = lanes0[2].first + 3;
    for (std::size_t k = l3; k <= lanes0[2].last; ++k) {
        geo::Vec2 q = frame.toLocal(r.waypoints[k].position);
        r.waypoints[k].position = frame.toGeo(q + geo::Vec2(-0.03, 0)); // lane 3 flies west
    }
    for (const auto& l : findTriggerLanes(r.waypoints)) {
        EXPECT_FALSE(l.first <= 5 && l.last >= 5 && l.first < 5 && l.last > 5 && l.photos() == 9u);
        EXPECT_FALSE(l.first < l3 && l.last >= l3) << l.first << ".." << l.last;
    }
}

TEST(TriggerLanes, CloseWaypointsAreMergedKeepingThePhoto) {
    route::Route r = laneRoute(20.0, 0.0);
    route::Waypoint dup = r.waypoints[3];
    dup.kind = route::WaypointKind::Turn;
    dup.position.lon += 2e-8; // about 1.5 mm
    r.waypoints.insert(r.waypoints.begin() + 3, dup);
    std::size_t merged = 0;
    auto out = mergeCloseWaypoints(r.waypoints, 0.1, &merged);
    EXPECT_EQ(merged, 1u);
    ASSERT_EQ(out.size(), r.waypoints.size() - 1);
    EXPECT_EQ(out[3].kind, route::WaypointKind::Photo);
    EXPECT_EQ(out[3].position, r.waypoints[4].position);
    // At 0.6 m (DJI) two photos 0.5 m apart become one.
    route::Route two = r;
    two.waypoints[5].position = geo::geodesicDirect(two.waypoints[4].position, 90, 0.5);
    EXPECT_EQ(mergeCloseWaypoints(two.waypoints, 0.6).size(), two.waypoints.size() - 2);
}

TEST(MissionItems, DistanceTriggerWritesOnlyLaneEndsAndRereadsTheSamePhotos) {
    const route::Route r = laneRoute(19.9, 33.0);
    const auto planned = photosOf(r);
    ASSERT_EQ(planned.size(), 9u + 13u + 6u);
    ExportContext ctx = makeExportContext(test::demoMission(), {r});
    ExportOptions perPhoto;
    ExportOptions byDistance;
    byDistance.trigger = CameraTrigger::Distance;
    const auto a = *missionItems(ctx, 0, perPhoto);
    const auto b = *missionItems(ctx, 0, byDistance);
    EXPECT_EQ(count(a, mav::kImageStartCapture), 28);
    EXPECT_EQ(count(b, mav::kDoSetCamTriggDist), 6); // on and off per lane
    EXPECT_EQ(count(b, mav::kImageStartCapture), 1); // the odd photo
    EXPECT_EQ(count(b, mav::kNavWaypoint), 6 + 6 + 1);
    EXPECT_LT(b.size(), a.size() / 2);

    const std::string dir = test::scratchDir("trigger_lanes");
    for (const char* ext : {".plan", ".waypoints"}) {
        const std::string path = dir + "/lanes" + ext;
        if (std::string(ext) == ".plan")
            ASSERT_TRUE(writeQgcPlan(ctx, 0, path, byDistance).ok());
        else
            ASSERT_TRUE(writeQgcWpl(ctx, 0, path, byDistance).ok());
        auto back = std::string(ext) == ".plan" ? readQgcPlan(path) : readQgcWpl(path);
        ASSERT_TRUE(back.ok()) << back.error().message;
        const auto photos = photosOf(back->routes.at(0));
        ASSERT_EQ(photos.size(), planned.size()) << ext;
        for (std::size_t i = 0; i < photos.size(); ++i)
            EXPECT_LT(geo::geodesicDistance(photos[i].position, planned[i].position), 0.02)
                << ext << " photo " << i;
        EXPECT_DOUBLE_EQ(back->routes[0].cruiseSpeedMps, 8.0);
    }
}

TEST(MissionItems, GimbalManagerRatesAreNullInPlanAndNaNInWaypoints) {
    std::mt19937 rng(41);
    ExportContext ctx = makeExportContext(test::demoMission(), {test::randomRoute(rng, "A")});
    ExportOptions opt;
    opt.gimbal = GimbalCommand::GimbalManagerPitchYaw;
    opt.homeElevationM = 112.5;
    const std::string plan = *qgcPlanJson(ctx, 0, opt);
    EXPECT_NE(plan.find("null"), std::string::npos);
    EXPECT_TRUE(test::qgcPlanViolations(plan).empty());
    CPLJSONDocument doc;
    ASSERT_TRUE(doc.LoadMemory(plan));
    const CPLJSONObject m = doc.GetRoot().GetObj("mission");
    const CPLJSONObject g = m.GetArray("items")[2];
    EXPECT_EQ(g.GetInteger("command"), 1000);
    EXPECT_DOUBLE_EQ(g.GetArray("params")[0].ToDouble(), -90.0);
    EXPECT_EQ(g.GetArray("params")[2].GetType(), CPLJSONObject::Type::Null);
    EXPECT_DOUBLE_EQ(m.GetArray("plannedHomePosition")[2].ToDouble(), 112.5);
    const CPLJSONArray rally = doc.GetRoot().GetObj("rallyPoints").GetArray("points");
    EXPECT_DOUBLE_EQ(rally[0].ToArray()[2].ToDouble(), rallyAltitude(ctx.routes[0]));
    EXPECT_GT(rally[0].ToArray()[2].ToDouble(), 0.0);

    const std::string wpl = *qgcWplText(ctx, 0, opt);
    EXPECT_NE(wpl.find("\t1000\t-90\t0\tNaN\tNaN\t"), std::string::npos) << wpl.substr(0, 400);
    EXPECT_NE(wpl.find("\t112.5\t1\n"), std::string::npos); // home line AMSL
    auto back = parseQgcWpl(wpl, "g.waypoints");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->routes[0].waypoints.size(), mergeCloseWaypoints(ctx.routes[0].waypoints, 0.1).size());
    // Heights above home are kept although the home line is at 112.5 m above sea level.
    EXPECT_NEAR(back->routes[0].waypoints[0].altitudeM, ctx.routes[0].waypoints[0].altitudeM, 1e-4);
}

// Oblique photos: the gimbal items pitch the camera to -90 + the tilt in .plan, .waypoints and
// Litchi; the tilt is read back from the gimbal item and written again on conversion; a plane's
// camera still looks straight down.
TEST(MissionItems, ObliquePhotosPitchTheGimbalAndReadBack) {
    std::mt19937 rng(43);
    mission::Mission m = test::demoMission();
    m.options.cameraTiltDeg = 25.0;
    const ExportContext ctx = makeExportContext(m, {test::randomRoute(rng, "A")});
    const auto pitchOf = [](const std::vector<MissionItem>& items, int command) {
        for (const auto& it : items)
            if (it.command == command)
                return it.params[0];
        return std::nan("");
    };
    auto items = missionItems(ctx, 0);
    ASSERT_TRUE(items.ok()) << items.error().message;
    EXPECT_DOUBLE_EQ(pitchOf(*items, mav::kDoMountControl), -65.0);
    ExportOptions manager;
    manager.gimbal = GimbalCommand::GimbalManagerPitchYaw;
    auto v2 = missionItems(ctx, 0, manager);
    ASSERT_TRUE(v2.ok());
    EXPECT_DOUBLE_EQ(pitchOf(*v2, mav::kDoGimbalManagerPitchYaw), -65.0);
    EXPECT_EQ(cameraTiltFromItems(*v2), 25.0);

    auto plan = qgcPlanJson(ctx, 0, ExportOptions{});
    ASSERT_TRUE(plan.ok());
    EXPECT_TRUE(test::qgcPlanViolations(*plan).empty());
    auto back = parseQgcPlan(*plan, "o.plan");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->cameraTiltDeg, 25.0);
    const ExportContext again = contextFromImport(*back);
    EXPECT_DOUBLE_EQ(again.gimbalPitchDeg(0), -65.0);
    auto wpl = qgcWplText(again, 0, ExportOptions{});
    ASSERT_TRUE(wpl.ok());
    EXPECT_NE(wpl->find("\t205\t-65\t0\t0\t0\t"), std::string::npos) << wpl->substr(0, 400);
    auto wplBack = parseQgcWpl(*wpl, "o.waypoints");
    ASSERT_TRUE(wplBack.ok());
    EXPECT_EQ(wplBack->cameraTiltDeg, 25.0);

    auto csv = litchiCsvText(ctx, 0);
    ASSERT_TRUE(csv.ok()) << csv.error().message;
    std::istringstream rows(*csv);
    std::string row;
    std::getline(rows, row); // the header
    int checked = 0;
    while (std::getline(rows, row)) {
        std::vector<std::string> cols;
        std::stringstream cells(row);
        for (std::string c; std::getline(cells, c, ',');)
            cols.push_back(c);
        ASSERT_GT(cols.size(), 7u);
        EXPECT_EQ(cols[7], "-65") << row; // gimbalpitchangle
        ++checked;
    }
    EXPECT_GT(checked, 5);
    auto csvBack = parseLitchiCsv(*csv, "o.csv");
    ASSERT_TRUE(csvBack.ok()) << csvBack.error().message;
    EXPECT_EQ(csvBack->cameraTiltDeg, 25.0);

    // Nadir: no tilt read back from a pitch of -90.
    const ExportContext nadir = makeExportContext(test::demoMission(), {ctx.routes[0]});
    auto down = missionItems(nadir, 0);
    ASSERT_TRUE(down.ok());
    EXPECT_DOUBLE_EQ(pitchOf(*down, mav::kDoMountControl), -90.0);
    EXPECT_EQ(cameraTiltFromItems(*down), 0.0);
}

// A .plan whose distance trigger would fire every 0.5 m along 11,000 km of lane (found by the
// fuzzer: it filled 2 GB) is refused by name, as is the same in a .waypoints file.
TEST(MissionItems, ATriggerThatWouldMakeMillionsOfPhotosIsRefused) {
    const std::string path = std::string(PF_TEST_DATA_DIR) + "/fuzz/qgc_plan/long_triggered_lane.plan";
    auto plan = readQgcPlan(path);
    ASSERT_FALSE(plan.ok());
    EXPECT_NE(plan.error().message.find("mission.items: a camera trigger distance of 0.5 m over"),
              std::string::npos)
        << plan.error().message;
    std::string wpl = "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t0\t0\t0\t1\n";
    wpl += "1\t0\t3\t16\t0\t0\t0\t0\t0.0\t0.0\t50\t1\n";
    wpl += "2\t0\t3\t206\t0.01\t0\t1\t0\t0\t0\t0\t1\n";
    wpl += "3\t0\t3\t16\t0\t0\t0\t0\t0.0\t90.0\t50\t1\n";
    wpl += "4\t0\t3\t206\t0\t0\t1\t0\t0\t0\t0\t1\n";
    auto w = parseQgcWpl(wpl, "long.waypoints");
    ASSERT_FALSE(w.ok());
    EXPECT_NE(w.error().message.find("long.waypoints: a camera trigger distance of 0.01 m"), std::string::npos)
        << w.error().message;
}

TEST(MissionItems, FenceAndRallyItems) {
    std::mt19937 rng(42);
    ExportContext ctx = makeExportContext(test::demoMission(), {test::randomRoute(rng, "A")});
    const auto fence = fenceItems(ctx);
    ASSERT_EQ(fence.size(), 4u + 16u);
    EXPECT_EQ(fence[0].command, mav::kFenceVertexExclusion);
    EXPECT_DOUBLE_EQ(fence[0].params[0], 4.0);
    EXPECT_DOUBLE_EQ(fence[4].params[0], 16.0);
    EXPECT_DOUBLE_EQ(fence[0].params[4], 49.0118201);
    const auto rally = rallyItems(ctx, 0);
    ASSERT_EQ(rally.size(), 1u);
    EXPECT_EQ(rally[0].command, mav::kRallyPoint);
    EXPECT_DOUBLE_EQ(rally[0].params[5], ctx.mission.home->lon);
}

#include "core/io/litchi_csv.h"
#include "core/io/waypoint_formats.h"

#include <fstream>

TEST(LitchiSplit, RoutesOver99WaypointsComeAsNumberedMissionsThatJoinUp) {
    route::Route r = laneRoute(5.0, 10.0); // 28 photos and 6 turns
    route::Route big = r;
    for (int k = 0; k < 6; ++k) // 238 waypoints, all at least 5 m apart
        for (auto w : r.waypoints) {
            w.position.lat += 0.0012 * (k + 1);
            big.waypoints.push_back(w);
        }
    ASSERT_EQ(big.waypoints.size(), 238u);
    ExportContext ctx = makeExportContext(test::demoMission(), {big});
    const std::string dir = test::scratchDir("litchi_split");
    auto report = exportRouteFiles(ctx, 0, WaypointFormat::LitchiCsv, dir + "/m-Falcon_8.csv");
    ASSERT_TRUE(report.ok()) << report.error().message;
    ASSERT_EQ(report->files.size(), 3u); // 99 + 98 + 41 new waypoints
    EXPECT_EQ(report->files[0], dir + "/m-Falcon_8-part1.csv");
    ASSERT_EQ(report->notes.size(), 1u);
    EXPECT_NE(report->notes[0].find("at most 99"), std::string::npos) << report->notes[0];
    EXPECT_NE(report->notes[0].find("3 missions"), std::string::npos) << report->notes[0];
    std::size_t photos = 0;
    std::vector<route::Waypoint> joined;
    for (std::size_t f = 0; f < report->files.size(); ++f) {
        auto part = readLitchiCsv(report->files[f]);
        ASSERT_TRUE(part.ok()) << part.error().message;
        const auto& w = part->routes[0].waypoints;
        EXPECT_LE(w.size(), 99u);
        if (f > 0) { // starts where the previous ended, without a second photo there
            EXPECT_EQ(w.front().position, joined.back().position);
        }
        for (std::size_t i = f > 0 ? 1 : 0; i < w.size(); ++i)
            joined.push_back(w[i]);
        for (const auto& x : w)
            photos += x.kind == route::WaypointKind::Photo;
    }
    EXPECT_EQ(joined.size(), big.waypoints.size());
    EXPECT_EQ(photos, photosOf(big).size());
}

TEST(LitchiSplit, WaypointsCloserThanDjisMinimumAreMerged) {
    route::Route r = laneRoute(20.0, 45.0);
    route::Waypoint near = r.waypoints[2];
    near.kind = route::WaypointKind::Turn;
    near.position = geo::geodesicDirect(near.position, 0, 0.4); // DJI refuses < 0.6 m
    r.waypoints.insert(r.waypoints.begin() + 3, near);
    ExportContext ctx = makeExportContext(test::demoMission(), {r});
    const std::string dir = test::scratchDir("litchi_merge");
    auto report = exportRouteFiles(ctx, 0, WaypointFormat::LitchiCsv, dir + "/m.csv");
    ASSERT_TRUE(report.ok());
    ASSERT_EQ(report->files.size(), 1u);
    ASSERT_EQ(report->notes.size(), 1u);
    EXPECT_NE(report->notes[0].find("1 waypoint closer than 0.6 m"), std::string::npos) << report->notes[0];
    auto back = readLitchiCsv(dir + "/m.csv");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->routes[0].waypoints.size(), r.waypoints.size() - 1);
    for (std::size_t i = 1; i < back->routes[0].waypoints.size(); ++i)
        EXPECT_GE(geo::geodesicDistance(back->routes[0].waypoints[i - 1].position,
                                        back->routes[0].waypoints[i].position),
                  0.6);
    // The .plan keeps it (0.4 m is above its 0.1 m minimum).
    auto plan = exportRouteFiles(ctx, 0, WaypointFormat::QgcPlan, dir + "/m.plan");
    ASSERT_TRUE(plan.ok());
    EXPECT_TRUE(plan->notes.empty());
}

#include "core/io/gpx.h"
#include "core/io/kml_export.h"
#include "core/io/waypoint_geojson.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

double signedArea(const CPLJSONArray& ring) {
    double a = 0;
    for (int i = 0; i + 1 < ring.Size(); ++i) {
        const CPLJSONArray p = ring[i].ToArray(), q = ring[i + 1].ToArray();
        a += p[0].ToDouble() * q[1].ToDouble() - q[0].ToDouble() * p[1].ToDouble();
    }
    return a / 2;
}

} // namespace

TEST(ExportsAsFlown, KmlDrawsTheFlightAtItsHeightAboveTheGround) {
    std::mt19937 rng(61);
    ExportContext ctx = makeExportContext(test::demoMission(), {test::randomRoute(rng, "A")});
    const std::string dir = test::scratchDir("kml_alt");
    ASSERT_TRUE(writeKml(ctx, {0}, dir + "/a.kml").ok());
    const std::string kml = slurp(dir + "/a.kml");
    EXPECT_NE(kml.find("<altitudeMode>relativeToGround</altitudeMode>"), std::string::npos);
    EXPECT_NE(kml.find("<extrude>1</extrude>"), std::string::npos);
    // The path's third coordinates are the waypoint heights.
    GDALAllRegister();
    GDALDataset* ds = static_cast<GDALDataset*>(GDALOpenEx((dir + "/a.kml").c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr));
    ASSERT_NE(ds, nullptr);
    bool sawPath = false;
    for (auto* layer : ds->GetLayers())
        for (auto& f : *layer) {
            const OGRGeometry* g = f->GetGeometryRef();
            if (!g || wkbFlatten(g->getGeometryType()) != wkbLineString ||
                std::string(f->GetFieldAsString("name")).find(" path") == std::string::npos)
                continue;
            const auto* line = g->toLineString();
            ASSERT_EQ(line->getNumPoints(), int(ctx.routes[0].waypoints.size()));
            for (int i = 0; i < line->getNumPoints(); ++i)
                EXPECT_NEAR(line->getZ(i), ctx.routes[0].waypoints[std::size_t(i)].altitudeM, 1e-6);
            sawPath = true;
        }
    GDALClose(ds);
    EXPECT_TRUE(sawPath);
}

TEST(ExportsAsFlown, GpxSaysWhatItsElevationsAre) {
    std::mt19937 rng(62);
    ExportContext ctx = makeExportContext(test::demoMission(), {test::randomRoute(rng, "A"), test::randomRoute(rng, "B")});
    const std::string dir = test::scratchDir("gpx_meta");
    ASSERT_TRUE(writeGpx(ctx, {0, 1}, dir + "/a.gpx").ok());
    const std::string gpx = slurp(dir + "/a.gpx");
    const auto meta = gpx.find("<metadata>");
    ASSERT_NE(meta, std::string::npos);
    EXPECT_EQ(gpx.find("<metadata>", meta + 1), std::string::npos); // one metadata element
    EXPECT_LT(meta, gpx.find("<wpt"));
    EXPECT_NE(gpx.find(std::string("<desc>") + kGpxElevationNote + "</desc>"), std::string::npos);
    EXPECT_NE(gpx.find("<name>Rheinhafen training ground</name>"), std::string::npos);
    EXPECT_LT(gpx.find("<desc>"), gpx.find("<bounds")); // GPX 1.1 order: name, desc, ..., bounds
    auto back = readGpx(dir + "/a.gpx");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->routes.size(), 2u);
}

TEST(ExportsAsFlown, GeoJsonFollowsRfc7946) {
    std::mt19937 rng(63);
    mission::Mission m = test::demoMission();
    std::reverse(m.area.outer.begin(), m.area.outer.end()); // clockwise in the mission
    geo::GeoRing hole = {{8.3300, 49.0126}, {8.3302, 49.0126}, {8.3302, 49.0128}, {8.3300, 49.0128}};
    m.area.holes.push_back(hole); // counter-clockwise in the mission
    ExportContext ctx = makeExportContext(m, {test::randomRoute(rng, "A")});
    const std::string dir = test::scratchDir("geojson_rfc");
    ASSERT_TRUE(writeWaypointGeoJson(ctx, {0}, dir + "/a.geojson").ok());
    CPLJSONDocument doc;
    ASSERT_TRUE(doc.Load(dir + "/a.geojson"));
    EXPECT_FALSE(doc.GetRoot().GetObj("crs").IsValid());
    const CPLJSONArray features = doc.GetRoot().GetArray("features");
    int polygons = 0;
    for (int i = 0; i < features.Size(); ++i) {
        const CPLJSONObject g = features[i].GetObj("geometry");
        if (g.GetString("type") != "Polygon")
            continue;
        const CPLJSONArray rings = g.GetArray("coordinates");
        EXPECT_GT(signedArea(rings[0].ToArray()), 0) << "outer ring of feature " << i;
        for (int h = 1; h < rings.Size(); ++h)
            EXPECT_LT(signedArea(rings[h].ToArray()), 0) << "hole of feature " << i;
        ++polygons;
    }
    EXPECT_EQ(polygons, 3);
    // Positions still read back exactly.
    auto back = readWaypointGeoJson(dir + "/a.geojson");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->routes[0].waypoints[3].position, ctx.routes[0].waypoints[3].position);
}
