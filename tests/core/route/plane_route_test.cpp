// A plane's route over lanes: the skip pattern where lanes lie closer than two turn radii, turns
// within the minimum radius, photos only on lanes, the time against a boustrophedon with semicircle
// turns worked out by hand, and straight legs at radius 0.
#include "core/route/plane_route.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

using namespace pf;
using namespace pf::route;
using geo::Vec2;

namespace {

// `n` lanes of `length` m along x, `spacing` apart in y, photos every 20 m (as the sweep gives them:
// flown from photos.front() to photos.back()).
std::vector<plan::Lane> rectangleLanes(int n, double length, double spacing) {
    std::vector<plan::Lane> lanes;
    for (int i = 0; i < n; ++i) {
        const double y = i * spacing;
        lanes.push_back(plan::makeLane({0, y}, {length, y}, 20.0));
    }
    return lanes;
}

std::vector<Vec2> positions(const PlaneRoute& r) {
    std::vector<Vec2> out;
    for (const auto& w : r.waypoints)
        out.push_back(w.pos);
    return out;
}

double polylineLength(const std::vector<Vec2>& p) {
    double l = 0.0;
    for (std::size_t i = 1; i < p.size(); ++i)
        l += (p[i] - p[i - 1]).norm();
    return l;
}

// Photos only on lanes: every photo of the input once, each lane's photos one after the other
// without a turn point between them (and, with `turns`, a turn point between two lanes).
void expectPhotosOnlyOnLanes(const PlaneRoute& r, const std::vector<plan::Lane>& lanes, bool turns = true) {
    std::map<std::pair<long, long>, int> laneOf;
    std::size_t total = 0;
    for (std::size_t i = 0; i < lanes.size(); ++i)
        for (const auto& p : lanes[i].photos) {
            laneOf[{std::lround(p.x() * 1000), std::lround(p.y() * 1000)}] = static_cast<int>(i);
            ++total;
        }
    std::size_t photos = 0;
    int current = -1;
    std::set<int> done;
    for (const auto& w : r.waypoints) {
        if (w.kind != WaypointKind::Photo) {
            if (current >= 0)
                done.insert(current);
            current = -1;
            continue;
        }
        ++photos;
        const auto it = laneOf.find({std::lround(w.pos.x() * 1000), std::lround(w.pos.y() * 1000)});
        ASSERT_NE(it, laneOf.end()) << "a photo off every lane at " << w.pos.x() << ", " << w.pos.y();
        if (current != it->second) {
            EXPECT_EQ(done.count(it->second), 0u) << "lane " << it->second << " photographed in two pieces";
            if (turns)
                EXPECT_EQ(current, -1) << "two lanes' photos without a turn between them";
            else if (current >= 0)
                done.insert(current);
            current = it->second;
        }
    }
    EXPECT_EQ(photos, total);
}

} // namespace

// Lanes 20 m apart, radius 30 m: a turn to the next lane would be a loop, so the order flies every
// third lane (3 x 20 >= 2 x 30) and comes back (or a greedy order as wide, when it flies sooner); it is shorter than the boustrophedon and almost every
// turn spans two radii or more.
TEST(PlaneRoute, SkipPatternWhereLanesAreCloserThanTwoRadii) {
    const auto lanes = rectangleLanes(12, 400.0, 20.0);
    PlaneRouteOptions o;
    o.radiusM = 30.0;
    o.runInM = 0.0;
    o.trackSpacingM = 20.0;
    const PlaneRoute r = planPlaneRoute(lanes, o);
    ASSERT_EQ(r.order.size(), lanes.size());
    EXPECT_NE(r.skipEvery, 1); // not the boustrophedon (a skip pattern or a greedy order, 0)
    // Only the passes' ends (the k - 1 changes of residue, k = 3) may turn to a lane nearer than 2R.
    int wide = 0;
    for (std::size_t i = 1; i < r.order.size(); ++i)
        wide += std::abs(r.order[i] - r.order[i - 1]) * 20.0 >= 2 * o.radiusM ? 1 : 0;
    EXPECT_GE(wide, static_cast<int>(lanes.size()) - 3);
    // The boustrophedon over the same lanes, as a plane flies it.
    std::vector<DirectedLane> boustro;
    for (std::size_t i = 0; i < lanes.size(); ++i) {
        const auto& p = lanes[i].photos;
        boustro.push_back(i % 2 == 0 ? DirectedLane{p.front(), p.back()} : DirectedLane{p.back(), p.front()});
    }
    const double boustroM = planeLanesEstimate(boustro, o.radiusM, 0.0, plan::FlightTimeModel{}).lengthM();
    EXPECT_LT(r.lengthM, 0.95 * boustroM);
    EXPECT_NEAR(polylineLength(positions(r)), r.lengthM, 0.002 * r.lengthM);
    EXPECT_LE(maxCurvature(positions(r)), 1.0 / o.radiusM * 1.001);
    expectPhotosOnlyOnLanes(r, lanes);
}

// Spacing at least two radii: a boustrophedon with semicircle turns of diameter `spacing`, worked
// out by hand, is the reference; the route flies no more than 1.05 times it (its Dubins turns, two
// quarter circles of R and a straight, are never longer than the semicircle). Every turn stays within
// the radius, every photo on its lane; run-ins add their length to each lane.
TEST(PlaneRoute, TimeAgainstBoustrophedonWithSemicircles) {
    for (double radius : {10.0, 20.0, 25.0}) {
        const double spacing = 50.0, length = 600.0;
        const int n = 9;
        const auto lanes = rectangleLanes(n, length, spacing);
        PlaneRouteOptions o;
        o.radiusM = radius;
        o.trackSpacingM = spacing;
        const PlaneRoute r = planPlaneRoute(lanes, o);
        const double flownLane = (lanes[0].photos.back() - lanes[0].photos.front()).norm();
        const double reference = n * flownLane + (n - 1) * M_PI * spacing / 2.0;
        EXPECT_LE(r.lengthM, 1.05 * reference) << "R " << radius;
        EXPECT_GE(r.lengthM, n * flownLane + (n - 1) * spacing) << "R " << radius;
        EXPECT_LE(maxCurvature(positions(r)), 1.0 / radius * 1.001);
        expectPhotosOnlyOnLanes(r, lanes);
        // The time is the one model's: the flown polyline over the cruise speed.
        plan::FlightTimeModel m;
        m.dynamics = plan::FlightDynamics::FixedWing;
        m.speedMps = 15.0;
        EXPECT_NEAR(plan::flightTime(positions(r), m).totalS, r.lengthM / 15.0, 0.002 * r.lengthM / 15.0);

        o.runInM = 40.0;
        const PlaneRoute withRunIn = planPlaneRoute(lanes, o);
        int runIns = 0;
        for (std::size_t i = 1; i < withRunIn.waypoints.size(); ++i)
            if (withRunIn.waypoints[i].kind == WaypointKind::Photo &&
                withRunIn.waypoints[i - 1].kind == WaypointKind::Turn) {
                EXPECT_NEAR((withRunIn.waypoints[i].pos - withRunIn.waypoints[i - 1].pos).norm(), 40.0, 1e-6);
                ++runIns;
            }
        EXPECT_EQ(runIns, n);
        EXPECT_LE(maxCurvature(positions(withRunIn)), 1.0 / radius * 1.001);
    }
}

// Radius 0 and no run-in: the lanes as given, joined by straight legs (the multirotor's lane set).
TEST(PlaneRoute, RadiusZeroFliesTheLanesStraight) {
    const auto lanes = rectangleLanes(6, 300.0, 40.0);
    PlaneRouteOptions o;
    o.trackSpacingM = 40.0;
    const PlaneRoute r = planPlaneRoute(lanes, o);
    expectPhotosOnlyOnLanes(r, lanes, false);
    for (const auto& w : r.waypoints)
        EXPECT_EQ(w.kind, WaypointKind::Photo);
    EXPECT_EQ(r.skipEvery, 1);
}

// A zone between two groups of lanes: every turn keeps the margin (sampled legs checked against the
// field), going round the zone where the direct turn would cross it; a lane whose run-in would enter
// the margin starts with a shorter one.
TEST(PlaneRoute, TurnsKeepTheMargins) {
    std::vector<plan::Lane> lanes;
    for (int i = 0; i < 8; ++i) {
        const double y = i * 30.0;
        lanes.push_back(plan::makeLane({0, y}, {150, y}, 20.0));   // left of the zone
        lanes.push_back(plan::makeLane({260, y}, {500, y}, 20.0)); // right of it
    }
    geo::Polygon zone;
    zone.outer = {{170, -40}, {240, -40}, {240, 260}, {170, 260}};
    const geo::NoFlyField field({zone}, 5.0);
    const geo::SafePathFinder detours(geo::NoFlyField({zone}, 5.0 + 0.9 * 15.0));
    PlaneRouteOptions o;
    o.radiusM = 15.0;
    o.runInM = 30.0;
    o.trackSpacingM = 30.0;
    o.field = &field;
    o.detours = &detours;
    const PlaneRoute r = planPlaneRoute(lanes, o);
    EXPECT_EQ(r.unsafeTurns, 0);
    const auto pts = positions(r);
    for (std::size_t i = 1; i < pts.size(); ++i)
        EXPECT_TRUE(field.segmentIsSafe(pts[i - 1], pts[i])) << "leg " << i;
    EXPECT_LE(maxCurvature(pts), 1.0 / 15.0 * 1.001);
    expectPhotosOnlyOnLanes(r, lanes);
}
