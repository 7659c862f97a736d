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
    // A camera of 40 x 30 mm behind 40 mm: at 40 m a footprint of 40 x 30 m.
    void giveCamera() {
        sensor::Camera& c = m.aircraft[0].camera;
        c.sensorWidthMm = 40.0;
        c.sensorHeightMm = 30.0;
        c.focalLengthMm = 40.0;
        c.imageWidthPx = 4000;
        c.imageHeightPx = 3000;
    }
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

// What keeps the margin (geo/no_fly_field.h): a leg at exactly the margin does, and so does one within
// the drawing tolerance (1 cm + 0.5 % of the margin, 3.5 cm of 5 m); one closer breaches it, and the
// message shows its clearance with the decimals that tell it from the margin (not "5.0 m").
TEST(RouteCheck, ALegAtTheMarginKeepsItOneJustInsideBreachesItAndReadsSo) {
    Site s; // the zone's top edge is at y = 10
    EXPECT_TRUE(s.check(s.route({{-60, 15.0}, {60, 15.0}})).ok());
    EXPECT_TRUE(s.check(s.route({{-60, 14.97}, {60, 14.97}})).ok());
    const auto c = s.check(s.route({{-60, 14.96}, {60, 14.96}}));
    EXPECT_EQ(c.noFly, 1);
    EXPECT_EQ(c.leg[0], "the leg to waypoint 2 passes 4.96 m from no-fly zone Mast (margin 5.0 m)");
    const auto far = s.check(s.route({{-60, 14.2}, {60, 14.2}}));
    EXPECT_EQ(far.leg[0], "the leg to waypoint 2 passes 4.2 m from no-fly zone Mast (margin 5.0 m)");
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
    Site s; // the aircraft's camera gives no footprint: why they are outside is not known
    const auto c = s.check(s.route({{-80, -80}, {-118, -80}, {80, -80}, {80, -107}}));
    EXPECT_TRUE(c.ok());
    EXPECT_EQ(c.outsideArea, 2);
    ASSERT_EQ(c.outside.size(), 1u);
    EXPECT_EQ(c.outside[0].reason, OutsideReason::Unknown);
    EXPECT_EQ(c.outside[0].waypoints, (std::vector<int>{1, 3}));
    EXPECT_EQ(c.outside[0].farthest, 1);
    EXPECT_NEAR(c.outside[0].farthestM, 18.0, 0.05);
}

// A lane ends on the boundary: 2 cm beyond it (rounding) is inside, 20 cm is outside.
TEST(RouteCheck, AWaypointOnTheBoundaryIsInside) {
    Site s;
    const auto c = s.check(s.route({{-80, -80}, {-100.02, -80}, {-100.2, -60}, {-80, -60}}));
    EXPECT_EQ(c.outsideArea, 1);
    ASSERT_EQ(c.outside.size(), 1u);
    EXPECT_EQ(c.outside[0].waypoints, (std::vector<int>{2}));
    EXPECT_NEAR(c.outside[0].farthestM, 0.2, 0.01);
}

// Each reason is true of the waypoints listed under it: a photo whose footprint (40 x 30 m at 40 m,
// its long side across the track) still reaches the area covers the boundary, one that sees none of
// it is listed apart, and so are the transit waypoints, whose legs take no photo.
TEST(RouteCheck, WaypointsOutsideTheAreaAreGroupedByWhatTheirPhotosSee) {
    Site s;
    s.giveCamera();
    s.m.home = s.frame.toGeo(geo::Vec2{-130, -100});
    auto r = s.route({{-80, -80},  // inside
                      {-109, -80}, // 9 m out, within half the short side: sees the area
                      {119, 0},  // 19 m east, flying north: its 40 m across the track reach back in
                      {119, 40}, // 19 m east, flying east: 15 m of its footprint reach back, not 19
                      {-80, 130}, // 30 m north: beyond the footprint's corners
                      {-130, -100},
                      {-100, 125}});
    r.waypoints[3].headingDeg = 90.0;
    r.waypoints[5].kind = route::WaypointKind::Transit; // home between two sorties
    const auto c = s.check(r);
    EXPECT_EQ(c.outsideArea, 6);
    const auto* covers = c.outsideGroup(OutsideReason::CoversBoundary);
    const auto* nothing = c.outsideGroup(OutsideReason::SeesNothing);
    const auto* transit = c.outsideGroup(OutsideReason::Transit);
    ASSERT_TRUE(covers && nothing && transit);
    EXPECT_EQ(c.outsideGroup(OutsideReason::Unknown), nullptr);
    EXPECT_EQ(covers->waypoints, (std::vector<int>{1, 2}));
    EXPECT_EQ(covers->farthest, 2);
    EXPECT_NEAR(covers->farthestM, 19.0, 0.05);
    EXPECT_EQ(nothing->waypoints, (std::vector<int>{3, 4, 6}));
    EXPECT_NEAR(nothing->farthestM, 30.0, 0.05);
    EXPECT_EQ(transit->waypoints, (std::vector<int>{5}));
    EXPECT_TRUE(transit->atHomeOnly);
    EXPECT_NEAR(transit->farthestM, 30.0, 0.05);
    // A transit waypoint elsewhere (a detour): no longer "at home only".
    r.waypoints[6].kind = route::WaypointKind::Transit;
    const auto d = s.check(r);
    ASSERT_NE(d.outsideGroup(OutsideReason::Transit), nullptr);
    EXPECT_EQ(d.outsideGroup(OutsideReason::Transit)->waypoints, (std::vector<int>{5, 6}));
    EXPECT_FALSE(d.outsideGroup(OutsideReason::Transit)->atHomeOnly);
    // Lower, the footprint shrinks: at 20 m (20 x 15 m) the one 19 m east sees nothing any more.
    for (auto& w : r.waypoints)
        w.altitudeM = 20.0;
    const auto low = s.check(r);
    ASSERT_NE(low.outsideGroup(OutsideReason::CoversBoundary), nullptr);
    EXPECT_EQ(low.outsideGroup(OutsideReason::CoversBoundary)->waypoints, (std::vector<int>{1}));
}

// A plane's turn waypoints outside the area are its arcs beyond the lane ends: a reason of their
// own, never "photos that see nothing" (it takes none there); a multirotor's turn waypoints are
// judged by what a photo there would see, as before.
TEST(RouteCheck, APlanesTurnsOutsideTheAreaAreTheirOwnReason) {
    Site s;
    s.giveCamera();
    auto r = s.route({{-80, -80}, {-80, 130}, {-60, 150}, {-40, 130}, {-40, -80}});
    for (int i : {1, 2, 3})
        r.waypoints[std::size_t(i)].kind = route::WaypointKind::Turn;
    const auto copter = s.check(r);
    ASSERT_NE(copter.outsideGroup(OutsideReason::SeesNothing), nullptr);
    EXPECT_EQ(copter.outsideGroup(OutsideReason::PlaneTurn), nullptr);
    s.m.aircraft[0].kind = fleet::AircraftKind::FixedWing;
    const auto plane = s.check(r);
    EXPECT_EQ(plane.outsideGroup(OutsideReason::SeesNothing), nullptr);
    const auto* turns = plane.outsideGroup(OutsideReason::PlaneTurn);
    ASSERT_NE(turns, nullptr);
    EXPECT_EQ(turns->waypoints, (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(turns->farthest, 2);
    EXPECT_NEAR(turns->farthestM, 50.0, 0.05);
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

// A plan flown in two sorties: the jump from the first sortie's last waypoint (west of the zone) to
// the second's first (east of it) crosses the zone but is never flown (the aircraft goes home between
// them); checked sortie by sortie, the plan has no error, while the route as one flight has that leg.
TEST(RouteCheck, PlanRouteErrorsChecksEachSortieFromHome) {
    Site s;
    MissionPlan plan;
    AircraftPlan a;
    a.route = s.route({{-40, 0}, {-40, 30}, {40, 30}, {40, 0}});
    a.route.home = s.m.home;
    a.sorties = {{0, 1, 2, 0, 0}, {2, 3, 2, 0, 0}};
    for (const auto& so : a.sorties) {
        route::Route r = a.route;
        r.waypoints.assign(a.route.waypoints.begin() + so.firstWaypoint, a.route.waypoints.begin() + so.lastWaypoint + 1);
        a.sortieRoutes.push_back(r);
    }
    // As one flight the leg from (-40, 30) to (40, 30) passes 20 m from the zone: fine; make it cross.
    a.route.waypoints[1].position = s.frame.toGeo(geo::Vec2{-40, 0});
    a.route.waypoints[2].position = s.frame.toGeo(geo::Vec2{40, 0});
    a.sortieRoutes[0].waypoints[1].position = a.route.waypoints[1].position;
    a.sortieRoutes[1].waypoints[0].position = a.route.waypoints[2].position;
    plan.aircraft.push_back(a);
    const auto whole = routeErrors(s.m, {a.route});
    ASSERT_EQ(whole.size(), 1u);
    EXPECT_EQ(whole[0], "Copter, waypoint 2: the leg to waypoint 3 crosses no-fly zone Mast");
    EXPECT_TRUE(planRouteErrors(s.m, plan).empty());
    // A real breach inside a sortie is still found, and named with its sortie.
    plan.aircraft[0].sortieRoutes[1].waypoints[1].position = s.frame.toGeo(geo::Vec2{0, 0});
    const auto lines = planRouteErrors(s.m, plan);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines[0].rfind("Copter, sortie 2, waypoint", 0), 0u) << lines[0];
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
