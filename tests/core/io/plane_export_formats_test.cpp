// A plane's MAVLink mission item by item, against the mission protocol's commands: the take-off of
// its kind, the camera triggered by distance on and off around each lane, every turn waypoint flown
// through, the landing of its kind (DO_LAND_START, approach and NAV_LAND; NAV_VTOL_LAND); the .plan
// names the vehicle type; Litchi refuses a plane by name; the read-back gives the route again.
#include "core/geo/geodesic.h"
#include "core/geo/local_frame.h"
#include "core/io/mission_items.h"
#include "core/io/qgc_plan.h"
#include "core/io/waypoint_formats.h"
#include "tests/core/io/formats_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace pf;
using namespace pf::io;

namespace {

const geo::LonLat kOrigin{8.3290, 49.0115};

// Two lanes of 5 photos 20 m apart (east, then west 40 m north), each after a run-in point, joined
// by a half circle of radius 20 m sampled every 30 degrees (turn waypoints).
route::Route planeRoute() {
    const auto frame = *geo::LocalFrame::create(kOrigin);
    route::Route r;
    r.aircraft = "Wing";
    r.cruiseSpeedMps = 15;
    const auto add = [&](double x, double y, double heading, route::WaypointKind k) {
        r.waypoints.emplace_back(frame.toGeo(geo::Vec2(x, y)), 100.0, heading, k);
    };
    add(-40, 0, 90, route::WaypointKind::Turn); // run-in
    for (int x = 0; x <= 80; x += 20)
        add(x, 0, 90, route::WaypointKind::Photo);
    for (int a = 30; a < 180; a += 30) // the turn: centre (80, 20), radius 20, to the left
        add(80 + 20 * std::sin(a * M_PI / 180), 20 - 20 * std::cos(a * M_PI / 180), 90 - a, route::WaypointKind::Turn);
    add(120, 40, 270, route::WaypointKind::Turn); // run-in of lane 2 (its first photo at x = 80)
    for (int x = 80; x >= 0; x -= 20)
        add(x, 40, 270, route::WaypointKind::Photo);
    return r;
}

ExportContext contextFor(fleet::AircraftKind kind) {
    mission::Mission m = test::demoMission();
    m.home = geo::LonLat{8.3290, 49.0110};
    mission::AircraftConfig a;
    a.name = "Wing";
    a.kind = kind;
    a.cruiseSpeedMps = 15;
    a.plane.minTurnRadiusM = 20;
    m.aircraft = {a};
    return makeExportContext(m, {planeRoute()});
}

std::vector<int> commands(const std::vector<MissionItem>& items) {
    std::vector<int> out;
    for (const auto& it : items)
        out.push_back(it.command);
    return out;
}

} // namespace

// Fixed-wing, item by item: NAV_TAKEOFF with the pitch; DO_CHANGE_SPEED as airspeed; the gimbal
// down; per lane its run-in waypoint, its first photo, the trigger on (20 m, a photo now), its last
// photo, the trigger off (a last photo); the turn waypoints between, flown through (no hold, the
// autopilot's own acceptance radius); then DO_LAND_START, the approach 400 m before the landing
// point against the first lane's heading (east) at 40 m, and NAV_LAND at home. No capture command:
// the camera fires by distance even with the per-photo trigger option.
TEST(PlaneExport, FixedWingItemsByTheProtocol) {
    const ExportContext ctx = contextFor(fleet::AircraftKind::FixedWing);
    auto items = missionItems(ctx, 0);
    ASSERT_TRUE(items) << items.error().message;
    const int W = mav::kNavWaypoint, T = mav::kDoSetCamTriggDist;
    const std::vector<int> expected{mav::kNavTakeoff, mav::kDoChangeSpeed, mav::kDoMountControl,
                                    W, W, T, W, T,          // lane 1: run-in, first, on, last, off
                                    W, W, W, W, W,          // the turn (30 to 150 degrees)
                                    W, W, T, W, T,          // lane 2
                                    mav::kDoLandStart, W, mav::kNavLand};
    ASSERT_EQ(commands(*items), expected);
    const auto& v = *items;
    EXPECT_EQ(v[0].params[0], kPlaneTakeoffPitchDeg);
    EXPECT_EQ(v[0].params[6], 100.0);
    EXPECT_EQ(v[1].params[0], 0.0); // airspeed
    EXPECT_EQ(v[1].params[1], 15.0);
    EXPECT_NEAR(v[5].params[0], 20.0, 1e-6);
    EXPECT_EQ(v[5].params[2], 1.0);
    EXPECT_EQ(v[7].params[0], 0.0);
    for (const auto& it : v)
        if (it.command == W) {
            EXPECT_EQ(it.params[0], 0.0); // no hold: a plane flies through
            EXPECT_EQ(it.params[1], 0.0); // the autopilot's own acceptance radius
        }
    const geo::LonLat home = *ctx.homeFor(0);
    EXPECT_NEAR(v[18].params[4], home.lat, 1e-9);
    const geo::LonLat approach{v[19].params[5], v[19].params[4]};
    EXPECT_NEAR(geo::geodesicDistance(home, approach), kApproachDistanceM, 0.5);
    EXPECT_NEAR(geo::initialBearingDeg(approach, home), 90.0, 0.5); // lands heading east
    EXPECT_EQ(v[19].params[6], kApproachAltitudeM);
    EXPECT_EQ(v[20].params[6], 0.0);
    EXPECT_NEAR(v[20].params[4], home.lat, 1e-9);

    // Read back: the route's waypoints again (photos along the triggered lanes), no landing approach.
    auto read = routeFromItems(v);
    ASSERT_TRUE(read.ok()) << read.error().message;
    const route::Route back = *read;
    const route::Route& r = ctx.routes[0];
    ASSERT_EQ(back.waypoints.size(), r.waypoints.size());
    for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
        EXPECT_EQ(back.waypoints[i].kind == route::WaypointKind::Photo, r.waypoints[i].kind == route::WaypointKind::Photo)
            << i;
        EXPECT_LT(geo::geodesicDistance(back.waypoints[i].position, r.waypoints[i].position), 0.01) << i;
    }
}

// VTOL: NAV_VTOL_TAKEOFF (the transition towards the next waypoint) and NAV_VTOL_LAND at home; the
// lanes and turns as a fixed-wing's. The .plan says the vehicle type: 22 (VTOL with fixed rotors)
// here, 1 for a fixed-wing, 2 for a multirotor.
TEST(PlaneExport, VtolItemsAndPlanVehicleType) {
    const ExportContext ctx = contextFor(fleet::AircraftKind::Vtol);
    auto items = missionItems(ctx, 0);
    ASSERT_TRUE(items) << items.error().message;
    const auto c = commands(*items);
    ASSERT_GE(c.size(), 3u);
    EXPECT_EQ(c.front(), mav::kNavVtolTakeoff);
    EXPECT_EQ((*items)[0].params[1], 1.0);
    EXPECT_EQ(c.back(), mav::kNavVtolLand);
    EXPECT_EQ(std::count(c.begin(), c.end(), mav::kDoSetCamTriggDist), 4);
    EXPECT_EQ(std::count(c.begin(), c.end(), mav::kDoLandStart), 0);
    EXPECT_EQ(std::count(c.begin(), c.end(), mav::kImageStartCapture), 0);
    EXPECT_NEAR(items->back().params[4], ctx.homeFor(0)->lat, 1e-9);

    for (auto [kind, type] : {std::pair{fleet::AircraftKind::Vtol, 22}, std::pair{fleet::AircraftKind::FixedWing, 1},
                              std::pair{fleet::AircraftKind::Multirotor, 2}}) {
        auto json = qgcPlanJson(contextFor(kind), 0, {});
        ASSERT_TRUE(json) << json.error().message;
        EXPECT_NE(json->find("\"vehicleType\":" + std::to_string(type)), std::string::npos) << type;
    }
}

// Litchi flies DJI multirotors: a plane's route is refused with its name, kind and what to export
// instead, and no file is written.
TEST(PlaneExport, LitchiRefusesAPlane) {
    const ExportContext ctx = contextFor(fleet::AircraftKind::FixedWing);
    const auto dir = std::filesystem::temp_directory_path() / "pf_plane_litchi";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "wing.csv").string();
    std::filesystem::remove(path);
    auto r = exportRouteFiles(ctx, 0, WaypointFormat::LitchiCsv, path);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "Wing is a fixed-wing aircraft: Litchi missions are flown by DJI multirotors only, "
                                 "which stop and turn on the spot; export a QGroundControl .plan or a .waypoints "
                                 "file for its ArduPilot or PX4 autopilot instead");
    EXPECT_FALSE(std::filesystem::exists(path));
}

namespace {

// The fixed-wing's approach waypoint (the waypoint before NAV_LAND) and the NAV_LAND item.
std::pair<geo::LonLat, MissionItem> approachAndLand(const std::vector<MissionItem>& v) {
    return {geo::LonLat{v[v.size() - 2].params[5], v[v.size() - 2].params[4]}, v.back()};
}

// A square zone of side `side` m centred `east` m east and `north` m north of `at`.
mission::NoFlyZone squareZone(const geo::LonLat& at, double east, double north, double side) {
    const auto frame = *geo::LocalFrame::create(at);
    const double h = side / 2;
    mission::NoFlyZone z;
    z.name = "Tower";
    z.polygon.outer = frame.toGeo(std::vector<geo::Vec2>{{east - h, north - h}, {east + h, north - h},
                                                          {east + h, north + h}, {east - h, north + h}});
    return z;
}

} // namespace

// The landing direction: the user's (into the wind) when given; without it the first lane's
// heading, turned in 15-degree steps until the approach keeps the no-fly margins; a heading given
// whose approach enters a margin is refused with the route's name, and nothing is written for it.
TEST(PlaneExport, LandingHeadingIsTheUsersOrKeepsTheMargins) {
    ExportContext ctx = contextFor(fleet::AircraftKind::FixedWing);
    const geo::LonLat home = *ctx.homeFor(0);
    ctx.mission.noFlyZones.clear(); // the demo's zones lie north-east, across a 200-degree approach
    ExportOptions o;
    o.landingHeadingDeg = 200.0;
    auto given = missionItems(ctx, 0, o);
    ASSERT_TRUE(given) << given.error().message;
    auto [approach, land] = approachAndLand(*given);
    EXPECT_NEAR(geo::initialBearingDeg(approach, home), 200.0, 0.5);
    EXPECT_NEAR(geo::geodesicDistance(home, approach), kApproachDistanceM, 0.5);
    EXPECT_EQ(land.params[3], 200.0); // NAV_LAND yaw

    // A zone 200 m west of home, on the default approach (from the west, heading east).
    ctx.mission.noFlyZones = {squareZone(home, -200, 0, 60)};
    ctx.mission.options.safetyMarginM = 10;
    auto turned = missionItems(ctx, 0);
    ASSERT_TRUE(turned) << turned.error().message;
    const auto [a2, l2] = approachAndLand(*turned);
    const double h = geo::initialBearingDeg(a2, home);
    EXPECT_GT(std::abs(std::remainder(h - 90.0, 360.0)), 7.0) << h; // not straight from the west
    auto chosen = planeLandingHeadingDeg(ctx, 0);
    ASSERT_TRUE(chosen);
    EXPECT_NEAR(std::remainder(*chosen - h, 360.0), 0.0, 0.5);
    EXPECT_EQ(std::fmod(std::abs(*chosen - 90.0), 15.0), 0.0); // a 15-degree step from the lane
    // The approach keeps the margin: sampled every metre, 10 m from the zone or more.
    const auto frame = *geo::LocalFrame::create(home);
    const geo::Vec2 p = frame.toLocal(a2);
    for (int i = 0; i <= 400; ++i) {
        const geo::Vec2 q = p * (1.0 - i / 400.0);
        const double dx = std::max(std::abs(q.x() + 200) - 30, 0.0), dy = std::max(std::abs(q.y()) - 30, 0.0);
        EXPECT_GE(std::hypot(dx, dy), 10.0 - 0.1) << i;
    }

    o.landingHeadingDeg = 90.0; // from the west, over the zone
    auto refused = missionItems(ctx, 0, o);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("the landing approach towards 90 degrees (from 400 m before the "
                                           "landing point) comes within a no-fly zone's safety margin"),
              std::string::npos)
        << refused.error().message;
}

// The way down that the map draws is the one the mission items fly: a fixed-wing's approach
// waypoint and landing point, a VTOL's landing point, nothing for a multirotor.
TEST(PlaneExport, LandingLegIsWhatTheItemsFly) {
    const ExportContext wing = contextFor(fleet::AircraftKind::FixedWing);
    auto leg = planeLandingLeg(wing, 0);
    ASSERT_TRUE(leg) << leg.error().message;
    ASSERT_EQ(leg->size(), 2u);
    auto items = missionItems(wing, 0);
    ASSERT_TRUE(items);
    const auto [approach, land] = approachAndLand(*items);
    EXPECT_LT(geo::geodesicDistance((*leg)[0], approach), 0.01);
    EXPECT_LT(geo::geodesicDistance((*leg)[1], geo::LonLat{land.params[5], land.params[4]}), 0.01);
    auto vtol = planeLandingLeg(contextFor(fleet::AircraftKind::Vtol), 0);
    ASSERT_TRUE(vtol);
    EXPECT_EQ(vtol->size(), 1u);
    auto copter = planeLandingLeg(contextFor(fleet::AircraftKind::Multirotor), 0);
    ASSERT_TRUE(copter);
    EXPECT_TRUE(copter->empty());
}
