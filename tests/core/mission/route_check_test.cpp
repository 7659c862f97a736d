// Tests of the route check (no-fly margins, altitude limits, home legs, waypoints outside the area)
// and of the table of planner kinds.
#include "core/geo/local_frame.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/route_check.h"

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::mission;

namespace {

// A 200 m square area with a 20 m square zone in its middle; points are given in local metres.
struct Site {
    geo::LocalFrame frame = *geo::LocalFrame::create({8.33, 49.01});
    Mission m;
    Site() {
        m.area = frame.toGeo(geo::Polygon{{{-100, -100}, {100, -100}, {100, 100}, {-100, 100}}, {}});
        m.noFlyZones.push_back({"Mast", frame.toGeo(geo::Polygon{{{-10, -10}, {10, -10}, {10, 10}, {-10, 10}}, {}})});
        m.options.safetyMarginM = 5.0;
        AircraftConfig a;
        a.name = "Copter";
        a.maxAltitudeM = 120.0;
        m.aircraft.push_back(a);
        m.home = frame.toGeo(geo::Vec2{-90, -90});
    }
    route::Route route(const std::vector<geo::Vec2>& pts, double alt = 40.0) const {
        route::Route r;
        r.aircraft = "Copter";
        for (const auto& p : pts)
            r.waypoints.push_back({frame.toGeo(p), alt, 0.0, route::WaypointKind::Photo});
        return r;
    }
    RouteCheck check(const route::Route& r) const { return checkRoute(r, routeLimits(m, r)); }
};

} // namespace

TEST(RouteCheck, ARouteClearOfTheZoneAndWithinTheLimitsHasNoError) {
    Site s;
    const auto c = s.check(s.route({{-80, -80}, {80, -80}, {80, -40}, {-80, -40}}));
    EXPECT_TRUE(c.ok()) << c.messages("Copter").front();
    EXPECT_EQ(c.noFly, 0);
    EXPECT_EQ(c.outsideArea, 0);
}

TEST(RouteCheck, WaypointsAndLegsInTheMarginAreNamedWithTheZone) {
    Site s;
    // Waypoint 2 inside the zone, waypoint 3 at 3 m from it (margin 5 m), leg 4 -> 5 across it.
    const auto c = s.check(s.route({{-80, -80}, {0, 0}, {13, 0}, {-60, 0}, {60, 2}, {60, -80}}));
    EXPECT_EQ(c.waypoint[1], "inside no-fly zone Mast");
    EXPECT_EQ(c.waypoint[2], "3.0 m from no-fly zone Mast (margin 5.0 m)");
    EXPECT_EQ(c.leg[3], "the leg to waypoint 5 crosses no-fly zone Mast");
    EXPECT_TRUE(c.waypoint[0].empty());
    EXPECT_TRUE(c.leg[4].empty());
    const auto lines = c.messages("Copter");
    EXPECT_EQ(int(lines.size()), c.count());
    EXPECT_EQ(lines.front().rfind("Copter, waypoint 1: the leg to waypoint 2 crosses no-fly zone Mast", 0), 0u)
        << lines.front();
    EXPECT_EQ(c.noFly, c.count());
}

TEST(RouteCheck, LegsFromAndBackHomeAreChecked) {
    Site s;
    s.m.home = s.frame.toGeo(geo::Vec2{-50, 0});
    const auto c = s.check(s.route({{50, 0}, {50, 50}, {60, 0}}));
    EXPECT_EQ(c.fromHome, "the leg from home to waypoint 1 crosses no-fly zone Mast");
    EXPECT_EQ(c.toHome, "the leg from waypoint 3 back home crosses no-fly zone Mast");
    EXPECT_EQ(c.count(), 2);
    const auto lines = c.messages("Copter");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "Copter, take-off: the leg from home to waypoint 1 crosses no-fly zone Mast");
    EXPECT_EQ(lines[1], "Copter, landing: the leg from waypoint 3 back home crosses no-fly zone Mast");
}

TEST(RouteCheck, AltitudesAboveTheMaximumOrBelowTheMinimumSafeAltitudeAreErrors) {
    Site s;
    auto r = s.route({{-80, -80}, {80, -80}, {80, -60}});
    r.waypoints[0].altitudeM = 150.0;
    r.waypoints[1].altitudeM = 1.0;
    r.waypoints[2].altitudeM = 5.0; // low, but allowed
    const auto c = s.check(r);
    EXPECT_EQ(c.waypoint[0], "altitude 150.0 m is above the aircraft's maximum of 120.0 m");
    EXPECT_EQ(c.waypoint[1], "altitude 1.0 m is below the minimum safe altitude of 2.0 m");
    EXPECT_TRUE(c.waypoint[2].empty());
    EXPECT_EQ(c.noFly, 0);
    // A route of an aircraft the mission does not know: no ceiling to check against.
    r.aircraft = "Stranger";
    EXPECT_TRUE(s.check(r).waypoint[0].empty());
}

TEST(RouteCheck, WaypointsOutsideTheAreaAreANoteWithTheFarthest) {
    Site s;
    const auto c = s.check(s.route({{-80, -80}, {-118, -80}, {80, -80}, {80, -107}}));
    EXPECT_TRUE(c.ok());
    EXPECT_EQ(c.outsideArea, 2);
    EXPECT_EQ(c.farthestOutside, 1);
    EXPECT_NEAR(c.farthestOutsideM, 18.0, 0.05);
}

TEST(RouteCheck, RouteErrorsLabelsEveryRoute) {
    Site s;
    auto a = s.route({{-80, -80}, {0, 0}});
    auto b = s.route({{-80, -80}, {80, -80}});
    b.aircraft.clear();
    b.waypoints[1].altitudeM = 0.5;
    const auto lines = routeErrors(s.m, {a, b});
    ASSERT_EQ(lines.size(), 4u) << lines[0];
    EXPECT_EQ(lines[0], "Copter, waypoint 1: the leg to waypoint 2 crosses no-fly zone Mast");
    EXPECT_EQ(lines[1], "Copter, waypoint 2: inside no-fly zone Mast");
    EXPECT_EQ(lines[2], "Copter, landing: the leg from waypoint 2 back home crosses no-fly zone Mast");
    EXPECT_EQ(lines[3], "route 2, waypoint 2: altitude 0.5 m is below the minimum safe altitude of 2.0 m");
}

TEST(PlannerKinds, OneTableNamesEveryKindBothWays) {
    const auto& kinds = plannerKinds();
    ASSERT_GE(kinds.size(), 3u);
    for (const auto& k : kinds) {
        EXPECT_EQ(plannerKindFromId(k.id), k.kind) << k.id;
        EXPECT_STREQ(plannerKindInfo(k.kind).label, k.label);
        EXPECT_GT(std::string(k.summary).size(), 10u);
    }
    EXPECT_FALSE(plannerKindFromId("zigzag").has_value());
    EXPECT_EQ(plannerKindIdList(), "auto, sweep, stride, raster, wavefront or lawnmower");
}
