#include "core/route/safety.h"

#include "core/geo/polygon_ops.h"
#include "core/plan/coverage_check.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pf;
using namespace pf::route;
using geo::Vec2;

namespace {

geo::Polygon square(double x0, double y0, double s) {
    return geo::Polygon{{Vec2(x0, y0), Vec2(x0 + s, y0), Vec2(x0 + s, y0 + s), Vec2(x0, y0 + s)}, {}};
}

double length(const Vec2& a, const std::vector<Vec2>& mid, const Vec2& b) {
    double len = 0;
    Vec2 p = a;
    for (const auto& q : mid) {
        len += (q - p).norm();
        p = q;
    }
    return len + (b - p).norm();
}

// Exact shortest path from a = (-dist, side/2) to its mirror image over the square [0, side]^2
// grown by a rounded margin: tangent to the corner circle at (0, side), arc to its top point, the
// straight top, and the same mirrored.
double aroundSquareLength(double side, double margin, double dist) {
    const Vec2 a(-dist, side / 2), c(0, side);
    const double d = (c - a).norm();
    const double tangent = std::sqrt(d * d - margin * margin);
    double t = std::atan2(a.y() - c.y(), a.x() - c.x()) - std::acos(margin / d); // tangent point, seen from c
    while (t < 0)
        t += 2 * M_PI;
    const double arc = margin * (t - M_PI / 2);
    return 2 * (tangent + arc) + side;
}

} // namespace

TEST(NoFlyField, ClearanceIsExact) {
    const NoFlyField f({square(40, 40, 20)}, 5.0);
    EXPECT_DOUBLE_EQ(f.clearance(Vec2(30, 50)), 10.0);
    EXPECT_DOUBLE_EQ(f.clearance(Vec2(50, 50)), 0.0);
    EXPECT_NEAR(f.clearance(Vec2(63, 64)), 5.0, 1e-12);
    EXPECT_DOUBLE_EQ(f.clearance(Vec2(0, 36), Vec2(100, 36)), 4.0);
    EXPECT_DOUBLE_EQ(f.clearance(Vec2(0, 0), Vec2(100, 100)), 0.0);
    EXPECT_FALSE(f.segmentIsSafe(Vec2(0, 36), Vec2(100, 36)));
    EXPECT_TRUE(f.pointIsSafe(Vec2(63, 64)));
    EXPECT_FALSE(f.pointIsSafe(Vec2(62, 62)));
}

TEST(SafePathFinder, DetourAroundASquareIsShortAndSafe) {
    const double side = 20, margin = 5;
    const SafePathFinder finder(NoFlyField({square(0, 0, side)}, margin));
    const Vec2 a(-40, 10), b(60, 10);
    auto mid = finder.detour(a, b);
    ASSERT_TRUE(mid.ok()) << mid.error().message;
    ASSERT_FALSE(mid->empty());
    Vec2 p = a;
    for (const auto& q : *mid) {
        EXPECT_TRUE(finder.field().pointIsSafe(q));
        EXPECT_TRUE(finder.field().segmentIsSafe(p, q));
        p = q;
    }
    EXPECT_TRUE(finder.field().segmentIsSafe(p, b));
    // Within 3 % of the exact shortest path around the rounded margin.
    const double exact = aroundSquareLength(side, margin, 40);
    const double got = length(a, *mid, b);
    EXPECT_GE(got, exact - 1e-6);
    EXPECT_LE(got, 1.03 * exact);
}

TEST(SafePathFinder, StraightWhenClear) {
    const SafePathFinder finder(NoFlyField({square(0, 0, 20)}, 5));
    auto mid = finder.detour(Vec2(-10, 30), Vec2(40, 30));
    ASSERT_TRUE(mid.ok());
    EXPECT_TRUE(mid->empty());
}

TEST(SafePathFinder, ErrorsNameThePointAndTheMargin) {
    const SafePathFinder finder(NoFlyField({square(0, 0, 20)}, 5));
    auto inside = finder.detour(Vec2(10, 10), Vec2(40, 30));
    ASSERT_FALSE(inside.ok());
    EXPECT_EQ(inside.error().code, ErrorCode::NoPath);
    EXPECT_EQ(inside.error().message, "The point (10.0, 10.0) m lies within the 5.0 m safety margin of a no-fly zone.");
    // A courtyard closed on all sides: no way out.
    geo::Polygon donut = square(0, 0, 100);
    donut.holes.push_back(square(30, 30, 40).outer);
    const SafePathFinder closed(NoFlyField({donut}, 2));
    auto none = closed.detour(Vec2(50, 50), Vec2(150, 50));
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().code, ErrorCode::NoPath);
    EXPECT_EQ(none.error().message,
              "No safe way from (50.0, 50.0) m to (150.0, 50.0) m keeps the 2.0 m margin around the no-fly zones.");
}

TEST(Heading, ClockwiseFromNorth) {
    EXPECT_DOUBLE_EQ(headingDeg(Vec2(0, 0), Vec2(0, 1)), 0.0);
    EXPECT_DOUBLE_EQ(headingDeg(Vec2(0, 0), Vec2(1, 0)), 90.0);
    EXPECT_DOUBLE_EQ(headingDeg(Vec2(0, 0), Vec2(0, -1)), 180.0);
    EXPECT_DOUBLE_EQ(headingDeg(Vec2(0, 0), Vec2(-1, 0)), 270.0);
    EXPECT_NEAR(headingDeg(Vec2(0, 0), Vec2(1, 1)), 45.0, 1e-12);
}

TEST(EnforceNoFly, MovesWaypointsOutAndDetoursLegs) {
    const std::vector<geo::Polygon> zones{square(40, 40, 20), square(100, -20, 10)};
    const SafePathFinder finder(NoFlyField(zones, 5));
    std::vector<LocalWaypoint> wps;
    for (Vec2 p : {Vec2(0, 50), Vec2(50, 62), Vec2(100, 50), Vec2(100, 0), Vec2(130, -15)}) {
        LocalWaypoint w;
        w.pos = p;
        w.headingDeg = 90;
        wps.push_back(w);
    }
    SafetyReport rep;
    auto out = enforceNoFly(wps, finder, &rep);
    ASSERT_TRUE(out.ok()) << out.error().message;
    EXPECT_EQ(rep.waypointsMoved, 1); // (50, 62) is 2 m from the zone
    EXPECT_GE(rep.detours, 2);
    EXPECT_EQ(rep.detourWaypoints, static_cast<int>(out->size() - wps.size()));
    EXPECT_GT(rep.addedLengthM, 0.0);
    ASSERT_EQ(rep.warnings.size(), 1u);
    std::vector<Vec2> path;
    for (std::size_t i = 0; i < out->size(); ++i) {
        const auto& w = (*out)[i];
        path.push_back(w.pos);
        if (w.kind == WaypointKind::Transit) {
            ASSERT_LT(i + 1, out->size());
            EXPECT_NEAR(w.headingDeg, headingDeg(w.pos, (*out)[i + 1].pos), 1e-9);
        }
    }
    EXPECT_EQ(plan::countNoFlyViolations({path}, zones, 5).total(), 0);
}

TEST(KeepInsideArea, ProjectsOnlyAsFarAsCoverageAllows) {
    const geo::MultiPolygon area{square(0, 0, 100)};
    const SafePathFinder finder;
    PhotoSides sides{20, 10, 40, 30};
    LocalWaypoint w;
    w.pos = Vec2(-3, 50);
    w.headingDeg = 0; // flying north: across = east-west
    // Margin 15: the target (15, 50) still sees x in [-5, 35], which holds [0, 7]: moved fully.
    SafetyReport rep;
    auto a = keepInsideArea({w}, area, area, sides, 15, finder, &rep);
    ASSERT_TRUE(a.ok()) << a.error().message;
    EXPECT_NEAR((*a)[0].pos.x(), 15.0, 1e-9);
    EXPECT_NEAR((*a)[0].pos.y(), 50.0, 1e-9);
    EXPECT_EQ(rep.keptInside, 1);
    EXPECT_EQ(rep.leftOutside, 0);
    // Margin 25: at (25, 50) the photo would start at x = 5 and miss [0, 5]; it stops at x = 20.
    SafetyReport rep2;
    auto b = keepInsideArea({w}, area, area, sides, 25, finder, &rep2);
    ASSERT_TRUE(b.ok());
    EXPECT_NEAR((*b)[0].pos.x(), 20.0, 0.01);
    EXPECT_EQ(rep2.leftOutside, 1);
    ASSERT_EQ(rep2.warnings.size(), 1u);
    EXPECT_EQ(rep2.warnings[0],
              "Photo waypoint 1 stays 5.0 m outside the area: moving it further in would leave part of its ground "
              "unphotographed.");
    // The responsibility is still photographed.
    auto cov = plan::checkCoverage(
        geo::intersection(area, geo::Polygon{plan::footprintRing({w.pos, 0, 20, 10}), {}}),
        {{(*b)[0].pos, 0, 40, 30}});
    ASSERT_TRUE(cov.ok());
    EXPECT_DOUBLE_EQ(cov->coveredFraction, 1.0);
    // Waypoints already inside and Transit waypoints do not move.
    LocalWaypoint in = w, transit = w;
    in.pos = Vec2(50, 50);
    transit.kind = WaypointKind::Transit;
    auto c = keepInsideArea({in, transit}, area, area, sides, 5, finder);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ((*c)[0].pos, in.pos);
    EXPECT_EQ((*c)[1].pos, transit.pos);
}

TEST(KeepInsideArea, BadInputsAreRejectedWithAMessage) {
    const geo::MultiPolygon area{square(0, 0, 100)};
    auto big = keepInsideArea({}, area, area, PhotoSides{20, 10, 40, 30}, 60, SafePathFinder());
    ASSERT_FALSE(big.ok());
    EXPECT_EQ(big.error().message, "The area shrunk by the inside margin of 60.0 m is empty: reduce the margin.");
    auto sides = keepInsideArea({}, area, area, PhotoSides{0, 10, 40, 30}, 5, SafePathFinder());
    ASSERT_FALSE(sides.ok());
    EXPECT_EQ(sides.error().message, "Keeping waypoints inside the area needs positive footprint sides.");
    auto neg = keepInsideArea({}, area, area, PhotoSides{20, 10, 40, 30}, -1, SafePathFinder());
    ASSERT_FALSE(neg.ok());
    EXPECT_EQ(neg.error().message, "The inside margin must not be negative.");
}
