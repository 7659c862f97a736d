// The DJI WPML .kmz export and reader: every exported file passes the documentation's checks
// (tests/core/io/wpml_checker), the route drawn from waylines.wpml is the plan's (positions and
// heights to 1 cm, the same photos), read back likewise; on the demo, a terrain mission and a
// fleet; the aircraft a format cannot fly; bad files; the DJI types in the catalog and the mission
// file.
#include "core/geo/geodesic.h"
#include "core/io/catalog.h"
#include "core/io/mission_export.h"
#include "core/io/mission_file.h"
#include "core/io/trigger_lanes.h"
#include "core/io/waypoint_formats.h"
#include "core/io/wpml_kmz.h"
#include "core/mission/plan_mission.h"
#include "core/mission/terrain_stage.h"

#include "tests/core/io/wpml_checker.h"
#include "tests/sample_missions.h"

#include <cpl_json.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <set>

namespace pf::io {
namespace {

const std::string kData = std::string(PF_TEST_DATA_DIR) + "/formats/";

const Catalog& catalog() {
    static const Catalog c = [] {
        auto r = loadDefaultCatalog();
        EXPECT_TRUE(r.ok()) << r.error().message;
        return r.ok() ? *r : Catalog{};
    }();
    return c;
}

// The mission file flown by the given catalog aircraft ("NAME:ALT").
mission::Mission withAircraft(const std::string& file,
                              const std::vector<std::pair<std::string, double>>& fleet) {
    auto m = readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/" + file);
    EXPECT_TRUE(m.ok()) << m.error().message;
    mission::Mission out = *m;
    out.aircraft.clear();
    for (const auto& [name, alt] : fleet) {
        auto a = test::catalogAircraft(catalog(), name, alt);
        EXPECT_TRUE(a.has_value()) << name;
        if (a)
            out.aircraft.push_back(*a);
    }
    return out;
}

std::string tempPath(const std::string& name) {
    return testing::TempDir() + name;
}

// Checks the .kmz at `path`, written for route i of ctx, against the documentation and the route,
// and reads it back. `notes`: the export's (a note about merged waypoints means the file flies the
// route with them merged). `lanes`: the route has lanes of equally spaced photos at one height (not
// over terrain, where each photo has its own height and keeps its waypoint).
void checkAndReadBack(const ExportContext& ctx, std::size_t i, const std::string& path,
                      const std::vector<std::string>& notes, bool lanes = true) {
    SCOPED_TRACE(ctx.routeLabel(i));
    // What the file must fly: the route, with waypoints closer than the format's minimum merged
    // when the export says it merged them.
    route::Route r = ctx.routes[i];
    const bool merged = std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
        return n.find("merged into it") != std::string::npos;
    });
    if (merged)
        r.waypoints =
            mergeCloseWaypoints(r.waypoints, formatInfo(WaypointFormat::WpmlKmz).minSpacingM);
    const test::WpmlCheck c = test::checkWpmlKmz(path);
    for (const auto& p : c.problems)
        ADD_FAILURE() << p;
    const auto* a = ctx.aircraftFor(i);
    EXPECT_EQ(c.droneEnum, a->dji->droneEnum);
    EXPECT_EQ(c.droneSubEnum, a->dji->subEnum);
    EXPECT_EQ(c.payloadEnum, *a->camera.djiPayloadEnum);
    std::size_t photos = 0;
    for (const auto& w : r.waypoints)
        photos += w.kind == route::WaypointKind::Photo;
    EXPECT_EQ(c.photos, photos);
    // Lanes of equally spaced photos are flown by distance: fewer waypoints than photos.
    if (lanes) {
        EXPECT_LT(c.waypoints.size(), r.waypoints.size());
    } else {
        EXPECT_EQ(c.waypoints.size(), r.waypoints.size());
    }
    // The route drawn from waylines.wpml is the plan's (heights compared where they are above
    // take-off).
    ASSERT_EQ(c.flown.size(), r.waypoints.size());
    const bool relative = c.executeHeightMode == "relativeToStartPoint";
    for (std::size_t k = 0; k < r.waypoints.size(); ++k) {
        EXPECT_LT(geo::geodesicDistance(c.flown[k].position, r.waypoints[k].position), 0.01) << k;
        if (relative) {
            EXPECT_NEAR(c.flown[k].executeHeightM, r.waypoints[k].altitudeM, 0.01) << k;
        }
        EXPECT_EQ(c.flown[k].photo, r.waypoints[k].kind == route::WaypointKind::Photo) << k;
    }
    auto back = readWpmlKmz(path);
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->routes.size(), 1u);
    const route::Route& b = back->routes[0];
    EXPECT_EQ(b.aircraft, a->model);
    ASSERT_EQ(b.waypoints.size(), r.waypoints.size());
    for (std::size_t k = 0; k < r.waypoints.size(); ++k) {
        EXPECT_LT(geo::geodesicDistance(b.waypoints[k].position, r.waypoints[k].position), 0.01)
            << k;
        EXPECT_NEAR(b.waypoints[k].altitudeM, r.waypoints[k].altitudeM, 0.01) << k;
        EXPECT_EQ(b.waypoints[k].kind == route::WaypointKind::Photo,
                  r.waypoints[k].kind == route::WaypointKind::Photo)
            << k;
    }
    EXPECT_NEAR(b.cruiseSpeedMps, std::min(r.cruiseSpeedMps, 15.0), 0.01);
    ASSERT_TRUE(back->home.has_value());
    EXPECT_LT(geo::geodesicDistance(*back->home, *ctx.homeFor(i)), 0.01);
}

// Exports route i on its own and checks it (checkAndReadBack).
void exportCheckAndReadBack(const ExportContext& ctx, std::size_t i, const std::string& name,
                            bool lanes = true) {
    const std::string path = tempPath(name);
    auto report = exportRouteFiles(ctx, i, WaypointFormat::WpmlKmz, path);
    ASSERT_TRUE(report.ok()) << report.error().message;
    ASSERT_EQ(report->files.size(), 1u);
    checkAndReadBack(ctx, i, path, report->notes, lanes);
}

// The DOS date and time of the first entry of a ZIP archive (its local file header), as a time.
std::time_t firstEntryTime(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char h[14] = {};
    in.read(reinterpret_cast<char*>(h), sizeof h);
    EXPECT_TRUE(in && h[0] == 'P' && h[1] == 'K' && h[2] == 3 && h[3] == 4) << path;
    const unsigned time = h[10] | (h[11] << 8), date = h[12] | (h[13] << 8);
    std::tm t{};
    t.tm_year = static_cast<int>(date >> 9) + 80;
    t.tm_mon = static_cast<int>((date >> 5) & 15) - 1;
    t.tm_mday = static_cast<int>(date & 31);
    t.tm_hour = static_cast<int>(time >> 11);
    t.tm_min = static_cast<int>((time >> 5) & 63);
    t.tm_sec = static_cast<int>(time & 31) * 2;
    t.tm_isdst = -1;
    return std::mktime(&t);
}

TEST(WpmlKmz, DemoMissionRoundTrip) {
    const mission::Mission m = withAircraft("demo_mission.json", {{"DJI Matrice 30T", 60.0}});
    auto plan = mission::planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    const ExportContext ctx = makeExportContext(m, {plan->aircraft[0].route});
    exportCheckAndReadBack(ctx, 0, "pf_wpml_demo.kmz");
}

// Oblique photos (a double grid with the camera tilted 30 degrees): the gimbal turns to -60 at the
// first point and every point says -60, and the file passes the documentation's checks and reads
// back as the plan.
TEST(WpmlKmz, ObliquePhotosPointTheGimbalForward) {
    mission::Mission m = withAircraft("demo_mission.json", {{"DJI Matrice 30T", 60.0}});
    m.options.doubleGrid = true;
    m.options.cameraTiltDeg = 30.0;
    auto plan = mission::planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    const ExportContext ctx = makeExportContext(m, {plan->aircraft[0].route});
    EXPECT_DOUBLE_EQ(ctx.gimbalPitchDeg(0), -60.0);
    exportCheckAndReadBack(ctx, 0, "pf_wpml_oblique.kmz");
    auto docs = wpmlDocuments(ctx, 0, ExportOptions{});
    ASSERT_TRUE(docs.ok()) << docs.error().message;
    EXPECT_NE(docs->templateKml.find("<wpml:gimbalPitchAngle>-60</wpml:gimbalPitchAngle>"),
              std::string::npos);
    EXPECT_EQ(docs->templateKml.find("<wpml:gimbalPitchAngle>-90"), std::string::npos);
    EXPECT_NE(docs->waylinesWpml.find("<wpml:gimbalPitchRotateAngle>-60</wpml:gimbalPitchRotateAngle>"),
              std::string::npos);
    // Read back, the tilt is kept: converted to a .plan it pitches the gimbal the same way.
    auto back = readWpmlKmz(tempPath("pf_wpml_oblique.kmz"));
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->cameraTiltDeg, 30.0);
    EXPECT_DOUBLE_EQ(contextFromImport(*back).gimbalPitchDeg(0), -60.0);
}

TEST(WpmlKmz, FleetMissionEachAircraftItsOwnFile) {
    const mission::Mission m = withAircraft(
        "demo_mission.json", {{"DJI Matrice 30T", 60.0}, {"DJI Mavic 3 Enterprise", 45.0}});
    auto plan = mission::planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    std::vector<route::Route> routes;
    for (const auto& a : plan->aircraft)
        routes.push_back(a.route);
    const ExportContext ctx = makeExportContext(m, routes);
    for (std::size_t i = 0; i < routes.size(); ++i)
        exportCheckAndReadBack(ctx, i, "pf_wpml_fleet_" + std::to_string(i) + ".kmz");
}

// A fleet needing several batteries each: exportMission (the CLI's and the GUI's export) writes one
// .kmz per sortie, none flying them all, each one flight from home back home, equal to its sortie
// as the plan cut it; the archive's entries carry the export time.
TEST(WpmlKmz, OneFilePerSortieEachFlyingItsSortie) {
    mission::Mission m = withAircraft(
        "demo_mission.json", {{"DJI Matrice 30T", 60.0}, {"DJI Mavic 3 Enterprise", 45.0}});
    for (auto& a : m.aircraft)
        a.enduranceMin = 6.0; // short batteries: several sorties each
    auto plan = mission::planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    std::vector<route::Route> routes;
    for (const auto& a : plan->aircraft) {
        ASSERT_GE(a.sortieRoutes.size(), 2u) << a.aircraft;
        routes.push_back(a.route);
    }
    const std::string dir = tempPath("pf_wpml_sorties");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    MissionExportRequest request;
    request.formats = {WaypointFormat::WpmlKmz};
    request.folder = dir;
    const std::time_t before = std::time(nullptr);
    auto report = exportMission(m, routes, request);
    const std::time_t after = std::time(nullptr);
    ASSERT_TRUE(report.ok()) << report.error().message;
    EXPECT_TRUE(report->warnings.empty());
    std::set<std::string> expected;
    for (std::size_t i = 0; i < plan->aircraft.size(); ++i) {
        const auto& a = plan->aircraft[i];
        const ExportContext sorties = makeExportContext(m, a.sortieRoutes);
        const std::size_t n = a.sortieRoutes.size();
        const std::string note = a.aircraft + " needs " + std::to_string(n) + " batteries";
        EXPECT_TRUE(std::any_of(report->notes.begin(), report->notes.end(),
                                [&](const std::string& t) { return t.find(note) == 0; }))
            << note;
        for (std::size_t k = 0; k < n; ++k) {
            const std::string name =
                "mission-" + fileNameSafe(a.aircraft) + "-sortie" + std::to_string(k + 1) + ".kmz";
            expected.insert(name);
            const std::string path = dir + "/" + name;
            ASSERT_TRUE(std::filesystem::exists(path)) << name;
            checkAndReadBack(sorties, k, path, report->notes);
            const std::time_t dated = firstEntryTime(path);
            EXPECT_GE(dated, before - 2) << name; // ZIP keeps times to two seconds
            EXPECT_LE(dated, after + 2) << name;
        }
    }
    std::set<std::string> onDisk;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        onDisk.insert(e.path().filename().string());
    EXPECT_EQ(onDisk, expected); // no file flying every sortie, no leftover .part
}

TEST(WpmlKmz, TerrainMissionFliesEllipsoidalHeightsOfTheEgm96Plan) {
    if (mission::demoDemPath().empty())
        GTEST_SKIP() << "the demo DEM is not built";
    const mission::Mission m =
        withAircraft("demo_mission_terrain.json", {{"DJI Matrice 350 RTK", 60.0}});
    auto plan = mission::planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    const route::Route& r = plan->aircraft[0].route;
    ASSERT_TRUE(r.hasTerrain());
    const ExportContext ctx = makeExportContext(m, {r});
    exportCheckAndReadBack(ctx, 0, "pf_wpml_terrain.kmz", false);
    const test::WpmlCheck c = test::checkWpmlKmz(tempPath("pf_wpml_terrain.kmz"));
    EXPECT_EQ(c.executeHeightMode, "WGS84");
    EXPECT_EQ(c.templateHeightMode, "EGM96");
    ASSERT_EQ(c.templateHeights.size(), c.waypoints.size());
    for (std::size_t k = 0; k < c.waypoints.size(); ++k) {
        // The EGM96 geoid lies about 48 m above the ellipsoid at the demo site (Karlsruhe).
        EXPECT_NEAR(c.waypoints[k].executeHeightM - c.templateHeights[k], 48.0, 2.0) << k;
        EXPECT_NEAR(c.templateEllipsoidHeights[k], c.waypoints[k].executeHeightM, 1e-3) << k;
    }
    EXPECT_NEAR(c.templateHeights.front(), *r.homeElevationM + r.waypoints.front().altitudeM, 0.01);
    auto back = readWpmlKmz(tempPath("pf_wpml_terrain.kmz"));
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_TRUE(back->routes[0].homeElevationM.has_value());
    EXPECT_NEAR(*back->routes[0].homeElevationM, *r.homeElevationM, 0.01);
}

TEST(WpmlKmz, AltitudeFrames) {
    const mission::Mission m = withAircraft("demo_mission.json", {{"DJI Matrice 4E", 50.0}});
    route::Route r("DJI Matrice 4E", m.home, 8.0,
                   {{{8.3280, 49.0112}, 50.0, 90.0, route::WaypointKind::Photo},
                    {{8.3290, 49.0112}, 50.0, 90.0, route::WaypointKind::Turn}});
    const ExportContext ctx = makeExportContext(m, {r});
    ExportOptions o;
    o.altitudeFrame = AltitudeFrame::AboveTerrain;
    auto terrain = wpmlDocuments(ctx, 0, o);
    ASSERT_FALSE(terrain.ok());
    EXPECT_NE(terrain.error().message.find("no heights above the terrain"), std::string::npos);
    o.altitudeFrame = AltitudeFrame::AboveSeaLevel;
    EXPECT_FALSE(wpmlDocuments(ctx, 0, o).ok()); // no home elevation known
    o.homeElevationM = 110.0;
    auto amsl = wpmlDocuments(ctx, 0, o);
    ASSERT_TRUE(amsl.ok()) << amsl.error().message;
    EXPECT_NE(amsl->waylinesWpml.find("<wpml:executeHeightMode>WGS84</wpml:executeHeightMode>"),
              std::string::npos);
    EXPECT_NE(amsl->templateKml.find("<wpml:height>160</wpml:height>"), std::string::npos);
    EXPECT_EQ(amsl->photos, 1u);
}

TEST(WpmlKmz, AircraftThatCannotFlyTheFormatIsRefusedUnlessForced) {
    const mission::Mission m =
        withAircraft("demo_mission.json", {{"Falcon 8", 40.0}, {"DJI Matrice 30T", 60.0}});
    std::vector<route::Route> routes;
    for (const auto& a : m.aircraft)
        routes.push_back(
            route::Route(a.name, m.home, 8.0,
                         {{{8.3280, 49.0112}, 40.0, 90.0, route::WaypointKind::Photo},
                          {{8.3290, 49.0112}, 40.0, 90.0, route::WaypointKind::Photo}}));
    const ExportContext ctx = makeExportContext(m, routes);
    EXPECT_NE(aircraftFormatProblem(ctx, 0, WaypointFormat::WpmlKmz)
                  .find("not a DJI Enterprise aircraft"),
              std::string::npos);
    EXPECT_TRUE(aircraftFormatProblem(ctx, 1, WaypointFormat::WpmlKmz).empty());
    EXPECT_NE(aircraftFormatProblem(ctx, 1, WaypointFormat::LitchiCsv).find("Litchi does not fly"),
              std::string::npos);
    EXPECT_NE(aircraftFormatProblem(ctx, 1, WaypointFormat::QgcPlan).find("not ArduPilot or PX4"),
              std::string::npos);
    EXPECT_TRUE(aircraftFormatProblem(ctx, 0, WaypointFormat::LitchiCsv).empty());
    EXPECT_TRUE(aircraftFormatProblem(ctx, 1, WaypointFormat::Kml).empty());

    const std::string kmz = tempPath("pf_wpml_falcon.kmz"), csv = tempPath("pf_wpml_m30t.csv");
    std::filesystem::remove(kmz);
    std::filesystem::remove(csv);
    EXPECT_FALSE(exportRouteFiles(ctx, 0, WaypointFormat::WpmlKmz, kmz).ok());
    EXPECT_FALSE(exportRouteFiles(ctx, 1, WaypointFormat::LitchiCsv, csv).ok());
    EXPECT_FALSE(std::filesystem::exists(kmz));
    EXPECT_FALSE(std::filesystem::exists(csv));
    ExportOptions force;
    force.forceAircraft = true;
    auto k = exportRouteFiles(ctx, 0, WaypointFormat::WpmlKmz, kmz, force);
    ASSERT_TRUE(k.ok());
    EXPECT_TRUE(k->files.empty()); // a .kmz must name a DJI aircraft: none is written
    ASSERT_EQ(k->notes.size(), 1u);
    EXPECT_NE(k->notes[0].find("no .kmz written"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(kmz));
    auto c = exportRouteFiles(ctx, 1, WaypointFormat::LitchiCsv, csv, force);
    ASSERT_TRUE(c.ok());
    EXPECT_TRUE(std::filesystem::exists(csv));
    ASSERT_FALSE(c->notes.empty());
    EXPECT_NE(c->notes[0].find("written anyway"), std::string::npos);

    // The mission's export: refused unless forced; forced, the M30T's .kmz is written and the
    // Falcon's left out with one note.
    const std::string dir = tempPath("pf_wpml_forced");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    MissionExportRequest request;
    request.formats = {WaypointFormat::WpmlKmz};
    request.folder = dir;
    EXPECT_FALSE(exportMission(m, routes, request).ok());
    request.options = force;
    auto all = exportMission(m, routes, request);
    ASSERT_TRUE(all.ok()) << all.error().message;
    ASSERT_EQ(all->files.size(), 1u);
    EXPECT_EQ(std::filesystem::path(all->files[0]).filename(), "mission-DJI_Matrice_30T.kmz");
    ASSERT_EQ(all->notes.size(), 1u);
    EXPECT_NE(all->notes[0].find("no .kmz written"), std::string::npos);
}

// A plane (fixed-wing or VTOL) gets no .kmz, even with DJI types in a custom entry: the message
// says what it is, and --force does not write one either.
TEST(WpmlKmz, APlaneIsRefusedPlainly) {
    for (const auto kind : {fleet::AircraftKind::FixedWing, fleet::AircraftKind::Vtol}) {
        mission::Mission m = withAircraft("demo_mission.json", {{"DJI Matrice 30T", 60.0}});
        m.aircraft[0].kind = kind;
        m.aircraft[0].name = "Wing";
        const std::vector<route::Route> routes{
            route::Route("Wing", m.home, 8.0,
                         {{{8.3280, 49.0112}, 60.0, 90.0, route::WaypointKind::Photo},
                          {{8.3290, 49.0112}, 60.0, 90.0, route::WaypointKind::Photo}})};
        const ExportContext ctx = makeExportContext(m, routes);
        const std::string why = aircraftFormatProblem(ctx, 0, WaypointFormat::WpmlKmz);
        SCOPED_TRACE(why);
        EXPECT_NE(why.find(std::string("is a ") + fleet::aircraftKindLabel(kind) + " aircraft"),
                  std::string::npos);
        EXPECT_NE(why.find("multirotors only"), std::string::npos);
        const std::string kmz = tempPath("pf_wpml_plane.kmz");
        std::filesystem::remove(kmz);
        auto refused = exportRouteFiles(ctx, 0, WaypointFormat::WpmlKmz, kmz);
        ASSERT_FALSE(refused.ok());
        EXPECT_EQ(refused.error().message, why);
        ExportOptions force;
        force.forceAircraft = true;
        auto forced = exportRouteFiles(ctx, 0, WaypointFormat::WpmlKmz, kmz, force);
        ASSERT_TRUE(forced.ok());
        EXPECT_TRUE(forced->files.empty());
        EXPECT_FALSE(std::filesystem::exists(kmz));
    }
}

TEST(WpmlKmz, BadFilesGetAMessageNamingTheProblem) {
    const std::pair<const char*, const char*> cases[] = {
        {"not_a_zip.kmz", "it is not a ZIP archive"},
        {"no_waylines.kmz", "the archive holds no wpmz/waylines.wpml"},
        {"wrong_namespace.kmz", "does not declare DJI's WPML namespace"},
        {"no_coordinates.kmz", "waypoint 1 has no coordinates"},
        {"missing_file.kmz", "cannot read the file"},
    };
    for (const auto& [file, message] : cases) {
        SCOPED_TRACE(file);
        auto r = importWaypoints(kData + file);
        ASSERT_FALSE(r.ok());
        EXPECT_NE(r.error().message.find(message), std::string::npos) << r.error().message;
        EXPECT_NE(r.error().message.find(file), std::string::npos) << r.error().message;
    }
    auto good = importWaypoints(kData + "hand_written.kmz");
    ASSERT_TRUE(good.ok()) << good.error().message;
    ASSERT_EQ(good->routes.size(), 1u);
    EXPECT_EQ(good->routes[0].aircraft, "DJI Matrice 30T");
    EXPECT_EQ(good->routes[0].waypoints.size(), 2u);
    EXPECT_NEAR(good->routes[0].waypoints[1].headingDeg, 90.0,
                0.1); // along the leg, without a yaw of its own
}

TEST(WpmlKmz, CatalogHoldsTheDjiEnterpriseFleetWithTheirTypes) {
    const std::tuple<const char*, int, int, int> fleet[] = {
        {"DJI Matrice 30", 67, 0, 52},
        {"DJI Matrice 30T", 67, 1, 53},
        {"DJI Mavic 3 Enterprise", 77, 0, 66},
        {"DJI Mavic 3 Thermal", 77, 1, 67},
        {"DJI Mavic 3 Multispectral", 77, 2, 68},
        {"DJI Matrice 300 RTK", 60, 0, 50},
        {"DJI Matrice 350 RTK", 89, 0, 50},
        {"DJI Matrice 4E", 99, 0, 88},
        {"DJI Matrice 4T", 99, 1, 89}};
    for (const auto& [name, drone, sub, payload] : fleet) {
        SCOPED_TRACE(name);
        const auto* a = catalog().findAircraft(name);
        ASSERT_NE(a, nullptr);
        ASSERT_TRUE(a->dji.has_value());
        EXPECT_EQ(a->dji->droneEnum, drone);
        EXPECT_EQ(a->dji->subEnum, sub);
        const auto* c = catalog().findCamera(a->defaultCamera);
        ASSERT_NE(c, nullptr);
        EXPECT_EQ(c->djiPayloadEnum, payload);
        EXPECT_NE(a->notes.find("DJI specifications"), std::string::npos);
    }
    const auto* h20 = catalog().findCamera("DJI Zenmuse H20 wide camera");
    ASSERT_NE(h20, nullptr);
    EXPECT_EQ(h20->djiPayloadEnum, 42);
    // Written and read back equal.
    const std::string path = tempPath("pf_wpml_catalog.json");
    std::ofstream(path) << catalogToJson(catalog());
    auto again = loadCatalog(path);
    ASSERT_TRUE(again.ok()) << again.error().message;
    EXPECT_EQ(again->aircraft, catalog().aircraft);
    EXPECT_EQ(again->cameras, catalog().cameras);
}

TEST(WpmlKmz, MissionFileKeepsTheDjiTypesAndOlderFilesGetThemFromTheCatalog) {
    mission::Mission m = withAircraft("demo_mission.json", {{"DJI Matrice 30T", 60.0}});
    const std::string text = missionToJson(m);
    CPLJSONDocument doc;
    ASSERT_TRUE(doc.LoadMemory(text));
    EXPECT_EQ(doc.GetRoot().GetInteger("version"), 6);
    EXPECT_EQ(doc.GetRoot().GetArray("aircraft")[0].GetInteger("dji_drone_enum"), 67);
    EXPECT_EQ(doc.GetRoot().GetArray("aircraft")[0].GetInteger("dji_drone_sub_enum"), 1);
    EXPECT_EQ(doc.GetRoot().GetArray("aircraft")[0].GetObj("camera").GetInteger("dji_payload_enum"),
              53);
    auto back = parseMissionJson(text, "<memory>");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->aircraft, m.aircraft);
    // A version 5 file (aircraft kinds and plane figures) cannot hold them.
    doc.GetRoot().Set("version", 5);
    auto refused =
        parseMissionJson(doc.GetRoot().Format(CPLJSONObject::PrettyFormat::Pretty), "old.json");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("need version 6"), std::string::npos)
        << refused.error().message;
    // One file holds both a plane's figures (version 5) and the DJI types (version 6).
    mission::Mission both = m;
    both.aircraft.push_back(m.aircraft[0]);
    both.aircraft[1].name = "Wing";
    both.aircraft[1].model = "custom";
    both.aircraft[1].kind = fleet::AircraftKind::FixedWing;
    both.aircraft[1].plane.minTurnRadiusM = 60.0;
    both.aircraft[1].dji.reset();
    both.aircraft[1].camera.djiPayloadEnum.reset();
    const std::string bothText = missionToJson(both);
    ASSERT_TRUE(doc.LoadMemory(bothText));
    EXPECT_EQ(doc.GetRoot().GetInteger("version"), 6);
    auto bothBack = parseMissionJson(bothText, "<memory>");
    ASSERT_TRUE(bothBack.ok()) << bothBack.error().message;
    EXPECT_EQ(bothBack->aircraft, both.aircraft);
    // Without the DJI types the plane's file stays version 5.
    both.aircraft.erase(both.aircraft.begin());
    ASSERT_TRUE(doc.LoadMemory(missionToJson(both)));
    EXPECT_EQ(doc.GetRoot().GetInteger("version"), 5);
    // An older file of a catalog model: the types come from the catalog.
    mission::Mission old = m;
    old.aircraft[0].dji.reset();
    old.aircraft[0].camera.djiPayloadEnum.reset();
    EXPECT_EQ(addDjiTypesFromCatalog(old, catalog()), 1);
    EXPECT_EQ(old.aircraft, m.aircraft);
}

} // namespace
} // namespace pf::io
