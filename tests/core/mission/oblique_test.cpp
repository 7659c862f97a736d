// Oblique photos (a camera tilted forward): planned for the photos' centres, flown from behind
// them, the double grid's two passes covered by the tilted footprints, the margins kept by the
// aircraft, every lane joined along its line, and the missions it refuses.
#include "core/mission/oblique.h"
#include "core/mission/plan_mission.h"
#include "core/mission/route_check.h"
#include "core/mission/validation.h"

#include "core/geo/local_frame.h"
#include "core/geo/no_fly_field.h"
#include "core/geo/polygon_ops.h"
#include "core/plan/coverage_check.h"
#include "core/route/photo_waypoints.h"
#include "core/sensor/footprint.h"
#include "tests/sample_missions.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf::mission {
namespace {

using geo::Vec2;

const geo::LonLat kOrigin{8.33, 49.01};

Mission block(double w, double h, double tiltDeg) {
    auto frame = geo::LocalFrame::create(kOrigin);
    Mission m;
    m.name = "Burnt hall";
    m.area = geo::GeoPolygon{
        frame->toGeo(std::vector<Vec2>{Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)}), {}};
    m.home = frame->toGeo(Vec2(-30, -30));
    AircraftConfig a = pf::test::bigSiteAircraft(40.0);
    a.name = "Matrice";
    a.overlap = {0.75, 0.65};
    a.enduranceMin = 600;
    m.aircraft.push_back(a);
    m.options.cameraTiltDeg = tiltDeg;
    return m;
}

Vec2 ahead(double headingDeg, double d) {
    const double h = headingDeg * M_PI / 180.0;
    return d * Vec2(std::sin(h), std::cos(h));
}

TEST(Oblique, DoubleGridSeesEveryPointTwiceWithTheTiltedFootprints) {
    Mission m = block(300, 220, 30.0);
    m.options.doubleGrid = true;
    auto p = planMission(m);
    ASSERT_TRUE(p.ok()) << p.error().message;
    const AircraftPlan& a = p->aircraft.front();
    // The tilted camera's footprint (sensor::footprintAt), its centre ahead of the aircraft.
    sensor::Camera tilted = m.aircraft.front().camera;
    tilted.tiltDeg = 30.0;
    auto fp = sensor::footprintAt(tilted, 40.0);
    ASSERT_TRUE(fp.ok());
    EXPECT_NEAR(a.footprint.real.aheadM, fp->aheadM, 1e-9);
    EXPECT_GT(fp->aheadM, 15.0);
    // Each pass, measured here from the photo waypoints with the tilted footprint placed ahead.
    ASSERT_TRUE(p->frame);
    const geo::MultiPolygon ground{p->frame->toLocal(m.area)}; // the plan's frame
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<plan::PhotoFootprint> photos;
        for (const auto& w : a.localWaypoints)
            if (w.kind == route::WaypointKind::Photo && w.pass == pass)
                photos.push_back(sensor::photoTakenFrom(w.pos, w.headingDeg, *fp));
        auto cov = plan::checkCoverage(ground, photos);
        ASSERT_TRUE(cov.ok());
        EXPECT_GE(cov->coveredFraction, 0.995) << "pass " << pass;
        // The photos at the lanes' starts are taken from outside the area, behind the ground
        // they show (its edge), which lies inside.
        int fromOutside = 0;
        for (const auto& f : photos) {
            const Vec2 from = f.pos - ahead(f.headingDeg, fp->aheadM);
            fromOutside += !geo::contains(ground.front(), from) && geo::contains(ground.front(), f.pos);
        }
        EXPECT_GT(fromOutside, 5) << "pass " << pass;
    }
    ASSERT_EQ(p->passCoverage.size(), 2u);
    EXPECT_GE(p->passCoverage[0], 0.995);
    EXPECT_GE(p->passCoverage[1], 0.995);
    // Four directions of view: north, south, east and west (lanes flown both ways in each pass).
    int facing[4] = {0, 0, 0, 0};
    for (const auto& w : a.localWaypoints)
        if (w.kind == route::WaypointKind::Photo)
            ++facing[static_cast<int>(std::lround(w.headingDeg / 90.0)) % 4];
    for (int d = 0; d < 4; ++d)
        EXPECT_GT(facing[d], 20) << d * 90 << " degrees";
}

TEST(Oblique, EveryLaneIsJoinedAlongItsLineAndTheRouteIsClear) {
    Mission m = block(260, 200, 35.0);
    m.options.doubleGrid = true;
    auto p = planMission(m);
    ASSERT_TRUE(p.ok()) << p.error().message;
    const auto& w = p->aircraft.front().localWaypoints;
    int lanes = 0;
    for (std::size_t i = 1; i < w.size(); ++i) {
        if (w[i].kind != route::WaypointKind::Photo)
            continue;
        const Vec2 d = w[i].pos - w[i - 1].pos;
        ASSERT_GT(d.norm(), 1e-6) << i;
        const double off = std::abs(std::remainder(route::headingDeg(d) - w[i].headingDeg, 360.0));
        EXPECT_LT(off, 10.0) << "photo " << i << " is reached across its lane";
        lanes += w[i - 1].kind == route::WaypointKind::Turn;
    }
    EXPECT_GT(lanes, 10);
    EXPECT_TRUE(routeErrors(m, {p->aircraft.front().route}).empty());
}

TEST(Oblique, AircraftKeepsTheMarginWhereThePhotosReachTheZone) {
    Mission m = block(400, 300, 30.0);
    auto frame = geo::LocalFrame::create(kOrigin);
    const std::vector<Vec2> tank{Vec2(160, 110), Vec2(230, 110), Vec2(230, 180), Vec2(160, 180)};
    m.noFlyZones.push_back({"Tank", geo::GeoPolygon{frame->toGeo(tank), {}}});
    m.options.doubleGrid = true;
    auto p = planMission(m);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->noFlyViolations, 0);
    EXPECT_TRUE(routeErrors(m, {p->aircraft.front().route}).empty());
    // The aircraft keeps the margin; its photos see the ground up to the zone.
    ASSERT_TRUE(p->frame);
    const geo::NoFlyField field = geo::NoFlyField::forCheck({p->frame->toLocal(m.noFlyZones.front().polygon)},
                                                            m.options.safetyMarginM);
    const double aheadM = p->aircraft.front().footprint.real.aheadM;
    int photosSeeingCloser = 0;
    for (const auto& w : p->aircraft.front().localWaypoints) {
        EXPECT_TRUE(field.pointIsSafe(w.pos));
        if (w.kind == route::WaypointKind::Photo)
            photosSeeingCloser += field.clearance(w.pos + ahead(w.headingDeg, aheadM)) < field.clearance(w.pos);
    }
    EXPECT_GT(photosSeeingCloser, 0);
    ASSERT_EQ(p->passCoverage.size(), 2u);
    EXPECT_GE(p->passCoverage[0], 0.99);
    EXPECT_GE(p->passCoverage[1], 0.99);
}

// The sorties are cut from the route the aircraft flies (photos moved back, lead-ins, diagonals):
// no battery is asked for more than it holds, and the sorties' photos are all the plan's.
TEST(Oblique, SortiesAreCutFromTheFlightAsFlown) {
    Mission m = block(420, 300, 30.0);
    m.options.doubleGrid = true;
    m.aircraft.front().enduranceMin = 7.0;
    auto p = planMission(m);
    ASSERT_TRUE(p.ok()) << p.error().message;
    const AircraftPlan& a = p->aircraft.front();
    ASSERT_GT(a.sorties.size(), 2u);
    const double budgetS = 7.0 * 60.0 * (1.0 - m.options.batteryReserve);
    int photos = 0;
    for (const auto& s : a.sorties) {
        EXPECT_LE(s.timeS, budgetS + 1e-6);
        photos += s.photos;
    }
    EXPECT_EQ(photos, a.metrics.photos);
    ASSERT_EQ(a.sortieRoutes.size(), a.sorties.size());
    EXPECT_TRUE(routeErrors(m, a.sortieRoutes).empty());
    ASSERT_EQ(p->passCoverage.size(), 2u);
    EXPECT_GE(p->passCoverage[0], 0.995);
    EXPECT_GE(p->passCoverage[1], 0.995);
}

TEST(Oblique, MovesPhotosBackAlongTheirLaneAndLeadsOntoIt) {
    using route::WaypointKind;
    std::vector<route::LocalWaypoint> w{{Vec2(0, 0), 0.0, WaypointKind::Photo, -1},
                                        {Vec2(0, 20), 0.0, WaypointKind::Photo, -1},
                                        {Vec2(15, 30), 90.0, WaypointKind::Turn, -1},
                                        {Vec2(30, 20), 180.0, WaypointKind::Photo, -1},
                                        {Vec2(30, 0), 180.0, WaypointKind::Photo, -1}};
    moveToAircraft(w, 25.0);
    ASSERT_EQ(w.size(), 5u); // moved, nothing added
    EXPECT_NEAR(w[0].pos.y(), -25.0, 1e-9);
    leadOntoLanes(w, nullptr);
    // The first lane gets its lead-in (nothing before it), the corner stays, the second lane gets
    // a lead-in too (reached across from the corner).
    ASSERT_EQ(w.size(), 7u);
    EXPECT_EQ(w[0].kind, WaypointKind::Turn);
    EXPECT_NEAR(w[0].pos.y(), -25.0 - kObliqueLeadInM, 1e-9);
    EXPECT_NEAR(w[1].pos.y(), -25.0, 1e-9);
    EXPECT_NEAR(w[2].pos.y(), -5.0, 1e-9);
    EXPECT_EQ(w[3].pos, Vec2(15, 30));
    EXPECT_EQ(w[4].kind, WaypointKind::Turn);
    EXPECT_NEAR(w[4].pos.y(), 45.0 + kObliqueLeadInM, 1e-9);
    EXPECT_NEAR(w[5].pos.y(), 45.0, 1e-9);
    EXPECT_NEAR(w[6].pos.y(), 25.0, 1e-9);
    // Nadir photos stay where they are.
    std::vector<route::LocalWaypoint> nadir{{Vec2(0, 0), 0.0, WaypointKind::Photo, -1}};
    moveToAircraft(nadir, 0.0);
    ASSERT_EQ(nadir.size(), 1u);
    EXPECT_EQ(nadir[0].pos, Vec2(0, 0));
    // A lead-in that would come within a zone's margin is made shorter, else left out.
    std::vector<route::LocalWaypoint> nearZone{{Vec2(0, 0), 0.0, WaypointKind::Photo, -1}};
    const geo::NoFlyField field({geo::Polygon{{Vec2(-5, -12), Vec2(5, -12), Vec2(5, -8), Vec2(-5, -8)}, {}}}, 1.0);
    leadOntoLanes(nearZone, &field);
    ASSERT_EQ(nearZone.size(), 2u);
    EXPECT_NEAR(nearZone[0].pos.y(), -kObliqueLeadInM / 2, 1e-9);
    std::vector<route::LocalWaypoint> atZone{{Vec2(0, 0), 0.0, WaypointKind::Photo, -1}};
    const geo::NoFlyField touching({geo::Polygon{{Vec2(-5, -4), Vec2(5, -4), Vec2(5, -1.5), Vec2(-5, -1.5)}, {}}}, 1.0);
    leadOntoLanes(atZone, &touching);
    EXPECT_EQ(atZone.size(), 1u);
    // A photo moved into a margin is taken from the nearest point outside it.
    std::vector<route::LocalWaypoint> pastZone{{Vec2(0, 0), 0.0, WaypointKind::Photo, -1}};
    const geo::SafePathFinder finder(
        geo::NoFlyField({geo::Polygon{{Vec2(-50, -40), Vec2(50, -40), Vec2(50, -20), Vec2(-50, -20)}, {}}}, 5.0));
    EXPECT_EQ(moveToAircraft(pastZone, 25.0, &finder), 1);
    EXPECT_TRUE(finder.field().pointIsSafe(pastZone[0].pos));
    EXPECT_NEAR(pastZone[0].pos.y(), -15.0, 0.3); // the (slightly inflated) margin's edge, north
    // Moved back over a wall into a pocket the margins close off (four walls 2 m apart, 5 m
    // margins): the aircraft could not get there, so it stays on the lane's near side.
    const auto wall = [](double x0, double y0, double x1, double y1) {
        return geo::Polygon{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}, {}};
    };
    const geo::SafePathFinder ring(geo::NoFlyField(
        {wall(-40, -10, 40, -6), wall(-40, 46, 40, 50), wall(-40, -4, -36, 44), wall(36, -4, 40, 44)}, 5.0));
    std::vector<route::LocalWaypoint> intoPocket{{Vec2(0, -25), 180.0, WaypointKind::Photo, -1}};
    EXPECT_EQ(moveToAircraft(intoPocket, 45.0, &ring), 1);
    EXPECT_TRUE(ring.field().pointIsSafe(intoPocket[0].pos));
    EXPECT_NEAR(intoPocket[0].pos.x(), 0.0, 1e-9);
    EXPECT_NEAR(intoPocket[0].pos.y(), -15.0, 0.3);
}

TEST(Oblique, RefusesPlanesAndTiltsOutOfRange) {
    Mission steep = block(200, 200, 50.0);
    auto p = planMission(steep);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("camera tilt must be between 0"), std::string::npos) << p.error().message;
    EXPECT_TRUE(validateMission(steep).hasErrors());

    Mission plane = block(400, 400, 20.0);
    plane.aircraft.front().kind = fleet::AircraftKind::FixedWing;
    plane.aircraft.front().name = "Wing";
    auto q = planMission(plane);
    ASSERT_FALSE(q.ok());
    EXPECT_NE(q.error().message.find("Wing flies as a plane"), std::string::npos) << q.error().message;
    EXPECT_NE(cameraTiltError(plane, plane.aircraft.front(), "Wing"), "");

    Mission nadir = block(200, 200, 0.0);
    EXPECT_EQ(cameraTiltError(nadir, nadir.aircraft.front(), "Matrice"), "");
}

} // namespace
} // namespace pf::mission
