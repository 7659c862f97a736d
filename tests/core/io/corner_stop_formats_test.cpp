// The exports make the vehicle do what the flight-time model counted: a stop (hold) where the model
// counts one, a corner flown through (no hold, the corner cut as acceptance radius) where it does
// not.
#include "core/geo/local_frame.h"
#include "core/io/litchi_csv.h"
#include "core/io/mission_items.h"
#include "core/mission/plan_mission.h"
#include "core/plan/flight_time.h"
#include "tests/core/io/formats_test_util.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace pf;
using namespace pf::io;

namespace {

const geo::LonLat kOrigin{8.3290, 49.0115};

// A flight in local metres around kOrigin: two lanes joined by a U-turn (two right angles), then a
// detour with two shallow corners (20 degrees each: at the last photo and the first transit point)
// and a sharp one (120 degrees).
route::Route cornerRoute() {
    const auto frame = *geo::LocalFrame::create(kOrigin);
    route::Route r;
    r.aircraft = "Copter";
    r.cruiseSpeedMps = 10;
    const auto add = [&](double x, double y, route::WaypointKind k) {
        r.waypoints.emplace_back(frame.toGeo(geo::Vec2(x, y)), 50.0, 90.0, k);
    };
    for (int x = 0; x <= 100; x += 20)
        add(x, 0, route::WaypointKind::Photo); // lane 1 east: 6 photos
    for (int x = 100; x >= 0; x -= 20)
        add(x, 30, route::WaypointKind::Photo); // lane 2 west
    const double c20 = std::cos(20 * M_PI / 180), s20 = std::sin(20 * M_PI / 180);
    add(-50 * c20, 30 + 50 * s20, route::WaypointKind::Transit);      // 20 degrees right of west...
    add(-50 * c20 - 50, 30 + 50 * s20, route::WaypointKind::Transit); // ... and back to west: 20
    add(-50 * c20 - 50 + 40 * std::cos(60 * M_PI / 180),
        30 + 50 * s20 + 40 * std::sin(60 * M_PI / 180),
        route::WaypointKind::Transit); // from west to 60 degrees: a turn of 120
    return r;
}

mission::Mission missionWith(const route::Route& r) {
    mission::Mission m = test::demoMission();
    m.home = geo::LonLat{8.3290, 49.0114}; // 11 m south of the first photo
    mission::AircraftConfig a;
    a.name = r.aircraft;
    a.cruiseSpeedMps = r.cruiseSpeedMps;
    m.aircraft.push_back(a);
    return m;
}

std::vector<MissionItem> waypointsOf(const std::vector<MissionItem>& items) {
    std::vector<MissionItem> out;
    for (const auto& it : items)
        if (it.command == mav::kNavWaypoint)
            out.push_back(it);
    return out;
}

// The stops the one model counts on the flight home -> waypoints -> landing, in local metres.
int modelStops(const ExportContext& ctx, std::size_t i, const geo::LocalFrame& frame) {
    std::vector<geo::Vec2> poly{frame.toLocal(*ctx.homeFor(i))};
    for (const auto& w : ctx.routes[i].waypoints)
        poly.push_back(frame.toLocal(w.position));
    poly.push_back(frame.toLocal(ctx.landingFor(i).value_or(*ctx.homeFor(i))));
    const auto* a = ctx.aircraftFor(i);
    return plan::flightTime(poly, a ? mission::flightModel(*a) : plan::FlightTimeModel{}).stops;
}

} // namespace

// Each waypoint, by hand: the first photo turns from the leg from home (north) to east: 90, a stop;
// the lane's photos are straight: flown through; both ends of the U-turn turn 90: stops; the
// detour's corners at waypoints 12 and 13 turn 20: flown through with the 2 m corner cut; waypoint
// 14 turns 120: a stop; the last one turns back towards home (110 degrees): a stop.
TEST(CornerStops, MissionItemsHoldWhereTheModelStops) {
    const route::Route r = cornerRoute();
    const ExportContext ctx = makeExportContext(missionWith(r), {r});
    const auto wps = waypointsOf(*missionItems(ctx, 0));
    ASSERT_EQ(wps.size(), r.waypoints.size());
    const plan::FlightTimeModel m = mission::flightModel(ctx.mission.aircraft[0]);
    const auto angles = cornerAnglesDeg(r.waypoints, *ctx.homeFor(0), *ctx.homeFor(0));
    EXPECT_NEAR(angles[0], 90.0, 0.05);
    EXPECT_NEAR(angles[3], 0.0, 0.05);
    EXPECT_NEAR(angles[5], 90.0, 0.05);
    EXPECT_NEAR(angles[6], 90.0, 0.05);
    EXPECT_NEAR(angles[11], 20.0, 0.05);
    EXPECT_NEAR(angles[12], 20.0, 0.05);
    EXPECT_NEAR(angles[13], 120.0, 0.05);
    int holds = 0;
    for (std::size_t i = 0; i < wps.size(); ++i) {
        const bool stop = plan::isStopCorner(angles[i], m);
        EXPECT_EQ(wps[i].params[0], stop ? plan::kStopHoldS : 0.0) << "waypoint " << i + 1;
        EXPECT_EQ(wps[i].params[1], stop ? 0.0 : plan::kCornerCutM) << "waypoint " << i + 1;
        holds += wps[i].params[0] > 0;
    }
    for (std::size_t i : {0, 5, 6, 13, 14})
        EXPECT_EQ(wps[i].params[0], 1.0) << i;
    for (std::size_t i : {1, 3, 7, 11, 12})
        EXPECT_EQ(wps[i].params[0], 0.0) << i;
    const auto frame = *geo::LocalFrame::create(kOrigin);
    EXPECT_EQ(holds, modelStops(ctx, 0, frame));
    // Distance triggering keeps the lane ends and their stops.
    ExportOptions dist;
    dist.trigger = CameraTrigger::Distance;
    int distHolds = 0;
    for (const auto& it : waypointsOf(*missionItems(ctx, 0, dist)))
        distHolds += it.params[0] > 0;
    EXPECT_EQ(distHolds, holds);
}

// Litchi: a stop has curve size 0 and a "stay for" action of the hold (type 0, 1000 ms) before its
// photo; a corner flown through the corner cut as curve size; a straight photo curve size 0.
TEST(CornerStops, LitchiStaysAndCurves) {
    const route::Route r = cornerRoute();
    const ExportContext ctx = makeExportContext(missionWith(r), {r});
    auto csv = litchiCsvText(ctx, 0);
    ASSERT_TRUE(csv) << csv.error().message;
    std::istringstream in(*csv);
    std::string line;
    std::getline(in, line); // header
    std::vector<std::vector<std::string>> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream ls(line);
        for (std::string cell; std::getline(ls, cell, ',');)
            f.push_back(cell);
        rows.push_back(f);
    }
    ASSERT_EQ(rows.size(), r.waypoints.size());
    // Columns: 4 curve size, 8/9 first action and its parameter, 10/11 the second.
    EXPECT_EQ(rows[0][4], "0");
    EXPECT_EQ(rows[0][8], "0");
    EXPECT_EQ(rows[0][9], "1000");
    EXPECT_EQ(rows[0][10], "1"); // the photo after the stay
    EXPECT_EQ(rows[1][4], "0");
    EXPECT_EQ(rows[1][8], "1"); // a photo on the lane: no stay
    EXPECT_EQ(rows[12][4], "2");
    EXPECT_EQ(rows[12][8], "-1"); // a transit corner flown through: no action
    EXPECT_EQ(rows[11][4], "2");  // a photo on a corner flown through: no stay
    EXPECT_EQ(rows[11][8], "1");
    EXPECT_EQ(rows[13][4], "0");
    EXPECT_EQ(rows[13][8], "0");
    // The file reads back with the same photos.
    auto back = parseLitchiCsv(*csv, "x.csv");
    ASSERT_TRUE(back) << back.error().message;
    ASSERT_EQ(back->routes.size(), 1u);
    int photos = 0;
    for (const auto& w : back->routes[0].waypoints)
        photos += w.kind == route::WaypointKind::Photo;
    EXPECT_EQ(photos, 12);
}

// On a planned mission (the demo site, a multirotor, zones and detours) the exports hold exactly
// where the model counted a stop, sortie by sortie.
TEST(CornerStops, PlannedMissionExportsMatchTheModel) {
    mission::Mission m = test::demoMission();
    mission::AircraftConfig a;
    a.name = "Copter";
    a.camera.hfovDeg = 60;
    a.camera.vfovDeg = 45;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = 40;
    m.aircraft.push_back(a);
    m.options.planner = mission::PlannerKind::Sweep;
    auto plan = mission::planMission(m);
    ASSERT_TRUE(plan) << plan.error().message;
    std::vector<route::Route> routes;
    for (const auto& ap : plan->aircraft)
        for (const auto& s : ap.sortieRoutes)
            routes.push_back(s);
    ASSERT_FALSE(routes.empty());
    const ExportContext ctx = makeExportContext(m, routes);
    const auto frame = *geo::LocalFrame::forArea(m.area);
    int total = 0;
    for (std::size_t i = 0; i < routes.size(); ++i) {
        int holds = 0;
        for (const auto& it : waypointsOf(*missionItems(ctx, i)))
            holds += it.params[0] > 0;
        EXPECT_EQ(holds, modelStops(ctx, i, frame)) << "sortie " << i + 1;
        total += holds;
    }
    EXPECT_GT(total, 4); // lane ends are stops
}
