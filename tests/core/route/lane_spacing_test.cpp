// Photo spacing per lane (route::spaceLanes): lanes found as straight runs of photos, respaced only
// where their own trigger distance saves photos, ends kept, nothing else of the flight touched.
#include "core/route/lane_spacing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pf::route {
namespace {

using geo::Vec2;

// Photos every `step` metres from a to b (both included), heading from a to b.
void addLane(std::vector<LocalWaypoint>& w, const Vec2& a, const Vec2& b, double step,
             int cell0 = 0) {
    const Vec2 d = b - a;
    const double heading = std::fmod(std::atan2(d.x(), d.y()) * 180.0 / M_PI + 360.0, 360.0);
    const int n = static_cast<int>(std::round(d.norm() / step));
    for (int k = 0; k <= n; ++k)
        w.push_back(
            {a + d * (static_cast<double>(k) / n), heading, WaypointKind::Photo, cell0 + k});
}

std::vector<LocalWaypoint> photosOf(const std::vector<LocalWaypoint>& w) {
    std::vector<LocalWaypoint> p;
    for (const auto& x : w)
        if (x.kind == WaypointKind::Photo)
            p.push_back(x);
    return p;
}

// A back-and-forth of two lanes of 100 m (photos 10 m apart) joined by a turn waypoint.
std::vector<LocalWaypoint> twoLanes() {
    std::vector<LocalWaypoint> w;
    addLane(w, Vec2(0, 0), Vec2(0, 100), 10.0);
    w.push_back({Vec2(15, 105), 90.0, WaypointKind::Turn, -1});
    addLane(w, Vec2(30, 100), Vec2(30, 0), 10.0, 100);
    return w;
}

TEST(LaneSpacing, FindsStraightRunsOfPhotos) {
    const auto w = twoLanes();
    const auto lanes = photoLanes(w, 10.0 + 1e-6);
    ASSERT_EQ(lanes.size(), 2u);
    EXPECT_EQ(lanes[0], std::make_pair(0, 10));
    EXPECT_EQ(lanes[1], std::make_pair(12, 22));
    // Wider gaps than allowed split every photo off.
    EXPECT_EQ(photoLanes(w, 9.0).size(), 22u);
}

TEST(LaneSpacing, EachLaneGetsItsOwnTriggerDistanceWithItsEndsKept) {
    const auto w = twoLanes();
    // The west lane may space its photos 25 m apart, the east one 40 m.
    const LaneSpacingFn spacing = [](const Vec2& a, const Vec2&) {
        return a.x() < 15 ? 25.0 : 40.0;
    };
    LaneSpacingReport rep;
    const auto out = spaceLanes(w, 10.0, spacing, &rep);
    EXPECT_EQ(rep.lanes, 2);
    EXPECT_EQ(rep.respaced, 2);
    EXPECT_EQ(rep.photosBefore, 22);
    EXPECT_EQ(rep.photosAfter, 5 + 4); // ceil(100 / 25) + 1, ceil(100 / 40) + 1
    const auto photos = photosOf(out);
    ASSERT_EQ(photos.size(), 9u);
    // Ends where they were, evenly between, heading kept, the turn waypoint untouched.
    EXPECT_EQ(photos[0].pos, w[0].pos);
    EXPECT_EQ(photos[4].pos, w[10].pos);
    EXPECT_EQ(photos[5].pos, w[12].pos);
    EXPECT_EQ(photos[8].pos, w[22].pos);
    for (int k = 0; k < 4; ++k)
        EXPECT_NEAR((photos[k + 1].pos - photos[k].pos).norm(), 25.0, 1e-9);
    for (int k = 5; k < 8; ++k) {
        EXPECT_NEAR((photos[k + 1].pos - photos[k].pos).norm(), 100.0 / 3.0, 1e-9);
        EXPECT_LE((photos[k + 1].pos - photos[k].pos).norm(), 40.0);
        EXPECT_EQ(photos[k].headingDeg, w[12].headingDeg);
    }
    ASSERT_EQ(out.size(), 10u);
    EXPECT_EQ(out[5].kind, WaypointKind::Turn);
    EXPECT_EQ(out[5].pos, w[11].pos);
    // The cell of the nearest old photo: the middle photo of the west lane sits on old photo 5.
    EXPECT_EQ(photos[2].cell, 5);
}

TEST(LaneSpacing, TheAreaSpacingOrLessKeepsTheFlightExactly) {
    const auto w = twoLanes();
    for (double d : {10.0, 9.0, 0.0, -1.0}) {
        LaneSpacingReport rep;
        const auto out = spaceLanes(
            w, 10.0, [d](const Vec2&, const Vec2&) { return d; }, &rep);
        ASSERT_EQ(out.size(), w.size()) << d;
        for (std::size_t i = 0; i < w.size(); ++i) {
            EXPECT_EQ(out[i].pos, w[i].pos);
            EXPECT_EQ(out[i].kind, w[i].kind);
        }
        EXPECT_EQ(rep.respaced, 0);
    }
    // A trigger distance a little longer than the area's that saves no photo keeps the lane too.
    const auto out = spaceLanes(w, 10.0, [](const Vec2&, const Vec2&) { return 10.5; });
    EXPECT_EQ(out.size(), w.size());
    EXPECT_TRUE(spaceLanes(w, 10.0, {}).size() == w.size());
}

TEST(LaneSpacing, APlannerRunDenserThanTheAreaSpacingIsNotThinnedOnItsOwn) {
    // Photos 5 m apart where the area spacing is 10 m: the lane's own 10 m is what the area needs
    // too.
    std::vector<LocalWaypoint> w;
    addLane(w, Vec2(0, 0), Vec2(0, 100), 5.0);
    EXPECT_EQ(spaceLanes(w, 10.0, [](const Vec2&, const Vec2&) { return 10.0; }).size(), w.size());
    // A longer trigger distance of its own respaces it.
    EXPECT_EQ(photosOf(spaceLanes(w, 10.0, [](const Vec2&, const Vec2&) { return 20.0; })).size(),
              6u);
}

TEST(LaneSpacing, GapsHeadingsAndOffsetsEndLanes) {
    // One line with a 40 m hole (a zone the flight crosses without photos): no photo goes into it.
    std::vector<LocalWaypoint> w;
    addLane(w, Vec2(0, 0), Vec2(0, 50), 10.0);
    addLane(w, Vec2(0, 90), Vec2(0, 140), 10.0);
    const auto out = photosOf(spaceLanes(w, 10.0, [](const Vec2&, const Vec2&) { return 50.0; }));
    ASSERT_EQ(out.size(), 4u);
    for (const auto& p : out)
        EXPECT_TRUE(p.pos.y() <= 50.0 + 1e-9 || p.pos.y() >= 90.0 - 1e-9) << p.pos.y();
    // A photo 5 cm off the line, or turned, starts a new lane.
    std::vector<LocalWaypoint> bent;
    addLane(bent, Vec2(0, 0), Vec2(0, 50), 10.0);
    bent[3].pos.x() += 0.05;
    EXPECT_EQ(photoLanes(bent, 10.1).size(), 3u);
    std::vector<LocalWaypoint> turned;
    addLane(turned, Vec2(0, 0), Vec2(0, 50), 10.0);
    turned[4].headingDeg = 5.0;
    EXPECT_EQ(photoLanes(turned, 10.1).size(), 3u);
    // Photos that go backwards along the heading are no lane either.
    std::vector<LocalWaypoint> back;
    addLane(back, Vec2(0, 0), Vec2(0, 50), 10.0);
    back[2].pos.y() = 0.0;
    EXPECT_GE(photoLanes(back, 10.1).size(), 2u);
}

TEST(LaneSpacing, CoincidentPhotosAtALaneEndAreOneLane) {
    // makeLane moves photos beyond a margin back to its edge: two photos at one point end the lane.
    std::vector<LocalWaypoint> w;
    addLane(w, Vec2(0, 0), Vec2(0, 60), 10.0);
    w.push_back(w.back());
    const auto lanes = photoLanes(w, 10.0 + 1e-6);
    ASSERT_EQ(lanes.size(), 1u);
    const auto out = photosOf(spaceLanes(w, 10.0, [](const Vec2&, const Vec2&) { return 30.0; }));
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out.back().pos, w.back().pos);
}

} // namespace
} // namespace pf::route
