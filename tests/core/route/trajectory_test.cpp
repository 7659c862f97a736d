#include "core/route/trajectory.h"

#include "core/geo/polygon_ops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pf;
using namespace pf::route;

namespace {

std::vector<LocalWaypoint> path(const std::vector<geo::Vec2>& pts, double heading = 0.0) {
    std::vector<LocalWaypoint> out;
    for (const auto& p : pts)
        out.push_back({p, heading, WaypointKind::Photo, -1});
    return out;
}

geo::Polygon rect(double x0, double y0, double x1, double y1) {
    return {{geo::Vec2(x0, y0), geo::Vec2(x1, y0), geo::Vec2(x1, y1), geo::Vec2(x0, y1)}, {}};
}

// Index of the first consecutive sample pair that enters the keep-out set, or -1.
long firstIntrusion(const Trajectory& t, const geo::MultiPolygon& keepOut) {
    for (std::size_t i = 1; i < t.samples.size(); ++i)
        if (geo::segmentCrossesInterior(keepOut, t.samples[i - 1].pos, t.samples[i].pos))
            return static_cast<long>(i);
    return -1;
}

bool passesThrough(const Trajectory& t, const geo::Vec2& p) {
    for (const auto& s : t.samples)
        if ((s.pos - p).norm() < 1e-9)
            return true;
    return false;
}

} // namespace

TEST(Trajectory, PassesThroughEveryWaypointWithTheRequestedSpacing) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-200, 200);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<geo::Vec2> pts;
        for (int i = 0; i < 3 + trial % 8; ++i)
            pts.emplace_back(u(rng), u(rng));
        TrajectoryOptions opt;
        opt.spacingM = 0.5 + trial % 4;
        auto t = buildTrajectory(path(pts), {}, opt);
        ASSERT_TRUE(t.ok()) << t.error().message;
        for (const auto& p : pts)
            EXPECT_TRUE(passesThrough(*t, p));
        EXPECT_EQ((t->samples.front().pos - pts.front()).norm(), 0.0);
        EXPECT_EQ((t->samples.back().pos - pts.back()).norm(), 0.0);
        double chordSum = 0.0;
        for (std::size_t i = 1; i < pts.size(); ++i)
            chordSum += (pts[i] - pts[i - 1]).norm();
        for (std::size_t i = 1; i < t->samples.size(); ++i) {
            const double d = (t->samples[i].pos - t->samples[i - 1].pos).norm();
            EXPECT_LE(d, opt.spacingM + 1e-6);
            EXPECT_NEAR(t->samples[i].distanceM - t->samples[i - 1].distanceM, d, 1e-9);
        }
        EXPECT_NEAR(t->samples.back().distanceM, t->lengthM, 1e-9);
        // A curve through the points is at least as long as the straight line between its ends.
        EXPECT_GE(t->lengthM, (pts.back() - pts.front()).norm() - 1e-9);
        EXPECT_EQ(t->straightLegs.size(), pts.size() - 1);
        EXPECT_TRUE(t->unsafeLegs.empty());
    }
}

TEST(Trajectory, YawTurnsThroughNorthWithoutWrappingRound) {
    auto wps = path({{0, 0}, {20, 0}, {40, 0}});
    wps[0].headingDeg = 350.0;
    wps[1].headingDeg = 10.0;
    wps[2].headingDeg = 30.0;
    auto t = buildTrajectory(wps, {}, {});
    ASSERT_TRUE(t.ok());
    for (const auto& s : t->samples) {
        EXPECT_GE(s.yawDeg, 0.0);
        EXPECT_LT(s.yawDeg, 360.0);
        // A turn the long way round would pass through south (180).
        EXPECT_TRUE(s.yawDeg >= 330.0 || s.yawDeg <= 50.0) << s.yawDeg;
    }
    EXPECT_NEAR(t->samples.front().yawDeg, 350.0, 1e-9);
    EXPECT_NEAR(t->samples.back().yawDeg, 30.0, 1e-9);
    EXPECT_NEAR(t->headingChangeDeg, 40.0, 1e-9);
}

TEST(Trajectory, CollinearWaypointsGiveTheHandComputedFlightTime) {
    // 30 m along a line (the curve stays on it), headings 0 -> 90 -> 180 -> 270 -> 0: four 90
    // degree turns.
    auto wps = path({{0, 0}, {10, 0}, {20, 0}, {25, 0}, {30, 0}});
    const double headings[] = {0, 90, 180, 270, 0};
    for (int i = 0; i < 5; ++i)
        wps[i].headingDeg = headings[i];
    auto t = buildTrajectory(wps, {}, {});
    ASSERT_TRUE(t.ok());
    EXPECT_NEAR(t->lengthM, 30.0, 1e-9);
    EXPECT_NEAR(t->headingChangeDeg, 360.0, 1e-9);
    auto e = estimateFlight(*t, 10.0, 90.0);
    ASSERT_TRUE(e.ok());
    EXPECT_NEAR(e->timeS, 30.0 / 10.0 + 360.0 / 90.0, 1e-9); // 7 s
}

TEST(Trajectory, StraightLegKeptStraightGivesThePapersPolylineTime) {
    // Two waypoints 100 m apart: the at-rest spline is the straight leg. Heading 90 -> 180, v = 5,
    // w = 30: T = 100 / 5 + 90 / 30 = 23 s.
    auto wps = path({{0, 0}, {60, 80}});
    wps[0].headingDeg = 90;
    wps[1].headingDeg = 180;
    auto t = buildTrajectory(wps, {}, {});
    ASSERT_TRUE(t.ok());
    EXPECT_NEAR(t->lengthM, 100.0, 1e-9);
    auto e = estimateFlight(*t, 5.0, 30.0);
    ASSERT_TRUE(e.ok());
    EXPECT_NEAR(e->timeS, 23.0, 1e-9);
    EXPECT_NEAR(totalHeadingChangeDeg({350, 10, 350, 170}), 20 + 20 + 180, 1e-9);
}

TEST(Trajectory, ZigZagNextToANoFlyZoneNeverCutsIn) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> spacing(4, 30), amplitude(5, 60);
    int held = 0;
    for (int trial = 0; trial < 20; ++trial) {
        // An irregular zig-zag whose lower vertices lie on the edge of the buffered zone below y =
        // 0: a curve through them swings below the line unless it is held back.
        std::vector<geo::Vec2> pts;
        double x = 0.0;
        for (int i = 0; i < 9; ++i) {
            pts.emplace_back(x, i % 2 == 0 ? 0.0 : amplitude(rng));
            x += spacing(rng);
        }
        const geo::MultiPolygon keepOut{rect(-20, -40, x + 20, 0)};
        auto free = buildTrajectory(path(pts), {}, {});
        ASSERT_TRUE(free.ok());
        if (firstIntrusion(*free, keepOut) >= 0)
            ++held;

        auto t = buildTrajectory(path(pts), keepOut, {});
        ASSERT_TRUE(t.ok());
        EXPECT_EQ(firstIntrusion(*t, keepOut), -1) << "trial " << trial;
        EXPECT_TRUE(t->unsafeLegs.empty());
        for (const auto& p : pts)
            EXPECT_TRUE(passesThrough(*t, p));
    }
    // The test means something only if the free curve does cut in for most shapes.
    EXPECT_GE(held, 15);
}

TEST(Trajectory, LawnmowerTurnsBesideAZoneAreHeldBackOnlyWhereNeeded) {
    // Turns at y = 100 touch a zone above; turns at y = 0 are far from anything and stay curved.
    const std::vector<geo::Vec2> pts{{0, 0},    {0, 100},  {10, 100}, {10, 0}, {20, 0},
                                     {20, 100}, {30, 100}, {30, 0},   {40, 0}, {40, 100}};
    const geo::MultiPolygon keepOut{rect(-20, 100, 60, 130)};
    auto t = buildTrajectory(path(pts), keepOut, {});
    ASSERT_TRUE(t.ok());
    EXPECT_EQ(firstIntrusion(*t, keepOut), -1);
    // The bottom turn legs (10,0)->(20,0) and (30,0)->(40,0) keep their curve.
    EXPECT_FALSE(t->straightLegs[3]);
    EXPECT_FALSE(t->straightLegs[7]);
}

TEST(Trajectory, ReportsLegsThatAreUnsafeEvenWhenStraight) {
    const geo::MultiPolygon keepOut{rect(40, -10, 60, 10)};
    auto t = buildTrajectory(path({{0, 0}, {100, 0}, {100, 50}}), keepOut, {});
    ASSERT_TRUE(t.ok());
    ASSERT_EQ(t->unsafeLegs.size(), 1u);
    EXPECT_EQ(t->unsafeLegs[0], 0u);
}

TEST(Trajectory, MergesCoincidentWaypointsAndCountsTheirTurn) {
    auto wps = path({{0, 0}, {0, 0}, {50, 0}});
    wps[0].headingDeg = 0;
    wps[1].headingDeg = 90;
    wps[2].headingDeg = 90;
    auto t = buildTrajectory(wps, {}, {});
    ASSERT_TRUE(t.ok());
    EXPECT_NEAR(t->lengthM, 50.0, 1e-9);
    EXPECT_NEAR(t->headingChangeDeg, 90.0, 1e-12);
    ASSERT_EQ(t->straightLegs.size(), 2u);
    EXPECT_TRUE(t->straightLegs[0]); // zero length
}

TEST(Trajectory, RouteOverloadStartsAndEndsAtHome) {
    auto frame = geo::LocalFrame::create({8.3299, 49.0120});
    ASSERT_TRUE(frame.ok());
    Route r;
    r.home = geo::LonLat{8.3270554, 49.010741};
    r.waypoints.push_back({{8.3280, 49.0115}, 40, 90, WaypointKind::Photo});
    r.waypoints.push_back({{8.3300, 49.0115}, 40, 90, WaypointKind::Photo});
    auto t = buildTrajectory(r, *frame, {}, {});
    ASSERT_TRUE(t.ok());
    const auto geoPts = toGeo(*t, *frame);
    EXPECT_NEAR(geoPts.front().lon, r.home->lon, 1e-9);
    EXPECT_NEAR(geoPts.front().lat, r.home->lat, 1e-9);
    EXPECT_NEAR(geoPts.back().lon, r.home->lon, 1e-9);
    EXPECT_NEAR(geoPts.back().lat, r.home->lat, 1e-9);
    EXPECT_EQ(t->straightLegs.size(), 3u);
}

TEST(Trajectory, KeepOutZonesAreBufferedInTheLocalFrame) {
    auto frame = geo::LocalFrame::create({8.3299, 49.0120});
    ASSERT_TRUE(frame.ok());
    const geo::GeoPolygon warehouse{{{8.3291782, 49.0118201},
                                     {8.3297261, 49.0118201},
                                     {8.3297261, 49.0121799},
                                     {8.3291782, 49.0121799}},
                                    {}};
    const auto zones = keepOutZones({warehouse}, *frame, 5.0);
    const double raw = geo::area(frame->toLocal(warehouse));
    ASSERT_EQ(zones.size(), 1u);
    EXPECT_GT(geo::area(zones), raw + 4 * 5.0 * std::sqrt(raw) * 0.9);
}

TEST(Trajectory, RejectsBadOptionsAndEstimates) {
    TrajectoryOptions opt;
    opt.spacingM = 0;
    auto t = buildTrajectory(path({{0, 0}, {1, 0}}), {}, opt);
    ASSERT_FALSE(t.ok());
    EXPECT_EQ(t.error().message,
              "the trajectory sample spacing must be a positive number of metres");
    auto ok = buildTrajectory(path({{0, 0}, {1, 0}}), {}, {});
    ASSERT_TRUE(ok.ok());
    auto e = estimateFlight(*ok, 0.0, 10.0);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().message, "the cruise speed must be positive to estimate a flight time");
    auto w = estimateFlight(*ok, 1.0, -1.0);
    ASSERT_FALSE(w.ok());
    EXPECT_EQ(w.error().message, "the turn rate must be positive to estimate a flight time");
}
