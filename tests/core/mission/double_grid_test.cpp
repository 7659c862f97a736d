// Double grids: two passes at 90 degrees, each a complete survey: the photos of the two single
// grids, each pass checked on its own, shared between aircraft pass by pass, zones and sorties
// kept.
#include "core/mission/double_grid.h"
#include "core/mission/plan_mission.h"

#include "core/geo/local_frame.h"
#include "core/io/export_context.h"
#include "core/io/mission_items.h"
#include "core/io/trigger_lanes.h"
#include "tests/sample_missions.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf::mission {
namespace {

using geo::Vec2;

const geo::LonLat kOrigin{8.33, 49.01};

Mission areaMission(double w, double h) {
    auto frame = geo::LocalFrame::create(kOrigin);
    Mission m;
    m.name = "Block";
    m.area = geo::GeoPolygon{
        frame->toGeo(std::vector<Vec2>{Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)}), {}};
    m.home = frame->toGeo(Vec2(-20, -20));
    AircraftConfig a = pf::test::bigSiteAircraft(40.0);
    a.name = "Falcon 1";
    a.overlap = {0.75, 0.65};
    a.enduranceMin = 600;
    m.aircraft.push_back(a);
    m.options.planner = PlannerKind::Sweep;
    return m;
}

int photosOf(const route::Route& r) {
    int n = 0;
    for (const auto& w : r.waypoints)
        n += w.kind == route::WaypointKind::Photo;
    return n;
}

// The double grid flies the photos of the single grid at its angle and of the one across it; the
// export leaves out only the photos it merges (closer than 0.1 m to the waypoint before).
TEST(DoubleGrid, PhotosOfTheTwoSingleGridsLessWhatTheExportMerges) {
    Mission one = areaMission(320, 210);
    one.options.gridAngleDeg = 0.0;
    Mission across = one;
    across.options.gridAngleDeg = 90.0;
    Mission both = one;
    both.options.doubleGrid = true;
    auto a = planMission(one), b = planMission(across), d = planMission(both);
    ASSERT_TRUE(a.ok()) << a.error().message;
    ASSERT_TRUE(b.ok()) << b.error().message;
    ASSERT_TRUE(d.ok()) << d.error().message;
    const int singles = a->totals.photos + b->totals.photos;
    EXPECT_EQ(d->totals.photos, singles);
    const route::Route& route = d->aircraft.front().route;
    EXPECT_EQ(photosOf(route), singles);
    // Each pass faces its own way: the first along x, the second along y.
    int firstPass = 0, secondPass = 0;
    for (const auto& w : d->aircraft.front().localWaypoints)
        if (w.kind == route::WaypointKind::Photo)
            ++(w.pass == 0 ? firstPass : secondPass);
    EXPECT_EQ(firstPass, a->totals.photos);
    EXPECT_EQ(secondPass, b->totals.photos);
    // The export: one capture per photo it keeps.
    io::ExportContext ctx;
    ctx.mission = both;
    ctx.routes = {route};
    auto items = io::missionItems(ctx, 0);
    ASSERT_TRUE(items.ok()) << items.error().message;
    int captures = 0;
    for (const auto& it : *items)
        captures += it.command == io::mav::kImageStartCapture;
    const auto merged = io::mergeCloseWaypoints(route.waypoints, 0.1);
    EXPECT_EQ(captures,
              photosOf(route::Route{route.aircraft, route.home, route.cruiseSpeedMps, merged}));
    EXPECT_LE(singles - captures, 1); // at most where the passes meet
    EXPECT_NE(d->plannerChoice.find("double grid"), std::string::npos) << d->plannerChoice;
}

// Each pass is checked on its own: every point is seen twice, once by each.
TEST(DoubleGrid, CoverageCountsEachPass) {
    Mission m = areaMission(300, 260);
    m.options.planner = PlannerKind::Auto;
    m.options.doubleGrid = true;
    auto p = planMission(m);
    ASSERT_TRUE(p.ok()) << p.error().message;
    ASSERT_EQ(p->passCoverage.size(), 2u);
    EXPECT_GE(p->passCoverage[0], 0.995);
    EXPECT_GE(p->passCoverage[1], 0.995);
    EXPECT_DOUBLE_EQ(p->coverageRatio, std::min(p->passCoverage[0], p->passCoverage[1]));
    // A second pass of one photo covers little: the check says so, whatever the first sees.
    const geo::MultiPolygon ground{
        geo::Polygon{{Vec2(0, 0), Vec2(100, 0), Vec2(100, 100), Vec2(0, 100)}, {}}};
    std::vector<plan::PhotoFootprint> photos;
    std::vector<int> passes;
    for (int x = 10; x < 100; x += 20)
        for (int y = 10; y < 100; y += 20) {
            photos.push_back({Vec2(x, y), 0.0, 30.0, 30.0});
            passes.push_back(0);
        }
    photos.push_back({Vec2(50, 50), 90.0, 30.0, 30.0});
    passes.push_back(1);
    std::vector<double> perPass;
    auto cov = checkPassCoverage(ground, photos, passes, nullptr, perPass);
    ASSERT_TRUE(cov.ok());
    ASSERT_EQ(perPass.size(), 2u);
    EXPECT_GT(perPass[0], 0.999);
    EXPECT_NEAR(perPass[1], 0.09, 0.01);
    EXPECT_NEAR(cov->coveredFraction, perPass[1], 1e-12);
}

// Both passes keep the zones' margins and are cut into sorties like any flight; two aircraft share
// the area and leave out only photos of their own pass that the other already takes.
TEST(DoubleGrid, ZonesSortiesAndSeveralAircraft) {
    Mission m = areaMission(400, 300);
    auto frame = geo::LocalFrame::create(kOrigin);
    m.noFlyZones.push_back(
        {"Tank", geo::GeoPolygon{frame->toGeo(std::vector<Vec2>{Vec2(150, 100), Vec2(200, 100),
                                                                Vec2(200, 160), Vec2(150, 160)}),
                                 {}}});
    m.options.doubleGrid = true;
    m.aircraft.front().enduranceMin = 6;
    auto p = planMission(m);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->noFlyViolations, 0);
    EXPECT_GT(p->aircraft.front().sorties.size(), 1u);
    ASSERT_EQ(p->passCoverage.size(), 2u);
    EXPECT_GE(p->passCoverage[0], 0.99);
    EXPECT_GE(p->passCoverage[1], 0.99);

    m.aircraft.front().enduranceMin = 600;
    AircraftConfig second = m.aircraft.front();
    second.name = "Falcon 2";
    second.altitudeM = 55;
    m.aircraft.push_back(second);
    auto two = planMission(m);
    ASSERT_TRUE(two.ok()) << two.error().message;
    ASSERT_EQ(two->passCoverage.size(), 2u);
    EXPECT_GE(two->passCoverage[0], 0.995);
    EXPECT_GE(two->passCoverage[1], 0.995);
    EXPECT_EQ(two->noFlyViolations, 0);
}

TEST(DoubleGrid, ReversedFlightFacesTheOtherWay) {
    std::vector<route::LocalWaypoint> w{{Vec2(0, 0), 90.0, route::WaypointKind::Photo, -1},
                                        {Vec2(10, 0), 90.0, route::WaypointKind::Photo, -1},
                                        {Vec2(10, 10), 0.0, route::WaypointKind::Transit, -1},
                                        {Vec2(0, 10), 270.0, route::WaypointKind::Photo, -1}};
    const auto r = reversedFlight(w);
    ASSERT_EQ(r.size(), 4u);
    EXPECT_EQ(r.front().pos, Vec2(0, 10));
    EXPECT_DOUBLE_EQ(r.front().headingDeg, 90.0);
    EXPECT_NEAR(r[1].headingDeg, 180.0, 1e-9); // the transit faces the next point, south
    EXPECT_DOUBLE_EQ(r.back().headingDeg, 270.0);
    EXPECT_DOUBLE_EQ(dominantLaneAngleDeg(w), 0.0);
}

} // namespace
} // namespace pf::mission
