#include "core/mission/plan_geojson.h"
#include "core/mission/plan_mission.h"

#include "core/geo/polygon_ops.h"
#include "core/io/catalog.h"
#include "core/mission/route_check.h"
#include "core/mission/survey_comparison.h"
#include "core/plan/area_generator.h"

#include <gtest/gtest.h>

#include <cpl_json.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <tuple>
#include <utility>

namespace pf::mission {
namespace {

// The demo site: "Rheinhafen training ground" with its two no-fly zones.
Mission demoMission() {
    Mission m;
    m.name = "Rheinhafen";
    m.area.outer = {{8.3272608, 49.0109209}, {8.3324653, 49.0108309}, {8.3327392, 49.0123597},
                    {8.3308218, 49.0125396}, {8.3305478, 49.0133489}, {8.3273978, 49.013259}};
    NoFlyZone warehouse;
    warehouse.name = "Warehouse";
    warehouse.polygon.outer = {{8.3291782, 49.0118201}, {8.3297261, 49.0118201}, {8.3297261, 49.0121799},
                               {8.3291782, 49.0121799}};
    m.noFlyZones.push_back(warehouse);
    NoFlyZone mast;
    mast.name = "Radio mast";
    for (int k = 0; k < 16; ++k) {
        const double a = 2 * M_PI * k / 16;
        mast.polygon.outer.push_back({8.3316435 + 20.0 * std::cos(a) / (111320.0 * std::cos(49.0115504 * M_PI / 180)),
                                      49.0115504 + 20.0 * std::sin(a) / 111320.0});
    }
    m.noFlyZones.push_back(mast);
    m.home = geo::LonLat{8.3270554, 49.010741};
    AircraftConfig a;
    a.name = "Falcon 1";
    a.model = "custom";
    a.camera.name = "test";
    a.camera.hfovDeg = 70;
    a.camera.vfovDeg = 55;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = 50;
    a.overlap = {0.6, 0.4};
    m.aircraft.push_back(a);
    m.options.gridAngleDeg = 0.0;
    // The tests below are about the grid planners' chain (cells, cell paths, the angle search); the
    // automatic choice and the sweep planner have their own tests at the end.
    m.options.planner = PlannerKind::Stride;
    return m;
}

TEST(PlanMission, DemoSiteStrideCoversEverythingWithoutJumps) {
    const Mission m = demoMission();
    auto plan = planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    ASSERT_EQ(plan->aircraft.size(), 1u);
    const AircraftPlan& a = plan->aircraft.front();
    EXPECT_EQ(a.aircraft, "Falcon 1");
    EXPECT_TRUE(a.metrics.complete());
    EXPECT_GT(a.metrics.visitable, 50);
    EXPECT_EQ(a.metrics.jumps, 0);
    EXPECT_GE(a.metrics.photos, a.metrics.cells);
    EXPECT_GE(a.metrics.turnLowerBound, 0);
    EXPECT_EQ(a.anglesTried, 1);
    // No warning: photos are placed outside the margins where they are made, so the safety stage has
    // nothing to move, and one aircraft's area has no parts that grid moves do not join.
    EXPECT_TRUE(plan->warnings.empty()) << plan->warnings.front();
    EXPECT_GE(plan->coverageRatio, 0.995);
    EXPECT_EQ(plan->noFlyViolations, 0);
    // Every cell of the path is flown at a safe position, and the route mirrors the local waypoints.
    for (int c : a.path.cells)
        EXPECT_TRUE(a.grid.pointIsSafe(a.grid.flightPosition(c)));
    ASSERT_EQ(a.route.waypoints.size(), a.localWaypoints.size());
    ASSERT_TRUE(a.route.home.has_value());
    EXPECT_NEAR(a.route.home->lon, 8.3270554, 1e-9);
    for (const auto& w : a.route.waypoints) {
        EXPECT_DOUBLE_EQ(w.altitudeM, 50.0);
        EXPECT_GT(w.position.lon, 8.325);
        EXPECT_LT(w.position.lon, 8.335);
    }
    EXPECT_EQ(plan->totals.photos, a.metrics.photos);
    EXPECT_DOUBLE_EQ(plan->totals.estimatedTimeS, a.metrics.estimatedTimeS);
    // Take-off and landing near home: the path starts and ends at the cell nearest to it.
    EXPECT_EQ(a.path.cells.front(), a.path.cells.back());
}

TEST(PlanMission, CatalogAircraftAsAMissionFliesIt) {
    auto cat = io::loadCatalog(std::string(PF_RESOURCES_DIR) + "/catalog.json");
    ASSERT_TRUE(cat.ok()) << cat.error().message;
    const fleet::AircraftSpec* spec = cat->findAircraft("DJI Phantom 4 Pro");
    ASSERT_NE(spec, nullptr);
    const sensor::Camera* cam = cat->findCamera(spec->defaultCamera);
    ASSERT_NE(cam, nullptr);
    const AircraftConfig a = aircraftFromCatalog(*spec, cam);
    EXPECT_EQ(a.name, "DJI Phantom 4 Pro");
    EXPECT_EQ(a.model, "DJI Phantom 4 Pro");
    EXPECT_TRUE(a.camera == *cam);
    EXPECT_EQ(a.cruiseSpeedMps, spec->cruiseSpeedMps);
    EXPECT_EQ(a.turnRateDegS, spec->turnRateDegS);
    EXPECT_EQ(a.enduranceMin, spec->enduranceMin);
    EXPECT_EQ(a.maxAltitudeM, spec->maxAltitudeM);
    EXPECT_FALSE(a.altitudeM.has_value());
    // Without a camera the default one stays.
    EXPECT_TRUE(aircraftFromCatalog(*spec, nullptr).camera == AircraftConfig{}.camera);
}

TEST(PlanMission, AutoAngleIsNoWorseThanZero) {
    Mission m = demoMission();
    auto fixed = planMission(m);
    ASSERT_TRUE(fixed.ok());
    m.options.gridAngleDeg.reset();
    auto autoPlan = planMission(m);
    ASSERT_TRUE(autoPlan.ok()) << autoPlan.error().message;
    const AircraftPlan& a = autoPlan->aircraft.front();
    EXPECT_GE(a.anglesTried, 36);
    EXPECT_LE(a.metrics.estimatedTimeS, fixed->aircraft.front().metrics.estimatedTimeS + 1e-9);
    EXPECT_TRUE(a.metrics.complete());
}

TEST(PlanMission, EveryPlannerCompletes) {
    for (PlannerKind k : {PlannerKind::Stride, PlannerKind::Raster, PlannerKind::Wavefront}) {
        Mission m = demoMission();
        m.options.planner = k;
        auto plan = planMission(m);
        ASSERT_TRUE(plan.ok()) << plan.error().message;
        EXPECT_TRUE(plan->aircraft.front().metrics.complete());
    }
}

// Two aircraft with different cameras and altitudes share the demo site: every aircraft gets a
// subarea and a complete flight from home and back, the photos of all of them cover the area and no
// leg breaks a margin; the route is the concatenation of the sorties.
TEST(PlanMission, SeveralAircraftShareTheAreaEndToEnd) {
    Mission m = demoMission();
    AircraftConfig b = m.aircraft.front();
    b.name = "Falcon 2";
    b.altitudeM = 70;
    b.cruiseSpeedMps = 12;
    m.aircraft.push_back(b);
    auto plan = planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    ASSERT_EQ(plan->aircraft.size(), 2u);
    for (const auto& w : plan->warnings)
        EXPECT_EQ(w.find("not available"), std::string::npos) << w;
    double sum = 0.0;
    for (const auto& a : plan->aircraft) {
        EXPECT_FALSE(a.subarea.empty()) << a.aircraft;
        EXPECT_GT(a.metrics.photos, 0) << a.aircraft;
        ASSERT_FALSE(a.sorties.empty());
        EXPECT_EQ(a.sorties.front().firstWaypoint, 0);
        EXPECT_EQ(a.sorties.back().lastWaypoint, static_cast<int>(a.route.waypoints.size()) - 1);
        EXPECT_EQ(a.sortieRoutes.size(), a.sorties.size());
        EXPECT_EQ(a.route.waypoints.size(), a.localWaypoints.size());
        EXPECT_TRUE(a.route.home.has_value());
        // Out from home and back by Transit waypoints or straight legs, never a photo at home.
        EXPECT_NE(a.route.waypoints.front().kind, route::WaypointKind::Turn);
        double t = 0.0;
        for (const auto& s : a.sorties)
            t += s.timeS;
        EXPECT_NEAR(t, a.timeS, 1e-6);
        sum += a.timeS;
        EXPECT_LE(a.timeS, plan->makespanS + 1e-9);
    }
    EXPECT_NEAR(plan->idealS, sum / 2, 1e-6);
    // The two subareas share at most a boundary.
    const double overlap = geo::area(geo::intersection(plan->aircraft[0].subarea, plan->aircraft[1].subarea.front()));
    EXPECT_LT(overlap, 1.0);
    EXPECT_GE(plan->coverageRatio, 0.995);
    EXPECT_EQ(plan->noFlyViolations, 0);
    EXPECT_LE(plan->makespanS / plan->idealS, 1.25);
}

// An endurance too short for the survey splits it into sorties that each return home and fit the
// battery less the reserve; the route flies them one after the other, through home between two.
TEST(PlanMission, ShortEnduranceGivesSorties) {
    Mission m = demoMission();
    m.aircraft.front().enduranceMin = 3.0;
    m.options.batteryReserve = 0.25;
    auto plan = planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    const AircraftPlan& a = plan->aircraft.front();
    ASSERT_GE(a.sorties.size(), 2u);
    int photos = 0;
    for (std::size_t i = 0; i < a.sorties.size(); ++i) {
        EXPECT_LE(a.sorties[i].timeS, 3.0 * 60 * 0.75 + 1e-6);
        if (i > 0) {
            // One Transit waypoint at home between two sorties (it belongs to neither).
            EXPECT_EQ(a.sorties[i].firstWaypoint, a.sorties[i - 1].lastWaypoint + 2);
            const auto& between = a.route.waypoints[static_cast<std::size_t>(a.sorties[i].firstWaypoint - 1)];
            EXPECT_EQ(between.kind, route::WaypointKind::Transit);
            ASSERT_TRUE(a.route.home.has_value());
            EXPECT_EQ(between.position.lon, a.route.home->lon);
            EXPECT_EQ(between.position.lat, a.route.home->lat);
        }
        photos += a.sorties[i].photos;
        EXPECT_EQ(a.sortieRoutes[i].waypoints.size(),
                  static_cast<std::size_t>(a.sorties[i].lastWaypoint - a.sorties[i].firstWaypoint + 1));
    }
    EXPECT_EQ(photos, a.metrics.photos);
    // The batteries a flight needs are worth knowing but ask for nothing: a note, not a warning.
    bool noted = false, warned = false;
    for (const auto& n : plan->notes)
        noted = noted || n.find(a.aircraft + ": the flight needs " +
                                std::to_string(a.sorties.size()) + " batteries") == 0;
    for (const auto& w : plan->warnings)
        warned = warned || w.find("batteries") != std::string::npos;
    EXPECT_TRUE(noted);
    EXPECT_FALSE(warned);
    EXPECT_GE(plan->coverageRatio, 0.995);
    EXPECT_EQ(plan->noFlyViolations, 0);

    // The drawn path lands at home between sorties: home starts, separates and ends them.
    CPLJSONDocument doc;
    ASSERT_TRUE(doc.LoadMemory(planToGeoJson(*plan)));
    const CPLJSONArray features = doc.GetRoot().GetArray("features");
    bool found = false;
    for (int i = 0; i < features.Size(); ++i) {
        const CPLJSONObject f = features[i];
        if (f.GetString("properties/kind") != "path" || f.GetString("properties/aircraft") != a.aircraft)
            continue;
        found = true;
        const CPLJSONArray coords = f.GetArray("geometry/coordinates");
        ASSERT_TRUE(a.route.home.has_value());
        int atHome = 0;
        for (int k = 0; k < coords.Size(); ++k) {
            const CPLJSONArray c = coords[k].ToArray();
            // Coordinates are written with 7 decimals.
            atHome += std::fabs(c[0].ToDouble() - a.route.home->lon) <= 0.5e-7 &&
                      std::fabs(c[1].ToDouble() - a.route.home->lat) <= 0.5e-7;
        }
        EXPECT_EQ(atHome, static_cast<int>(a.sorties.size()) + 1);
        EXPECT_EQ(coords.Size(), static_cast<int>(a.route.waypoints.size() + 2));
    }
    EXPECT_TRUE(found);
}

// Two aircraft close in altitude flying together from one home, each over its own part of the area:
// a note naming both and their altitudes as given. From two homes: a warning.
TEST(PlanMission, CloseAltitudesWarn) {
    Mission m = demoMission();
    AircraftConfig b = m.aircraft.front();
    b.name = "Falcon 2";
    b.altitudeM = 55; // 5 m above Falcon 1, separation asked: 10 m
    m.aircraft.push_back(b);
    auto plan = planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    EXPECT_EQ(plan->altitudeConflicts, 1);
    auto names = [](const std::vector<std::string>& lines) {
        int n = 0;
        for (const auto& w : lines)
            n += w.find("Falcon 1") != std::string::npos && w.find("Falcon 2") != std::string::npos;
        return n;
    };
    EXPECT_EQ(names(plan->warnings), 0);
    ASSERT_EQ(names(plan->notes), 1);
    for (const auto& n : plan->notes) {
        if (!names({n}))
            continue;
        EXPECT_EQ(n, "Falcon 1 and Falcon 2 take off from the same home and fly at the same time "
                     "only 5 m apart in "
                     "altitude (50 m and 55 m), each over its own part of the area: launch them "
                     "one after the "
                     "other, or keep 10 m between their altitudes.");
    }

    // Falcon 2 from a home of its own, 300 m away: their transit may cross, a warning.
    m.aircraft[1].home = geo::LonLat{m.home->lon + 0.004, m.home->lat};
    auto apart = planMission(m);
    ASSERT_TRUE(apart.ok()) << apart.error().message;
    EXPECT_EQ(names(apart->notes), 0);
    EXPECT_EQ(names(apart->warnings), 1);
}

// Keeping waypoints inside the area moves the photos that lay outside it without losing coverage.
TEST(PlanMission, KeepInsideAreaMovesWaypointsAndKeepsCoverage) {
    Mission m = demoMission();
    m.options.keepInsideArea = true;
    auto plan = planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    EXPECT_GT(plan->aircraft.front().keptInside, 0);
    EXPECT_GE(plan->coverageRatio, 0.995);
    EXPECT_EQ(plan->noFlyViolations, 0);
}

TEST(PlanMission, BadInputs) {
    Mission m = demoMission();
    m.aircraft.clear();
    auto plan = planMission(m);
    ASSERT_FALSE(plan.ok());
    EXPECT_EQ(plan.error().message, "the mission has no aircraft: add one to plan a flight");

    m = demoMission();
    m.aircraft.front().altitudeM.reset();
    plan = planMission(m);
    ASSERT_FALSE(plan.ok());
    EXPECT_EQ(plan.error().message,
              "Falcon 1: neither a flight altitude nor a ground sample distance is set");

    m = demoMission();
    m.options.maxCells = 10;
    plan = planMission(m);
    ASSERT_FALSE(plan.ok());
    EXPECT_EQ(plan.error().code, ErrorCode::TooLarge);
    EXPECT_EQ(plan.error().message.rfind("Falcon 1: ", 0), 0u);
}

TEST(PlanMission, AngleCandidatesIncludeLongestEdge) {
    const geo::MultiPolygon region{geo::Polygon{{{0, 0}, {100, 10}, {100, 20}, {0, 20}}, {}}};
    const auto angles = candidateAngles(region);
    EXPECT_EQ(angles.size(), 37u); // 36 steps + atan(10/100); the other long edge (180 deg) is 0
    EXPECT_NEAR(angles.back(), std::atan2(10.0, 100.0) * 180.0 / M_PI, 1e-3);
}

} // namespace
} // namespace pf::mission

namespace pf::mission {
namespace {

int runCli(const std::string& args, std::string* err) {
    const auto errFile = std::filesystem::temp_directory_path() / "pf_plan_cli_err.txt";
    const int rc = std::system((std::string(PF_CLI_PATH) + " " + args + " > /dev/null 2> " + errFile.string()).c_str());
    std::ifstream f(errFile);
    err->assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    std::filesystem::remove(errFile);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

TEST(PlanCli, WritesPlanAndMetrics) {
    const auto dir = std::filesystem::temp_directory_path() / "pf_plan_cli_out";
    std::filesystem::remove_all(dir);
    std::string err;
    const int rc = runCli("plan " + std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json --grid-angle 0 --out " +
                              dir.string(),
                          &err);
    ASSERT_EQ(rc, 0) << err;
    CPLJSONDocument metrics;
    ASSERT_TRUE(metrics.Load((dir / "metrics.json").string()));
    const CPLJSONArray aircraft = metrics.GetRoot().GetArray("aircraft");
    ASSERT_GE(aircraft.Size(), 1);
    EXPECT_FALSE(aircraft[0].GetString("name").empty());
    EXPECT_TRUE(aircraft[0].GetBool("complete"));
    EXPECT_EQ(aircraft[0].GetInteger("jumps"), 0);
    EXPECT_TRUE(metrics.GetRoot().GetObj("total").IsValid());
    CPLJSONDocument plan;
    ASSERT_TRUE(plan.Load((dir / "plan.geojson").string()));
    const CPLJSONArray features = plan.GetRoot().GetArray("features");
    ASSERT_GE(features.Size(), 2);
    EXPECT_EQ(features[0].GetObj("geometry").GetString("type"), "LineString");
    const CPLJSONObject photo = features[1].GetObj("properties");
    EXPECT_EQ(photo.GetInteger("seq"), 1);
    EXPECT_GT(photo.GetDouble("alt_m"), 0);
    EXPECT_TRUE(photo.GetObj("heading_deg").IsValid());
    EXPECT_EQ(photo.GetString("aircraft"), aircraft[0].GetString("name"));
    // The footprint, the same for all of an aircraft's photos, is given once, on its path.
    EXPECT_FALSE(photo.GetObj("footprint_across_m").IsValid());
    const CPLJSONObject path = features[0].GetObj("properties");
    EXPECT_EQ(path.GetString("kind"), "path");
    EXPECT_GT(path.GetDouble("footprint_across_m"), path.GetDouble("footprint_along_m"));
    EXPECT_GT(path.GetDouble("footprint_along_m"), 0);
    EXPECT_EQ(path.GetInteger("photos"), aircraft[0].GetInteger("photos"));
    // The plan-wide checks and the per-aircraft times.
    EXPECT_GE(metrics.GetRoot().GetDouble("coverage_ratio"), 0.995);
    EXPECT_EQ(metrics.GetRoot().GetInteger("nofly_violations", -1), 0);
    const CPLJSONObject total = metrics.GetRoot().GetObj("total");
    EXPECT_GE(total.GetDouble("coverage_ratio"), 0.995);
    EXPECT_EQ(total.GetInteger("nofly_violations", -1), 0);
    double makespan = 0;
    for (int i = 0; i < aircraft.Size(); ++i) {
        EXPECT_GT(aircraft[i].GetDouble("time_s"), 0);
        EXPECT_GE(aircraft[i].GetInteger("sorties"), 1);
        makespan = std::max(makespan, aircraft[i].GetDouble("time_s"));
    }
    EXPECT_DOUBLE_EQ(total.GetDouble("makespan_s"), makespan);
    int subareas = 0;
    for (int i = 0; i < features.Size(); ++i)
        subareas += features[i].GetObj("properties").GetString("kind") == "subarea";
    EXPECT_EQ(subareas, aircraft.Size());
    std::filesystem::remove_all(dir);
}

// --format writes one file per aircraft and format, plus the combined KML; the .plan holds what
// QGroundControl's loader requires.
TEST(PlanCli, WritesEveryFormatPerAircraft) {
    const auto dir = std::filesystem::temp_directory_path() / "pf_plan_cli_formats";
    std::filesystem::remove_all(dir);
    std::string err;
    const int rc = runCli("plan " + std::string(PF_RESOURCES_DIR) +
                              "/demo/demo_mission.json --grid-angle 0 --format plan,waypoints,kml,gpx,geojson,csv --out " +
                              dir.string(),
                          &err);
    ASSERT_EQ(rc, 0) << err;
    for (const char* name : {"Falcon_8", "Phantom_4_Pro"}) {
        for (const char* ext : {".plan", ".waypoints", ".kml", ".gpx", ".geojson"})
            EXPECT_TRUE(std::filesystem::exists(dir / (std::string("mission-") + name + ext))) << name << ext;
        // Litchi takes at most 99 waypoints: the demo's routes are longer and come in parts.
        EXPECT_TRUE(std::filesystem::exists(dir / (std::string("mission-") + name + "-part1.csv"))) << name;
        EXPECT_TRUE(std::filesystem::exists(dir / (std::string("mission-") + name + "-part2.csv"))) << name;
    }
    for (const char* ext : {".kml", ".gpx", ".geojson"})
        EXPECT_TRUE(std::filesystem::exists(dir / (std::string("mission") + ext))) << ext;
    EXPECT_FALSE(std::filesystem::exists(dir / "mission.plan"));
    CPLJSONDocument plan;
    ASSERT_TRUE(plan.Load((dir / "mission-Falcon_8.plan").string()));
    EXPECT_EQ(plan.GetRoot().GetString("fileType"), "Plan");
    const CPLJSONArray items = plan.GetRoot().GetObj("mission").GetArray("items");
    ASSERT_GT(items.Size(), 10);
    for (int i = 0; i < items.Size(); ++i)
        if (items[i].GetString("type") == "SimpleItem") {
            EXPECT_EQ(items[i].GetArray("params").Size(), 7) << i;
        }
    std::filesystem::remove_all(dir);
}

TEST(PlanCli, BadInputs) {
    std::string err;
    EXPECT_EQ(runCli("eval", &err), 2);
    EXPECT_NE(err.find("no area file given"), std::string::npos) << err;
    EXPECT_EQ(runCli("eval " + std::string(PF_RESOURCES_DIR) + "/areas/c_l_shape.geojson --planners stride,zigzag", &err), 2);
    EXPECT_NE(err.find("--planners: unknown planner 'zigzag' (use stride, raster or wavefront)"), std::string::npos)
        << err;
    EXPECT_EQ(runCli("eval /nonexistent.geojson", &err), 2);
    EXPECT_NE(err.find("cannot read the area file /nonexistent.geojson"), std::string::npos) << err;
    const std::string demo = std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json";
    EXPECT_EQ(runCli("plan " + demo + " --format plan,shapefile --out /tmp/pf_never_written", &err), 2);
    EXPECT_NE(err.find("--format: "), std::string::npos) << err;
    EXPECT_NE(err.find("shapefile"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists("/tmp/pf_never_written"));
    EXPECT_EQ(runCli("plan " + demo + " --format kml", &err), 2);
    EXPECT_NE(err.find("--format: needs --out DIR"), std::string::npos) << err;
}

} // namespace
} // namespace pf::mission

namespace pf::mission {
namespace {

// Local metres around the demo site as WGS84 (for hand-made test missions).
geo::GeoPolygon localRect(double x0, double y0, double x1, double y1) {
    const double lon0 = 8.33, lat0 = 49.01;
    const double kx = 1.0 / (111320.0 * std::cos(lat0 * M_PI / 180)), ky = 1.0 / 110540.0;
    geo::GeoPolygon p;
    p.outer = {{lon0 + x0 * kx, lat0 + y0 * ky}, {lon0 + x1 * kx, lat0 + y0 * ky}, {lon0 + x1 * kx, lat0 + y1 * ky},
               {lon0 + x0 * kx, lat0 + y1 * ky}};
    return p;
}

// A U-shaped zone whose 8 m wide opening the 5 m margins close: the 40 x 40 m inside is a pocket no safe
// path reaches. The plan must still be made (it used to stop with "No safe way ..."), never enter the
// pocket, warn about it with its area, and see its ground from outside as far as the footprints reach.
TEST(PlanMission, PocketClosedByMarginsIsPhotographedFromOutsideNotEntered) {
    Mission m = demoMission();
    m.noFlyZones.clear();
    m.area = localRect(0, 0, 300, 240);
    for (auto [x0, y0, x1, y1] : {std::tuple{100.0, 95.0, 105.0, 145.0}, std::tuple{100.0, 140.0, 150.0, 145.0},
                                  std::tuple{145.0, 95.0, 150.0, 145.0}, std::tuple{100.0, 95.0, 121.0, 100.0},
                                  std::tuple{129.0, 95.0, 150.0, 100.0}}) {
        NoFlyZone z;
        z.name = "wall";
        z.polygon = localRect(x0, y0, x1, y1);
        m.noFlyZones.push_back(z);
    }
    m.home = localRect(-20, -20, -19, -19).outer[0];
    m.options.safetyMarginM = 5;
    for (PlannerKind kind : {PlannerKind::Stride, PlannerKind::Raster, PlannerKind::Wavefront}) {
        m.options.planner = kind;
        auto plan = planMission(m);
        ASSERT_TRUE(plan.ok()) << plan.error().message;
        bool warned = false;
        for (const auto& w : plan->warnings)
            warned = warned || w.find("pocket") != std::string::npos;
        EXPECT_TRUE(warned);
        EXPECT_EQ(plan->noFlyViolations, 0);
        const auto& a = plan->aircraft.front();
        ASSERT_FALSE(a.grid.pockets().empty());
        // Nothing is flown inside the pocket (x 105..145, y 100..140 in the mission's frame).
        for (const auto& w : a.localWaypoints)
            EXPECT_FALSE(geo::contains(a.grid.pockets(), w.pos)) << w.pos.transpose();
        // All but the pocket's middle is seen: the pocket is 32 x 32 m of admissible ground, the
        // photos reach about 10 m into it from beyond its 5 m margin.
        EXPECT_GE(plan->coverageRatio, 0.99);
    }
}

// Generated area 8 of seed 1 (`photoflight-cli eval --generate 60 --seed 1`, a T with 15 zones, pairs
// and pockets whose margins merge): stride's plan had a leg 4.96 m from a zone (margin 5 m), made
// after the no-fly stage by dropping a detour's corner 1 cm before a photo; cut into sorties, its
// route also joined one sortie's last waypoint straight to the next one's first, across a zone. The
// plan (its own count) and the route check, the one every export passes, must both find nothing.
TEST(PlanMission, GeneratedAreaEightKeepsEveryMarginAlsoInSorties) {
    plan::AreaGeneratorOptions go;
    go.count = 8;
    go.seed = 1;
    auto areas = plan::generateAreas(go);
    ASSERT_TRUE(areas.ok()) << areas.error().message;
    const plan::GeneratedArea& g = areas->back();
    ASSERT_EQ(g.area.noFly.size(), 15u);
    PlannerOptions opt;
    opt.planner = PlannerKind::Stride;
    AircraftConfig aircraft = surveyAircraft(); // the survey comparison's: 60 x 45 degrees at 30 m, 20 %
    aircraft.name = "Falcon 8";
    auto m = surveyMission(g.area, aircraft, opt);
    ASSERT_TRUE(m.ok()) << m.error().message;
    // Endurance unlimited (as the comparison plans it: one flight), then the catalog's Falcon 8 (8 m/s,
    // 20 min: 3 batteries) as `photoflight-cli plan` flew it.
    for (auto [endurance, speed] : {std::pair{1e6, 10.0}, std::pair{20.0, 8.0}}) {
        m->aircraft.front().enduranceMin = endurance;
        m->aircraft.front().cruiseSpeedMps = speed;
        auto plan = planMission(*m);
        ASSERT_TRUE(plan.ok()) << plan.error().message;
        EXPECT_EQ(plan->noFlyViolations, 0) << endurance << " min";
        std::vector<route::Route> routes;
        for (const auto& a : plan->aircraft) {
            routes.push_back(a.route);
            routes.insert(routes.end(), a.sortieRoutes.begin(), a.sortieRoutes.end());
        }
        for (const auto& e : routeErrors(*m, routes))
            ADD_FAILURE() << endurance << " min: " << e;
        if (endurance < 100) {
            EXPECT_GE(plan->aircraft.front().sorties.size(), 2u);
        }
        EXPECT_GE(plan->coverageRatio, 0.99);
    }
}

} // namespace
} // namespace pf::mission
