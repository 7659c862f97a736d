#include "core/plan/lawnmower_planner.h"

#include "core/geo/polygon_ops.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf::plan {
namespace {

geo::MultiPolygon rectangle(double w, double h) { return {geo::Polygon{{{0, 0}, {w, 0}, {w, h}, {0, h}}, {}}}; }

geo::MultiPolygon rotated(const geo::MultiPolygon& mp, double deg) {
    const double t = deg * M_PI / 180.0, c = std::cos(t), s = std::sin(t);
    geo::MultiPolygon out = mp;
    for (auto& p : out)
        for (auto& v : p.outer)
            v = geo::Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
    return out;
}

LawnmowerOptions options(double track, double photo) {
    LawnmowerOptions o;
    o.trackSpacingM = track;
    o.photoSpacingM = photo;
    o.time.speedMps = 10;
    o.time.turnRateDegS = 60;
    return o;
}

void expectNear(const geo::Vec2& a, const geo::Vec2& b, const std::string& what) {
    EXPECT_NEAR(a.x(), b.x(), 1e-6) << what;
    EXPECT_NEAR(a.y(), b.y(), 1e-6) << what;
}

// 200 x 100 m, transects along x at the spacings: ceil(100 / 27.7) = 4 transects centred
// across the 100 m (first 8.45 m from the edge), each 200 m long with floor(200 / 19.9) + 1 = 11 photos
// from its entry and one at its exit, 1 m after the last; the home south-west of the area makes the
// first transect the southern one, flown east.
TEST(Lawnmower, RectangleMatchesHandComputedTransects) {
    LawnmowerOptions o = options(27.7, 19.9);
    o.angleDeg = 0;
    o.home = geo::Vec2(-50, -50);
    auto p = planLawnmower(rectangle(200, 100), o);
    ASSERT_TRUE(p.ok()) << p.error().message;
    ASSERT_EQ(p->transects.size(), 4u);
    EXPECT_EQ(p->photos, 48);
    EXPECT_DOUBLE_EQ(p->angleDeg, 0.0);
    const double ys[] = {8.45, 36.15, 63.85, 91.55};
    for (int k = 0; k < 4; ++k) {
        const Lane& l = p->transects[static_cast<std::size_t>(k)];
        const bool east = k % 2 == 0;
        expectNear(l.stripStart, {east ? 0.0 : 200.0, ys[k]}, "entry " + std::to_string(k));
        expectNear(l.stripEnd, {east ? 200.0 : 0.0, ys[k]}, "exit " + std::to_string(k));
        EXPECT_DOUBLE_EQ(l.headingDeg, east ? 90.0 : 270.0);
        ASSERT_EQ(l.photos.size(), 12u);
        // The Survey's trigger: the first photo at the entry, then every trigger distance, one at the exit.
        for (std::size_t j = 0; j < 11; ++j)
            expectNear(l.photos[j], {east ? 19.9 * j : 200.0 - 19.9 * j, ys[k]}, "photo");
        expectNear(l.photos.back(), l.stripEnd, "exit photo");
    }
    // Turnaround 10 m beyond each end, the legs between transects straight.
    ASSERT_EQ(p->flight.size(), 16u);
    expectNear(p->flight[0], {-10, 8.45}, "first turnaround");
    expectNear(p->flight[3], {210, 8.45}, "turnaround");
    expectNear(p->flight[4], {210, 36.15}, "next turnaround");
    expectNear(p->flight[15], {-10, 91.55}, "last turnaround");
    // The time is the one model's over home -> flight -> home.
    std::vector<geo::Vec2> path{*o.home};
    path.insert(path.end(), p->flight.begin(), p->flight.end());
    path.push_back(*o.home);
    const FlightTime t = flightTime(path, o.time);
    EXPECT_DOUBLE_EQ(p->time.totalS, t.totalS);
    EXPECT_EQ(p->time.turns, 8); // two at each of the 3 legs between transects, one at each end of the home legs
}

// An L of 200 x 200 m without its north-east quarter, transects along x, track 25 m and trigger 20 m:
// 8 transects at y = 12.5 + 25 k; the four southern ones run 200 m (11 photos: a length of exactly 10
// trigger distances puts the last one on the exit), the four northern ones 100 m (6 photos).
TEST(Lawnmower, LShapeMatchesHandComputedTransects) {
    const geo::MultiPolygon l{geo::Polygon{{{0, 0}, {200, 0}, {200, 100}, {100, 100}, {100, 200}, {0, 200}}, {}}};
    LawnmowerOptions o = options(25, 20);
    o.angleDeg = 0;
    o.home = geo::Vec2(-20, -20);
    auto p = planLawnmower(l, o);
    ASSERT_TRUE(p.ok()) << p.error().message;
    ASSERT_EQ(p->transects.size(), 8u);
    EXPECT_EQ(p->photos, 4 * 11 + 4 * 6);
    for (int k = 0; k < 8; ++k) {
        const Lane& lane = p->transects[static_cast<std::size_t>(k)];
        const double y = 12.5 + 25.0 * k, xEnd = k < 4 ? 200.0 : 100.0;
        const bool east = k % 2 == 0;
        expectNear(lane.stripStart, {east ? 0.0 : xEnd, y}, "entry");
        expectNear(lane.stripEnd, {east ? xEnd : 0.0, y}, "exit");
        EXPECT_EQ(lane.photos.size(), k < 4 ? 11u : 6u) << k;
        expectNear(lane.photos.back(), {east ? 20.0 * (lane.photos.size() - 1) : xEnd - 20.0 * (lane.photos.size() - 1), y},
                   "last photo");
    }
}

// The Survey does not split concave areas: a transect runs from the line's first to its last crossing
// of the boundary, straight over the notch of a U.
TEST(Lawnmower, ConcaveAreaIsFlownStraightAcross) {
    const geo::MultiPolygon u{
        geo::Polygon{{{0, 0}, {300, 0}, {300, 200}, {200, 200}, {200, 50}, {100, 50}, {100, 200}, {0, 200}}, {}}};
    LawnmowerOptions o = options(25, 20);
    o.angleDeg = 0;
    auto p = planLawnmower(u, o);
    ASSERT_TRUE(p.ok());
    ASSERT_EQ(p->transects.size(), 8u);
    for (const auto& lane : p->transects)
        EXPECT_NEAR((lane.stripEnd - lane.stripStart).norm(), 300.0, 1e-6);
    EXPECT_EQ(p->photos, 8 * 16);
}

// The real footprint of the camera at 30 m (60 x 45 degrees) for the spacings 27.7 and 19.9 m.
LawnmowerOptions withFootprint(LawnmowerOptions o) {
    o.footprintAcrossM = o.trackSpacingM / 0.8;
    o.footprintAlongM = o.photoSpacingM / 0.8;
    return o;
}

// On a long thin rectangle the fastest Survey that covers it flies along it: a few long transects, not
// many short ones, exactly along the long edges.
TEST(Lawnmower, AngleSearchFliesAlongALongThinRectangle) {
    for (double rot : {0.0, 30.0, 117.0}) {
        auto p = planLawnmower(rotated(rectangle(1000, 60), rot), withFootprint(options(27.7, 19.9)));
        ASSERT_TRUE(p.ok());
        EXPECT_GE(p->coverage, 0.995);
        const double d = std::fabs(std::remainder(p->angleDeg - rot, 180.0));
        EXPECT_LT(d, 1e-6) << "rotated by " << rot << ": chose " << p->angleDeg;
        EXPECT_EQ(p->transects.size(), 3u);
        EXPECT_GE(p->anglesTried, 180);
        // Flying across instead (37 transects of 60 m) is slower by the one model.
        LawnmowerOptions across = options(27.7, 19.9);
        across.angleDeg = rot + 90.0;
        auto q = planLawnmower(rotated(rectangle(1000, 60), rot), across);
        ASSERT_TRUE(q.ok());
        EXPECT_EQ(q->transects.size(), 37u);
        EXPECT_GT(q->time.totalS, p->time.totalS);
    }
}

// The entry corner follows home: the flight starts at the corner nearest to it.
TEST(Lawnmower, EntryCornerIsTheOneNearestHome) {
    const geo::Vec2 corners[] = {{-30, -30}, {230, -30}, {230, 130}, {-30, 130}};
    for (const auto& home : corners) {
        LawnmowerOptions o = options(27.7, 19.9);
        o.angleDeg = 0;
        o.home = home;
        auto p = planLawnmower(rectangle(200, 100), o);
        ASSERT_TRUE(p.ok());
        const geo::Vec2 start = p->transects.front().stripStart;
        EXPECT_LT((start - home).norm(), 60.0) << home.transpose() << " started at " << start.transpose();
    }
}

// A hand-made case: a zone over the second transect holds one photo and is crossed by that transect;
// a second zone lies 3.5 m from the third transect, inside its 5 m margin.
TEST(Lawnmower, NoFlyCrossingsOnAHandMadeCase) {
    LawnmowerOptions o = options(25, 20);
    o.angleDeg = 0;
    o.home = geo::Vec2(-50, -50);
    auto p = planLawnmower(rectangle(200, 100), o);
    ASSERT_TRUE(p.ok());
    ASSERT_EQ(p->photos, 44);
    const std::vector<geo::Polygon> zones{geo::Polygon{{{91, 30}, {109, 30}, {109, 45}, {91, 45}}, {}},
                                          geo::Polygon{{{150, 66}, {170, 66}, {170, 80}, {150, 80}}, {}}};
    const NoFlyCrossings c = countNoFlyCrossings(*p, zones, 5.0);
    EXPECT_EQ(c.photosInZones, 1);      // (100, 37.5)
    EXPECT_EQ(c.photosOutsideZones, 43);
    EXPECT_EQ(c.legsCrossing, 2);       // the transects at y = 37.5 and y = 62.5
    const NoFlyCrossings none = countNoFlyCrossings(*p, zones, 3.0); // 3.5 m clear of the second zone
    EXPECT_EQ(none.legsCrossing, 1);
    EXPECT_EQ(countNoFlyCrossings(*p, {}, 5.0).photosOutsideZones, 44);
}

// Without the coverage condition the search takes what is fastest by the time model alone: on the tilted
// rectangle a degree off its edges (shorter, clipped transects that leave its corners unseen).
TEST(Lawnmower, CoverageConditionKeepsTheSearchOffAnglesThatMissCorners) {
    const auto area = rotated(rectangle(1000, 60), 117.0);
    auto free = planLawnmower(area, options(27.7, 19.9));
    auto covered = planLawnmower(area, withFootprint(options(27.7, 19.9)));
    ASSERT_TRUE(free.ok());
    ASSERT_TRUE(covered.ok());
    EXPECT_DOUBLE_EQ(free->coverage, -1.0);
    EXPECT_LE(free->time.totalS, covered->time.totalS);
    EXPECT_NEAR(covered->angleDeg, 117.0, 1e-6);
}

TEST(Lawnmower, BadInputIsAnError) {
    EXPECT_FALSE(planLawnmower(rectangle(100, 100), options(0, 20)).ok());
    EXPECT_FALSE(planLawnmower(rectangle(100, 100), options(25, -1)).ok());
    EXPECT_FALSE(planLawnmower({}, options(25, 20)).ok());
    LawnmowerOptions o = options(25, 20);
    o.turnaroundM = -1;
    auto r = planLawnmower(rectangle(100, 100), o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("turnaround"), std::string::npos);
    // Spacings far too small for the area: refused at once instead of searching for minutes.
    r = planLawnmower(rectangle(10000, 10000), options(0.1, 0.1));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::TooLarge);
}

} // namespace
} // namespace pf::plan
