// Photos left out inside lanes where other photos see their ground: by hand (a lane beside another
// two metres off, ground only a real footprint reaches) and on generated areas through the sweep,
// where the flight must not change and the overlap the operator set must survive.
#include "core/plan/lanes/photo_thinning.h"

#include "core/plan/lanes/lane.h"
#include "tests/core/plan/sweep_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pf;
using namespace pf::plan;
using namespace pf::plan::sweeptest;
using geo::Vec2;

namespace {

PhotoThinningOptions thinning() {
    PhotoThinningOptions o;
    o.trackSpacingM = 20.0;
    o.photoSpacingM = 10.0;
    o.realAcrossM = 25.0;
    o.realAlongM = 12.0;
    return o;
}

// Whether a kept photo's footprint of (along, across) holds p; every lane here flies east.
bool seen(const std::vector<Lane>& lanes, const Vec2& p, double along, double across) {
    for (const auto& l : lanes)
        for (const auto& c : l.photos)
            if (std::fabs(p.x() - c.x()) <= 0.5 * along + 1e-9 &&
                std::fabs(p.y() - c.y()) <= 0.5 * across + 1e-9)
                return true;
    return false;
}

} // namespace

// Three lanes 20 m apart (the track spacing) over a field: every photo's band is its own; none
// goes.
TEST(PhotoThinning, KeepsLanesATrackSpacingApart) {
    std::vector<Lane> lanes{makeLane(Vec2(0, 10), Vec2(100, 10), 10),
                            makeLane(Vec2(0, 30), Vec2(100, 30), 10),
                            makeLane(Vec2(0, 50), Vec2(100, 50), 10)};
    const auto before = lanes;
    EXPECT_EQ(thinLanePhotos(lanes, {}, thinning(),
                             [](const Vec2& p) { return p.y() >= 0 && p.y() <= 60; }),
              0);
    for (std::size_t i = 0; i < lanes.size(); ++i)
        EXPECT_EQ(lanes[i].photos, before[i].photos);
}

// A lane 2 m beside another over a 24 m wide field: one of them photographs everything the other
// does, so the other keeps only its two ends (it is still flown end to end) and the field stays
// seen by the effective footprints, at the overlap set.
TEST(PhotoThinning, LeavesOutTheInteriorOfALaneBesideAnother) {
    std::vector<Lane> lanes{makeLane(Vec2(0, 12), Vec2(100, 12), 10),
                            makeLane(Vec2(0, 14), Vec2(100, 14), 10)};
    ASSERT_EQ(lanes[0].photos.size(), 10u);
    const auto before = lanes;
    auto ground = [](const Vec2& p) {
        return p.x() >= 0 && p.x() <= 100 && p.y() >= 2 && p.y() <= 22;
    };
    EXPECT_EQ(thinLanePhotos(lanes, {}, thinning(), ground), 8);
    const std::size_t thinned = lanes[0].photos.size() == 2 ? 0 : 1;
    ASSERT_EQ(lanes[thinned].photos.size(), 2u);
    EXPECT_EQ(lanes[thinned].photos.front(), before[thinned].photos.front());
    EXPECT_EQ(lanes[thinned].photos.back(), before[thinned].photos.back());
    EXPECT_EQ(lanes[1 - thinned].photos, before[1 - thinned].photos);
    for (double x = 0.05; x < 100; x += 0.5)
        for (double y = 2.05; y < 22; y += 0.5)
            ASSERT_TRUE(seen(lanes, Vec2(x, y), 10, 20)) << x << ", " << y;
}

// The same two lanes, with ground beyond the effective footprints that only the lower lane's real
// footprint reaches (a strip along a zone's margin, say): the upper lane, wholly redundant, gives
// up its interior; the lower one keeps every photo, and the strip stays seen.
TEST(PhotoThinning, KeepsPhotosThatAloneSeeGroundWithTheirRealFootprint) {
    std::vector<Lane> lanes{makeLane(Vec2(0, 12), Vec2(100, 12), 10),
                            makeLane(Vec2(0, 14), Vec2(100, 14), 10)};
    const auto before = lanes;
    // y -0.4 to 1: within the lower lane's real footprint (down to -0.5), beyond the upper's (1.5).
    auto ground = [](const Vec2& p) {
        return p.x() >= 0 && p.x() <= 100 &&
               ((p.y() >= 4 && p.y() <= 22) ||
                (p.y() >= -0.4 && p.y() <= 1.0 && p.x() >= 40 && p.x() <= 45));
    };
    EXPECT_EQ(thinLanePhotos(lanes, {}, thinning(), ground), 8);
    EXPECT_EQ(lanes[0].photos, before[0].photos);
    EXPECT_EQ(lanes[1].photos.size(), 2u);
    for (double x = 40.05; x < 45; x += 0.25)
        for (double y : {-0.3, 0.5})
            EXPECT_TRUE(seen(lanes, Vec2(x, y), 12, 25)) << x << ", " << y;
}

// Fixed lanes keep their photos; a lane of one or two photos has no interior.
TEST(PhotoThinning, FixedAndShortLanesStay) {
    std::vector<Lane> lanes{makeLane(Vec2(0, 12), Vec2(100, 12), 10),
                            makeLane(Vec2(0, 14), Vec2(100, 14), 10),
                            makeLane(Vec2(0, 13), Vec2(15, 13), 10)};
    ASSERT_EQ(lanes[2].photos.size(), 2u);
    const auto before = lanes;
    auto ground = [](const Vec2& p) {
        return p.x() >= 0 && p.x() <= 100 && p.y() >= 2 && p.y() <= 22;
    };
    EXPECT_EQ(thinLanePhotos(lanes, {1, 1, 0}, thinning(), ground), 0);
    for (std::size_t i = 0; i < lanes.size(); ++i)
        EXPECT_EQ(lanes[i].photos, before[i].photos);
}

// Through the sweep on generated areas with zones: the flight (time, lane ends) is the same, photos
// are never more and fewer in all, the coverage by the effective and by the real footprints no
// lower.
TEST(PhotoThinning, SweepFliesTheSameWithFewerPhotosOnGeneratedAreas) {
    const Camera cam;
    Camera effective;
    effective.realAcross = cam.track();
    effective.realAlong = cam.photo();
    int before = 0, after = 0;
    for (unsigned seed = 1; seed <= 8; ++seed) {
        const Area a = generateArea(seed + 500, 8 + static_cast<int>(seed % 3) * 5);
        SweepOptions o = options(cam);
        o.thinPhotos = false;
        auto plain = planSweep(a.region, a.zones, o);
        o.thinPhotos = true;
        auto thinned = planSweep(a.region, a.zones, o);
        ASSERT_TRUE(plain.ok() && thinned.ok()) << a.name;
        before += photoCount(*plain);
        after += photoCount(*thinned);
        EXPECT_LE(photoCount(*thinned), photoCount(*plain)) << a.name;
        EXPECT_EQ(thinned->stats.photosLeftOut, photoCount(*plain) - photoCount(*thinned))
            << a.name;
        EXPECT_DOUBLE_EQ(thinned->time.totalS, plain->time.totalS) << a.name;
        ASSERT_EQ(thinned->lanes.size(), plain->lanes.size()) << a.name;
        for (std::size_t i = 0; i < plain->lanes.size(); ++i) {
            EXPECT_EQ(thinned->lanes[i].photos.front(), plain->lanes[i].photos.front()) << a.name;
            EXPECT_EQ(thinned->lanes[i].photos.back(), plain->lanes[i].photos.back()) << a.name;
        }
        EXPECT_GE(coverage(a, *thinned, effective), coverage(a, *plain, effective) - 1e-4)
            << a.name;
        EXPECT_GE(coverage(a, *thinned, cam), coverage(a, *plain, cam) - 1e-4) << a.name;
    }
    EXPECT_LT(after, before);
}
