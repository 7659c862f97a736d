#include "core/plan/lanes/lane.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pf;
using namespace pf::plan;
using geo::Vec2;

// A 100 m strip with a 19.9 m trigger distance: ceil(100 / 19.9) = 6 photos 19.9 m apart, centred,
// so the first and last effective footprints (19.9 m long) reach past both ends of the strip.
TEST(Lane, PhotosAtTheTriggerDistanceCentredOnTheStrip) {
    const auto p = stripPhotos(Vec2(0, 0), Vec2(100, 0), 19.9);
    ASSERT_EQ(p.size(), 6u);
    for (std::size_t i = 1; i < p.size(); ++i)
        EXPECT_NEAR((p[i] - p[i - 1]).norm(), 19.9, 1e-9);
    EXPECT_NEAR(p.front().x() + p.back().x(), 100.0, 1e-9);
    EXPECT_LE(p.front().x() - 19.9 / 2, 0.0);
    EXPECT_GE(p.back().x() + 19.9 / 2, 100.0);
    EXPECT_GT(p.front().x(), 0.0); // inside the strip: the lane turns at its last photo, not past the end
    for (const auto& q : p)
        EXPECT_NEAR(q.y(), 0.0, 1e-12);
}

// Exactly k spacings: k photos, not k + 1; a strip shorter than one spacing: one photo in its middle.
TEST(Lane, ExactMultiplesAndShortStrips) {
    EXPECT_EQ(stripPhotos(Vec2(0, 0), Vec2(0, 60), 20).size(), 3u);
    const auto one = stripPhotos(Vec2(10, 10), Vec2(14, 13), 20);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_NEAR((one[0] - Vec2(12, 11.5)).norm(), 0.0, 1e-12);
    EXPECT_EQ(stripPhotos(Vec2(5, 5), Vec2(5, 5), 20).size(), 1u);
}

// A margin covers the strip's last 8 m: the photo that would fall in it moves back to the margin's
// edge; the others keep their places and spacing.
TEST(Lane, PhotosInAMarginMoveToItsEdge) {
    const Lane free = makeLane(Vec2(0, 0), Vec2(100, 0), 19.9);
    const Lane cut = makeLane(Vec2(0, 0), Vec2(100, 0), 19.9, Vec2(0, 0), Vec2(92, 0));
    ASSERT_EQ(free.photos.size(), cut.photos.size());
    for (std::size_t i = 0; i + 1 < cut.photos.size(); ++i)
        EXPECT_EQ(cut.photos[i], free.photos[i]);
    ASSERT_GT(free.photos.back().x(), 92.0);
    EXPECT_NEAR(cut.photos.back().x(), 92.0, 1e-12);
    // Two photos pushed onto the same edge become one.
    const Lane tight = makeLane(Vec2(0, 0), Vec2(100, 0), 19.9, Vec2(35, 0), Vec2(100, 0));
    EXPECT_EQ(tight.photos.size(), free.photos.size() - 1);
    EXPECT_NEAR(tight.photos.front().x(), 35.0, 1e-12);
}

TEST(Lane, MakeLaneKeepsTheStripAndHeadsAlongIt) {
    const Lane l = makeLane(Vec2(0, 100), Vec2(0, 0), 30);
    EXPECT_NEAR(l.headingDeg, 180.0, 1e-9); // south
    ASSERT_EQ(l.photos.size(), 4u);
    EXPECT_GT(l.photos.front().y(), l.photos.back().y()); // in flight order
    EXPECT_NEAR(makeLane(Vec2(0, 0), Vec2(1, 0), 30).headingDeg, 90.0, 1e-9);
}

// laneSpan is makeLane without the photos in between: the same first and last photo, the same count.
TEST(Lane, SpanMatchesMakeLane) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-100, 100), t(0, 1), sp(3, 40);
    for (int k = 0; k < 2000; ++k) {
        const Vec2 a(u(rng), u(rng));
        const Vec2 b = k % 50 == 0 ? a : Vec2(u(rng), u(rng));
        double ta = t(rng) * 0.5, tb = 1 - t(rng) * 0.5;
        if (k % 7 == 0)
            ta = 0, tb = 1;
        const Vec2 fa = a + ta * (b - a), fb = a + tb * (b - a);
        const double s = k % 97 == 0 ? 0.0 : sp(rng);
        const Lane l = makeLane(a, b, s, fa, fb);
        const LaneSpan span = laneSpan(a, b, s, fa, fb);
        ASSERT_EQ(span.photos, static_cast<int>(l.photos.size())) << k;
        EXPECT_NEAR((span.first - l.photos.front()).norm(), 0.0, 1e-9) << k;
        EXPECT_NEAR((span.last - l.photos.back()).norm(), 0.0, 1e-9) << k;
    }
}
