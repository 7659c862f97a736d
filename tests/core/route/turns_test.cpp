#include "core/route/turns.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pf;
using namespace pf::route;
using geo::Vec2;

namespace {

constexpr double kR =
    20.0; // the radius of the hand-computed cases (worked out for R = 1, then scaled)

Pose pose(double x, double y, double headingDeg) {
    return Pose{Vec2(x, y), headingDeg * M_PI / 180.0};
}

double wrapPi(double a) {
    return std::remainder(a, 2 * M_PI);
}

// The path ends where it was asked to, heading as asked.
void expectEndsAt(const DubinsPath& p, const Pose& to) {
    const Pose e = p.end();
    EXPECT_NEAR((e.pos - to.pos).norm(), 0.0, 1e-9 * (1 + p.lengthM())) << dubinsWordName(p.word);
    EXPECT_NEAR(wrapPi(e.headingRad - to.headingRad), 0.0, 1e-9) << dubinsWordName(p.word);
}

struct HandCase {
    DubinsWord word;
    Pose from, to;
    double lengthOverR; // worked out in the comments of HandComputedWords
};

} // namespace

// Each word on a configuration where it is the shortest, lengths worked out by hand for R = 1
// (centres: left of a pose (x, y, h) at (x - sin h, y + cos h), right at (x + sin h, y - cos h)):
// - LSL (0,0,0) -> (0,4,180): centres (0,1) and (0,3); the straight runs along them at 90 degrees:
//   turn left 90 (to (1,1)), straight 2 (to (1,3)), turn left 90 to (0,4) heading west: pi + 2.
// - RSR (0,0,0) -> (0,-4,180): the mirror image of LSL: pi + 2.
// - LSR (0,0,0) -> (4,2,0): left centre (0,1), the end's right centre (4,1), 4 apart; the inner
// tangent
//   is sqrt(4^2 - 2^2) = 2 sqrt 3 long and heads atan2(2, 2 sqrt 3) = 30 degrees: left 30 (to (0.5,
//   0.134)), straight 2 sqrt 3 (to (3.5, 1.866), on the right circle), right 30: pi/3 + 2 sqrt 3.
// - RSL (0,0,0) -> (4,-2,0): its mirror image: pi/3 + 2 sqrt 3.
// - LRL (0,0,90) -> (1,0,270), a U-turn narrower than the turning circle: left centres (-1,0) and
//   (2,0), 3 apart; the right circle touching both has its centre 2 from each, at (0.5, sqrt 1.75)
//   (the one above, the other needs near-full circles). With a = acos(1.5 / 2) the angle between
//   the centre line and each touching radius: left a, right 180 + 2a, left a: pi + 4 acos(3/4).
// - RLR (0,0,90) -> (-1,0,270): its mirror image: pi + 4 acos(3/4).
TEST(Dubins, HandComputedWords) {
    const double csc = M_PI + 2, cross = M_PI / 3 + 2 * std::sqrt(3.0),
                 ccc = M_PI + 4 * std::acos(0.75);
    const HandCase cases[] = {
        {DubinsWord::LSL, pose(0, 0, 0), pose(0, 4 * kR, 180), csc},
        {DubinsWord::RSR, pose(0, 0, 0), pose(0, -4 * kR, 180), csc},
        {DubinsWord::LSR, pose(0, 0, 0), pose(4 * kR, 2 * kR, 0), cross},
        {DubinsWord::RSL, pose(0, 0, 0), pose(4 * kR, -2 * kR, 0), cross},
        {DubinsWord::LRL, pose(0, 0, 90), pose(kR, 0, 270), ccc},
        {DubinsWord::RLR, pose(0, 0, 90), pose(-kR, 0, 270), ccc},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(dubinsWordName(c.word));
        const auto p = dubinsPath(c.from, c.to, kR, c.word);
        ASSERT_TRUE(p.has_value());
        EXPECT_NEAR(p->lengthM(), c.lengthOverR * kR, 1e-9);
        expectEndsAt(*p, c.to);
        const DubinsPath best = shortestDubinsPath(c.from, c.to, kR);
        EXPECT_EQ(best.word, c.word);
        EXPECT_NEAR(best.lengthM(), c.lengthOverR * kR, 1e-9);
        EXPECT_NEAR(dubinsDistanceM(c.from, c.to, kR), c.lengthOverR * kR, 1e-9);
    }
}

// The longer words of the LSL case, by hand: RSR from (0,0,0) to (0,4,180) uses the right centres
// (0,-1) and (0,5), 6 apart at 90 degrees: right 270 (the long way round), straight 6, right 270:
// 3 pi + 6. The segments of the LSR case: 30 degrees, 2 sqrt 3, 30 degrees.
TEST(Dubins, HandComputedLongWordAndSegments) {
    const auto rsr = dubinsPath(pose(0, 0, 0), pose(0, 4 * kR, 180), kR, DubinsWord::RSR);
    ASSERT_TRUE(rsr.has_value());
    EXPECT_NEAR(rsr->lengthM(), (3 * M_PI + 6) * kR, 1e-9);
    expectEndsAt(*rsr, pose(0, 4 * kR, 180));
    const auto lsr = dubinsPath(pose(0, 0, 0), pose(4 * kR, 2 * kR, 0), kR, DubinsWord::LSR);
    ASSERT_TRUE(lsr.has_value());
    EXPECT_NEAR(lsr->segment[0], M_PI / 6, 1e-12);
    EXPECT_NEAR(lsr->segment[1], 2 * std::sqrt(3.0) * kR, 1e-9);
    EXPECT_NEAR(lsr->segment[2], M_PI / 6, 1e-12);
    EXPECT_EQ(lsr->kind(0), SegmentKind::Left);
    EXPECT_EQ(lsr->kind(1), SegmentKind::Straight);
    EXPECT_EQ(lsr->kind(2), SegmentKind::Right);
    // Halfway along the straight: (0.5, 0.134) + sqrt 3 (cos 30, sin 30) = (2, 1), heading 30.
    const Pose mid = lsr->poseAt(lsr->segmentLengthM(0) + lsr->segmentLengthM(1) / 2);
    EXPECT_NEAR(mid.pos.x(), 2 * kR, 1e-9);
    EXPECT_NEAR(mid.pos.y(), 1 * kR, 1e-9);
    EXPECT_NEAR(mid.headingRad, M_PI / 6, 1e-12);
}

// Words that cannot join two poses say so: LSR needs its two circles apart (here 0.5 R), RLR needs
// them at most 4 R apart (here 10 R).
TEST(Dubins, ImpossibleWordsAreRefused) {
    EXPECT_FALSE(
        dubinsPath(pose(0, 0, 0), pose(0.5 * kR, 0, 180), kR, DubinsWord::LSR).has_value());
    EXPECT_FALSE(dubinsPath(pose(0, 0, 0), pose(10 * kR, 0, 0), kR, DubinsWord::RLR).has_value());
    EXPECT_FALSE(dubinsPath(pose(0, 0, 0), pose(10 * kR, 0, 0), kR, DubinsWord::LRL).has_value());
    // Straight ahead: every CSC word exists, and the shortest is the straight line.
    EXPECT_NEAR(dubinsDistanceM(pose(0, 0, 0), pose(10 * kR, 0, 0), kR), 10 * kR, 1e-9);
}

// Flying a path backwards is the same path: a->b equals b'->a' with both headings reversed; the
// mirror image (y -> -y) has the mirrored word and the same length. Never shorter than the straight
// line.
TEST(Dubins, SymmetriesAndLowerBound) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> xy(-150, 150), h(-M_PI, M_PI);
    const auto mirrorWord = [](DubinsWord w) {
        switch (w) {
        case DubinsWord::LSL:
            return DubinsWord::RSR;
        case DubinsWord::RSR:
            return DubinsWord::LSL;
        case DubinsWord::LSR:
            return DubinsWord::RSL;
        case DubinsWord::RSL:
            return DubinsWord::LSR;
        case DubinsWord::RLR:
            return DubinsWord::LRL;
        case DubinsWord::LRL:
            return DubinsWord::RLR;
        }
        return w;
    };
    for (int i = 0; i < 500; ++i) {
        const Pose a{Vec2(xy(rng), xy(rng)), h(rng)}, b{Vec2(xy(rng), xy(rng)), h(rng)};
        const double d = dubinsDistanceM(a, b, kR);
        EXPECT_NEAR(
            dubinsDistanceM(Pose{b.pos, b.headingRad + M_PI}, Pose{a.pos, a.headingRad + M_PI}, kR),
            d, 1e-7);
        const Pose am{Vec2(a.pos.x(), -a.pos.y()), -a.headingRad},
            bm{Vec2(b.pos.x(), -b.pos.y()), -b.headingRad};
        const DubinsPath p = shortestDubinsPath(a, b, kR), pm = shortestDubinsPath(am, bm, kR);
        EXPECT_NEAR(pm.lengthM(), p.lengthM(), 1e-7);
        const auto same = dubinsPath(am, bm, kR, mirrorWord(p.word));
        ASSERT_TRUE(same.has_value());
        EXPECT_NEAR(same->lengthM(), p.lengthM(), 1e-7);
        EXPECT_GE(d, (b.pos - a.pos).norm() - 1e-9);
        EXPECT_NEAR(p.lengthM(), d, 1e-9);
        expectEndsAt(p, b);
    }
}

// As the radius shrinks the path tends to the straight line (each arc is at most a full circle: the
// excess is below 4 pi R), and with R = 0 it is the straight line whatever the headings: a heading
// change costs nothing.
TEST(Dubins, ZeroRadiusIsTheStraightLine) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> xy(-100, 100), h(-M_PI, M_PI);
    for (int i = 0; i < 200; ++i) {
        const Pose a{Vec2(xy(rng), xy(rng)), h(rng)}, b{Vec2(xy(rng), xy(rng)), h(rng)};
        const double straight = (b.pos - a.pos).norm();
        EXPECT_NEAR(dubinsDistanceM(a, b, 0.0), straight, 1e-9);
        for (const double r : {1.0, 0.1, 0.001})
            EXPECT_LE(dubinsDistanceM(a, b, r) - straight, 4 * M_PI * r + 1e-9);
        const DubinsPath p = shortestDubinsPath(a, b, 0.0);
        EXPECT_NEAR((p.end().pos - b.pos).norm(), 0.0, 1e-9);
    }
}

// Sampling: from the start pose to the end pose, consecutive samples at most a step apart, the
// heading changing by at most step / R between them, and the polyline's curvature within 1 / R.
TEST(Dubins, SampledPathIsContinuousAndWithinTheRadius) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> xy(-200, 200), h(-M_PI, M_PI);
    const double r = 30.0, step = 1.0;
    for (int i = 0; i < 100; ++i) {
        const Pose a{Vec2(xy(rng), xy(rng)), h(rng)}, b{Vec2(xy(rng), xy(rng)), h(rng)};
        const DubinsPath p = shortestDubinsPath(a, b, r);
        const auto s = samplePath(p, step);
        ASSERT_GE(s.size(), 2u);
        EXPECT_NEAR((s.front().pos - a.pos).norm(), 0.0, 1e-9);
        EXPECT_NEAR((s.back().pos - b.pos).norm(), 0.0, 1e-9);
        double chords = 0.0;
        for (std::size_t k = 1; k < s.size(); ++k) {
            const double gap = (s[k].pos - s[k - 1].pos).norm();
            EXPECT_LE(gap, step + 1e-9);
            EXPECT_LE(std::abs(wrapPi(s[k].headingRad - s[k - 1].headingRad)), step / r + 1e-9);
            chords += gap;
        }
        // Chords fall short of the arcs by at most (step / R)^2 / 24 of their length.
        EXPECT_NEAR(chords, p.lengthM(), p.lengthM() * (step / r) * (step / r) / 24 + 1e-9);
        std::vector<Vec2> pts;
        appendSampledPoints(p, step, pts);
        EXPECT_LE(maxCurvature(pts), (1.0 + 1e-6) / r);
    }
}

// The curvature helper, by hand: points on a circle of radius 5 give 1/5; a straight line 0; a
// right-angle corner between legs of 1 gives 2 sin(90) / sqrt 2 = sqrt 2; doubling back is
// infinite.
TEST(Dubins, MaxCurvatureByHand) {
    std::vector<Vec2> circle;
    for (int k = 0; k < 12; ++k)
        circle.emplace_back(5 * std::cos(k * 0.3), 5 * std::sin(k * 0.3));
    EXPECT_NEAR(maxCurvature(circle), 0.2, 1e-12);
    EXPECT_EQ(maxCurvature({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(3, 0)}), 0.0);
    EXPECT_NEAR(maxCurvature({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1)}), std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(std::isinf(maxCurvature({Vec2(0, 0), Vec2(1, 0), Vec2(0, 0)})));
    EXPECT_EQ(maxCurvature({Vec2(0, 0), Vec2(1, 0)}), 0.0);
}

// Two lanes 2R apart flown as a boustrophedon, by hand. Without run-in the connection is a
// semicircle: 2 x 100 + pi R. With a run-in of 10 m the next lane starts 10 m beyond its end, from
// (100, 0, east) to (110, 2R, west): LSL on the left centres (100, R) and (110, R): straight 10
// east, then the half circle: the lanes 2 x 110, the connection 10 + pi R.
TEST(PlaneLanes, BoustrophedonByHand) {
    plan::FlightTimeModel m;
    m.dynamics = plan::FlightDynamics::FixedWing;
    m.speedMps = 16.0;
    const std::vector<DirectedLane> lanes{{Vec2(0, 0), Vec2(100, 0)},
                                          {Vec2(100, 2 * kR), Vec2(0, 2 * kR)}};
    const auto e0 = planeLanesEstimate(lanes, kR, 0.0, m);
    EXPECT_NEAR(e0.lanesM, 200.0, 1e-9);
    EXPECT_NEAR(e0.connectionsM, M_PI * kR, 1e-9);
    EXPECT_NEAR(e0.timeS, (200.0 + M_PI * kR) / 16.0, 1e-9);
    const auto e1 = planeLanesEstimate(lanes, kR, 10.0, m);
    EXPECT_NEAR(e1.lanesM, 220.0, 1e-9);
    EXPECT_NEAR(e1.connectionsM, 10.0 + M_PI * kR, 1e-9);
    // The sampled flight: the one model gives the same time up to the chord error, within 1 / R.
    const auto path = planeLanesPath(lanes, kR, 10.0, kR / 10);
    const plan::FlightTime t = plan::flightTime(path, m);
    EXPECT_NEAR(t.totalS, e1.timeS, e1.timeS * 1e-3);
    EXPECT_LE(t.totalS, e1.timeS + 1e-9);
    EXPECT_LE(maxCurvature(path), (1.0 + 1e-6) / kR);
    EXPECT_NEAR((path.front() - Vec2(-10, 0)).norm(), 0.0, 1e-12); // the first run-in
    EXPECT_NEAR((path.back() - Vec2(0, 2 * kR)).norm(), 0.0, 1e-12);
}

// Compass headings (clockwise from north) and local headings (counter-clockwise from east) agree.
TEST(Dubins, CompassConversion) {
    EXPECT_NEAR(headingFromCompassDeg(0), M_PI / 2, 1e-12);
    EXPECT_NEAR(headingFromCompassDeg(90), 0.0, 1e-12);
    EXPECT_NEAR(compassFromHeadingRad(M_PI), 270.0, 1e-9);
    EXPECT_NEAR(compassFromHeadingRad(headingFromCompassDeg(123.5)), 123.5, 1e-9);
}
