// Corridor missions end to end: the corridor's ground as the area, planning with lanes along the
// line (one aircraft, several sharing it, zones, sorties), and a straight corridor against the area
// survey of its rectangle.
#include "core/mission/corridor.h"
#include "core/mission/plan_corridor.h"
#include "core/mission/plan_mission.h"
#include "core/mission/validation.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/plan/corridor/corridor_geometry.h"
#include "core/plan/coverage_check.h"
#include "tests/sample_missions.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf::mission {
namespace {

using geo::Vec2;

const geo::LonLat kOrigin{8.33, 49.01};

geo::GeoRing geoLine(const std::vector<Vec2>& local) {
    auto frame = geo::LocalFrame::create(kOrigin);
    return frame->toGeo(local);
}

// The big-site test aircraft (60 x 45 degrees, 70 % / 60 %) under its own name, with endurance to
// spare (sorties are tested on their own).
AircraftConfig testAircraft(const std::string& name, double altitude = 40.0) {
    AircraftConfig a = pf::test::bigSiteAircraft(altitude);
    a.name = name;
    a.enduranceMin = 600;
    return a;
}

Mission corridorMission(const std::vector<Vec2>& local, double width) {
    Mission m;
    m.name = "Corridor";
    applyCorridor(m, Corridor{geoLine(local), width});
    m.home = geo::LocalFrame::create(kOrigin)->toGeo(local.front() + Vec2(-30, -30));
    m.aircraft.push_back(testAircraft("Falcon 1"));
    return m;
}

// Runs of photos with one heading, each photo within two trigger distances of the one before: the
// lanes flown (two lanes flown the same way one after the other are two).
int laneCount(const AircraftPlan& a) {
    int lanes = 0;
    double heading = -1;
    std::optional<Vec2> last;
    for (const auto& w : a.localWaypoints) {
        if (w.kind != route::WaypointKind::Photo)
            continue;
        if (std::abs(w.headingDeg - heading) > 1.0 || !last ||
            (w.pos - *last).norm() > 2.0 * a.footprint.alongM)
            ++lanes;
        heading = w.headingDeg;
        last = w.pos;
    }
    return lanes;
}

TEST(CorridorMission, GroundIsTheAreaAndValidationNamesCorridorProblems) {
    Mission m = corridorMission({Vec2(0, 0), Vec2(800, 0), Vec2(1300, 400)}, 120.0);
    ASSERT_FALSE(m.area.outer.empty());
    EXPECT_NEAR(geo::groundAreaM2(m.area),
                geo::area(plan::corridorGround({Vec2(0, 0), Vec2(800, 0), Vec2(1300, 400)}, 120.0)),
                50.0);
    EXPECT_FALSE(validateMission(m).hasErrors()) << validateMission(m).errorSummary();

    Mission thin = m;
    applyCorridor(thin, Corridor{m.corridor->line, 0.0});
    EXPECT_TRUE(thin.area.outer.empty());
    const auto r = validateMission(thin);
    ASSERT_TRUE(r.hasErrors());
    EXPECT_NE(r.errorSummary().find("the corridor's width must be greater than 0 m"),
              std::string::npos)
        << r.errorSummary();
    EXPECT_EQ(r.errorSummary().find("the area"), std::string::npos) << r.errorSummary();

    Mission point = m;
    applyCorridor(point, Corridor{{m.corridor->line.front()}, 100.0});
    EXPECT_NE(validateMission(point).errorSummary().find("at least two distinct points"),
              std::string::npos);
    EXPECT_FALSE(planMission(point).ok());
}

// A straight corridor is flown as the area survey of its rectangle is: the same lanes, the same
// photos, the same time within 1 %.
TEST(CorridorMission, StraightCorridorEqualsTheSurveyOfItsRectangle) {
    for (double width : {40.0, 100.0, 170.0}) {
        const Mission corridor = corridorMission({Vec2(0, 0), Vec2(1200, 0)}, width);
        Mission area = corridor;
        area.corridor.reset(); // the same ground, as an area
        area.options.planner = PlannerKind::Sweep;
        area.options.gridAngleDeg = 0.0; // lanes along it
        auto c = planMission(corridor);
        auto a = planMission(area);
        ASSERT_TRUE(c.ok()) << c.error().message;
        ASSERT_TRUE(a.ok()) << a.error().message;
        const auto& ca = c->aircraft.front();
        const auto& aa = a->aircraft.front();
        EXPECT_EQ(laneCount(ca), laneCount(aa)) << width;
        EXPECT_EQ(ca.metrics.photos, aa.metrics.photos) << width;
        EXPECT_NEAR(ca.timeS, aa.timeS, 0.01 * aa.timeS) << width;
        EXPECT_GE(c->coverageRatio, 0.995) << width;
        EXPECT_NE(c->plannerChoice.find("corridor"), std::string::npos);
    }
}

// A bent corridor with zones across and beside it, flown in sorties: covered, no margin breached.
TEST(CorridorMission, BentCorridorWithZonesAndSorties) {
    Mission m =
        corridorMission({Vec2(0, 0), Vec2(900, 0), Vec2(1500, 500), Vec2(1500, 1300)}, 110.0);
    auto frame = geo::LocalFrame::create(kOrigin);
    const auto zone = [&](const std::string& name, std::vector<Vec2> pts) {
        m.noFlyZones.push_back({name, geo::GeoPolygon{frame->toGeo(pts), {}}});
    };
    zone("Bridge", {Vec2(400, -100), Vec2(430, -100), Vec2(430, 100), Vec2(400, 100)});
    zone("Mast", {Vec2(1480, 800), Vec2(1520, 800), Vec2(1520, 840), Vec2(1480, 840)});
    m.aircraft.front().enduranceMin = 12;
    auto p = planMission(m);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->noFlyViolations, 0);
    EXPECT_GE(p->coverageRatio, 0.99);
    EXPECT_GT(p->aircraft.front().sorties.size(), 1u);
}

// Several aircraft share a long corridor in stretches, balanced on their flight times.
TEST(CorridorMission, SeveralAircraftShareALongCorridor) {
    Mission m = corridorMission({Vec2(0, 0), Vec2(2500, 300), Vec2(5000, 0)}, 90.0);
    m.aircraft.push_back(testAircraft("Falcon 2", 50.0));
    m.aircraft.back().cruiseSpeedMps = 8.0;
    m.aircraft.push_back(testAircraft("Falcon 3"));
    auto p = planMission(m);
    ASSERT_TRUE(p.ok()) << p.error().message;
    ASSERT_EQ(p->aircraft.size(), 3u);
    for (const auto& a : p->aircraft) {
        EXPECT_GT(a.metrics.photos, 0) << a.aircraft;
        EXPECT_FALSE(a.subarea.empty()) << a.aircraft;
    }
    EXPECT_LE(p->makespanS / p->idealS, 1.10) << p->makespanS << " vs ideal " << p->idealS;
    EXPECT_GE(p->coverageRatio, 0.995);
    EXPECT_EQ(p->noFlyViolations, 0);
}

// More aircraft than the line has metres for: refused in words, never a plan with an empty stretch.
TEST(CorridorMission, TooShortToShareIsRefused) {
    Mission m = corridorMission({Vec2(0, 0), Vec2(2, 0)}, 50.0);
    m.aircraft.push_back(testAircraft("Falcon 2"));
    m.aircraft.push_back(testAircraft("Falcon 3"));
    auto p = planMission(m);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("too short to share between 3 aircraft"), std::string::npos)
        << p.error().message;
}

// Another planner kind plans the corridor's ground as an area (for comparison); the grid's cell
// budget applies only then.
TEST(CorridorMission, OtherPlannersPlanTheGroundAsAnArea) {
    Mission m = corridorMission({Vec2(0, 0), Vec2(600, 0), Vec2(900, 300)}, 80.0);
    m.options.planner = PlannerKind::Lawnmower;
    auto p = planMission(m);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->aircraft.front().planner, PlannerKind::Lawnmower);
    EXPECT_EQ(p->plannerChoice.find("corridor"), std::string::npos);
}

// A plane cannot fly lanes along a corridor (each lane end turns on the spot): validation and
// planning refuse it by name and point at the sweep, which then plans the ground with its turns.
TEST(CorridorMission, PlaneIsRefusedLanesAndGetsTheSweep) {
    Mission m = corridorMission({Vec2(0, 0), Vec2(1500, 0), Vec2(2500, 600)}, 120.0);
    AircraftConfig& wing = m.aircraft.front();
    wing.name = "Wing";
    wing.kind = fleet::AircraftKind::FixedWing;
    wing.cruiseSpeedMps = 13.0;
    wing.plane.minTurnRadiusM = 40.0;
    wing.plane.runInM = 30.0;
    auto refused = planMission(m);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message.rfind("Wing flies as a plane: lanes along a corridor are "
                                            "planned for multirotors only",
                                            0),
              0u)
        << refused.error().message;
    bool reported = false;
    for (const auto& p : validateMission(m).problems)
        reported = reported || (p.severity == geo::Severity::Error &&
                                p.message.find("choose the sweep planner") != std::string::npos);
    EXPECT_TRUE(reported);
    m.options.planner = PlannerKind::Sweep;
    auto swept = planMission(m);
    ASSERT_TRUE(swept.ok()) << swept.error().message;
    EXPECT_EQ(swept->aircraft.front().planner, PlannerKind::Sweep);
    EXPECT_GE(swept->coverageRatio, 0.995);
}

} // namespace
} // namespace pf::mission

namespace pf::mission {
namespace {

// A cut between two aircraft's stretches never falls where a bend's lanes reach: the stretch
// holding the bend keeps its lanes whole, and both stretches end square across the same segment.
TEST(CorridorMission, CutsStayOutOfTheBends) {
    const std::vector<Vec2> line{Vec2(0, 0), Vec2(1000, 0),
                                 Vec2(1000, 1000)}; // 90 degrees at 1000 m
    const double width = 100.0, reach = 0.5 * width * std::tan(M_PI / 4) + 1.0;
    for (double c : {960.0, 999.0, 1000.0, 1001.0, 1040.0}) {
        const auto s = snapCuts(line, {c}, width);
        ASSERT_EQ(s.size(), 1u);
        EXPECT_GE(std::abs(s.front() - 1000.0), reach - 1e-9) << c;
        EXPECT_LE(std::abs(s.front() - c), 2 * reach) << c;
    }
    EXPECT_DOUBLE_EQ(snapCuts(line, {500.0}, width).front(), 500.0);
    // Short segments: out of both bends' reach where the line leaves room (its first 9 m), else the
    // middle of the longer segment beside the bend.
    const std::vector<Vec2> zigzag{Vec2(0, 0), Vec2(60, 0), Vec2(60, 60), Vec2(0, 60)};
    EXPECT_NEAR(snapCuts(zigzag, {65.0}, width).front(), 9.0, 1e-9);
    const std::vector<Vec2> tight{Vec2(0, 0), Vec2(20, 0), Vec2(20, 60), Vec2(0, 60)};
    EXPECT_NEAR(snapCuts(tight, {25.0}, width).front(), 50.0, 1e-9);
}

} // namespace
} // namespace pf::mission
