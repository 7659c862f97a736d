// Planes planned end to end on generated areas with and without no-fly zones: coverage, no leg or
// turn in a margin, every turn within the plane's radius; a planner that cannot plan for a plane
// says so.
#include "core/mission/plan_mission.h"
#include "core/mission/validation.h"
#include "core/plan/area_generator.h"
#include "core/route/turns.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace pf;
using namespace pf::mission;

namespace {

AircraftConfig ebeeLike(fleet::AircraftKind kind, double radiusM) {
    AircraftConfig a;
    a.name = "Wing";
    a.kind = kind;
    a.camera.name = "S.O.D.A.-like";
    a.camera.hfovDeg = 73.0;
    a.camera.vfovDeg = 52.0;
    a.camera.imageWidthPx = 5472;
    a.camera.imageHeightPx = 3648;
    a.altitudeM = 100.0;
    a.cruiseSpeedMps = 13.0;
    a.enduranceMin = 90.0;
    a.plane.minTurnRadiusM = radiusM;
    a.plane.runInM = 30.0;
    return a;
}

Mission fromGenerated(const plan::GeneratedArea& g, const AircraftConfig& a) {
    Mission m;
    m.name = g.area.name;
    m.area = g.area.area;
    for (std::size_t i = 0; i < g.area.noFly.size(); ++i)
        m.noFlyZones.push_back({"zone " + std::to_string(i), g.area.noFly[i]});
    m.aircraft.push_back(a);
    m.options.planner = PlannerKind::Sweep;
    return m;
}

std::vector<geo::Vec2> surveyPolyline(const AircraftPlan& p) {
    std::vector<geo::Vec2> out;
    for (const auto& w : p.surveyWaypoints)
        out.push_back(w.pos);
    return out;
}

} // namespace

// Four generated areas (rectangle, rectilinear, polygonal), with zones and without, radii from a
// fraction of the lane spacing to about two spacings: everything seen (>= 0.995), no waypoint or leg
// in a margin, the survey's curvature within 1 / R at its turn waypoints (every 10 degrees).
TEST(PlanePlanning, GeneratedAreasKeepCoverageMarginsAndRadius) {
    plan::AreaGeneratorOptions go;
    go.count = 3;
    go.seed = 37;
    go.minZones = 0;
    go.maxZones = 6;
    auto areas = plan::generateAreas(go);
    ASSERT_TRUE(areas) << areas.error().message;
    int withZones = 0;
    for (const auto& g : *areas)
        for (double radius : {15.0, 60.0}) {
            Mission m = fromGenerated(g, ebeeLike(fleet::AircraftKind::FixedWing, radius));
            auto plan = planMission(m);
            ASSERT_TRUE(plan) << g.area.name << ": " << plan.error().message;
            SCOPED_TRACE(g.area.name + " R " + std::to_string(radius));
            EXPECT_GE(plan->coverageRatio, 0.995);
            EXPECT_EQ(plan->noFlyViolations, 0);
            const auto& ap = plan->aircraft[0];
            EXPECT_LE(route::maxCurvature(surveyPolyline(ap)), 1.0 / radius * 1.001);
            EXPECT_GT(ap.metrics.photos, 0);
            withZones += m.noFlyZones.empty() ? 0 : 1;
        }
    EXPECT_GT(withZones, 0);
}

// A VTOL aircraft plans the same way; the plan's time is its flown length over the cruise speed.
TEST(PlanePlanning, VtolTimeIsLengthOverSpeed) {
    plan::AreaGeneratorOptions go;
    go.count = 1;
    go.maxZones = 0;
    auto areas = plan::generateAreas(go);
    ASSERT_TRUE(areas);
    Mission m = fromGenerated((*areas)[0], ebeeLike(fleet::AircraftKind::Vtol, 25.0));
    auto plan = planMission(m);
    ASSERT_TRUE(plan) << plan.error().message;
    const auto& ap = plan->aircraft[0];
    const auto pts = surveyPolyline(ap);
    double length = 0.0;
    for (std::size_t i = 1; i < pts.size(); ++i)
        length += (pts[i] - pts[i - 1]).norm();
    EXPECT_NEAR(ap.metrics.estimatedTimeS, length / 13.0, 0.01 * length / 13.0);
    EXPECT_GE(plan->coverageRatio, 0.995);
}

// The grid planners and the lawnmower cannot plan for a plane: validation and planning say which
// planner, which aircraft, and which planners can.
TEST(PlanePlanning, PlannersThatCannotServeAPlaneSaySo) {
    plan::AreaGeneratorOptions go;
    go.count = 1;
    auto areas = plan::generateAreas(go);
    ASSERT_TRUE(areas);
    Mission m = fromGenerated((*areas)[0], ebeeLike(fleet::AircraftKind::FixedWing, 20.0));
    m.options.planner = PlannerKind::Stride;
    auto refused = planMission(m);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().message,
              "Wing is a fixed-wing aircraft: the stride planner cannot plan for a plane (a grid "
              "planner's path steps from cell to cell and turns on the spot, which a plane cannot fly); choose "
              "auto or sweep");
    bool reported = false;
    for (const auto& p : validateMission(m).problems)
        reported = reported || (p.severity == geo::Severity::Error &&
                                p.message.find("the stride planner cannot plan for a plane") != std::string::npos);
    EXPECT_TRUE(reported);
    m.options.planner = PlannerKind::Auto;
    auto chosen = planMission(m);
    ASSERT_TRUE(chosen) << chosen.error().message;
    EXPECT_EQ(chosen->aircraft[0].planner, PlannerKind::Sweep);
    EXPECT_NE(chosen->aircraft[0].plannerChoice.find("the only planner here that plans for a plane"),
              std::string::npos);
}

// A fixed-wing beside two multirotors over one area with zones: the area is shared, everything is
// seen, no route enters a margin, the plane's turns stay within its radius and the multirotors fly
// their own planners' routes.
TEST(PlanePlanning, PlaneBesideTwoMultirotors) {
    plan::AreaGeneratorOptions go;
    go.count = 1;
    go.seed = 5;
    go.minZones = 2;
    go.maxZones = 2;
    auto areas = plan::generateAreas(go);
    ASSERT_TRUE(areas);
    const AircraftConfig wing = ebeeLike(fleet::AircraftKind::FixedWing, 25.0);
    Mission m = fromGenerated((*areas)[0], wing);
    m.options.planner = PlannerKind::Auto;
    m.options.gridAngleDeg = 0.0; // one angle: the split's hundreds of estimates stay quick
    for (const char* name : {"Copter 1", "Copter 2"}) {
        AircraftConfig c = ebeeLike(fleet::AircraftKind::Multirotor, 25.0);
        c.name = name;
        c.altitudeM = 70.0;
        c.cruiseSpeedMps = 8.0;
        c.enduranceMin = 25.0;
        m.aircraft.push_back(c);
    }
    auto plan = planMission(m);
    ASSERT_TRUE(plan) << plan.error().message;
    ASSERT_EQ(plan->aircraft.size(), 3u);
    EXPECT_GE(plan->coverageRatio, 0.995);
    EXPECT_EQ(plan->noFlyViolations, 0);
    EXPECT_EQ(plan->aircraft[0].planner, PlannerKind::Sweep);
    EXPECT_LE(route::maxCurvature(surveyPolyline(plan->aircraft[0])), 1.0 / 25.0 * 1.001);
    for (const auto& ap : plan->aircraft)
        EXPECT_GT(ap.metrics.photos, 0) << ap.aircraft;
}

// Keep-inside cannot pull a plane's turns over the area: they stay arcs of its radius (the plan says
// so), the photos as without it.
TEST(PlanePlanning, KeepInsideLeavesThePlanesTurnsFlyable) {
    plan::AreaGeneratorOptions go;
    go.count = 1;
    go.maxZones = 2;
    auto areas = plan::generateAreas(go);
    ASSERT_TRUE(areas);
    Mission m = fromGenerated((*areas)[0], ebeeLike(fleet::AircraftKind::FixedWing, 30.0));
    m.options.keepInsideArea = true;
    auto plan = planMission(m);
    ASSERT_TRUE(plan) << plan.error().message;
    EXPECT_LE(route::maxCurvature(surveyPolyline(plan->aircraft[0])), 1.0 / 30.0 * 1.001);
    EXPECT_GE(plan->coverageRatio, 0.995);
    bool said = false;
    for (const auto& w : plan->warnings)
        said = said || w.find("keep-inside holds for its lanes, not its turns") != std::string::npos;
    EXPECT_TRUE(said);
}
