// Single photos for ground the lanes leave unseen: chosen by hand-checkable cases (a patch seen
// from where the aircraft may be, a patch too small to pay for a detour, places the aircraft may
// not be), placed in a flight where they add least time, and through the sweep on generated areas,
// where they must raise the coverage and keep every photo and leg out of the margins.
#include "core/plan/lanes/spot_photos.h"

#include "core/geo/no_fly_field.h"
#include "tests/core/plan/sweep_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pf;
using namespace pf::plan;
using namespace pf::plan::sweeptest;
using geo::Vec2;

namespace {

SpotPhotoOptions spotOptions() {
    SpotPhotoOptions o;
    o.realAcrossM = 30.0; // heading 0 (north): 30 m east-west, 20 m north-south
    o.realAlongM = 20.0;
    o.headingDeg = 0.0;
    return o;
}

bool inFootprint(const SpotPhoto& s, const Vec2& q, const SpotPhotoOptions& o) {
    const double h = s.headingDeg * M_PI / 180.0;
    const Vec2 along(std::sin(h), std::cos(h)), right(std::cos(h), -std::sin(h));
    const Vec2 d = q - s.pos;
    return std::abs(d.dot(along)) <= 0.5 * o.realAlongM + 1e-9 &&
           std::abs(d.dot(right)) <= 0.5 * o.realAcrossM + 1e-9;
}

} // namespace

// The places' scores count the probes in runs (whole runs inside or outside a footprint at once):
// the counts must be those of the footprint test on every probe, also for footprints whose edge runs
// exactly through probes, at headings along and across the lanes, and far from the origin.
TEST(SpotPhotos, ScoredProbesCountAsTheTestOnEveryProbe) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0, 1);
    for (const Vec2& origin : {Vec2(0, 0), Vec2(2.5e6, -1.5e6)}) {
        for (double heading : {0.0, 37.5, 90.0}) {
            // A patch's probes: pixel centres row by row, some pixels missing, every 1st or 3rd kept.
            std::vector<Vec2> pts;
            const double res = 0.5;
            for (int j = 0; j < 40; ++j)
                for (int i = 0; i < 60; ++i)
                    if (unit(rng) < 0.8)
                        pts.push_back(origin + Vec2((i + 0.5) * res, (j + 0.5) * res));
            const double halfAlong = 0.5 * 25.9, halfAcross = 0.5 * 34.6;
            const spot_detail::ScoredProbes sp(pts, heading, std::fmod(heading + 90.0, 360.0), halfAlong, halfAcross);
            const double h = heading * M_PI / 180.0;
            const Vec2 along(std::sin(h), std::cos(h)), right(std::cos(h), -std::sin(h));
            for (int k = 0; k < 400; ++k) {
                Vec2 c = origin + Vec2(-30 + 90 * unit(rng), -30 + 80 * unit(rng));
                if (k % 4 == 0) // a footprint edge through a probe
                    c = pts[static_cast<std::size_t>(k) % pts.size()] - (k % 8 ? halfAlong * along : halfAcross * right);
                for (int hi = 0; hi < 2; ++hi) {
                    std::size_t n = 0;
                    for (const auto& q : pts)
                        n += sp.sees(c, hi, q) ? 1 : 0;
                    ASSERT_EQ(sp.count(c, hi), n) << heading << " at " << (c - origin).transpose();
                }
            }
        }
    }
}

TEST(SpotPhotos, OnePhotoSeesASmallUnseenSquare) {
    const geo::MultiPolygon ground{rect(0, 0, 10, 10)};
    const auto o = spotOptions();
    auto c = chooseSpotPhotos(
        ground, {}, [](const Vec2&) { return true; }, o);
    ASSERT_TRUE(c.ok()) << c.error().message;
    EXPECT_NEAR(c->unseenBeforeM2, 100.0, 1.0);
    ASSERT_EQ(c->photos.size(), 1u);
    for (double x = 0.25; x < 10; x += 0.5)
        for (double y = 0.25; y < 10; y += 0.5)
            EXPECT_TRUE(inFootprint(c->photos[0], Vec2(x, y), o)) << x << ", " << y;
    EXPECT_LT(c->unseenAfterM2, 1.0);
}

TEST(SpotPhotos, TakenOnlyWhereTheAircraftMayBeAndSeeWhatTheyCan) {
    // The aircraft may not come west of x = 20: a footprint 30 m wide from there sees x >= 5.
    const geo::MultiPolygon ground{rect(0, 0, 10, 10)};
    const auto o = spotOptions();
    auto c = chooseSpotPhotos(
        ground, {}, [](const Vec2& p) { return p.x() >= 20.0; }, o);
    ASSERT_TRUE(c.ok());
    ASSERT_EQ(c->photos.size(), 1u);
    EXPECT_GE(c->photos[0].pos.x(), 20.0);
    EXPECT_NEAR(c->photos[0].seenM2, 50.0, 5.0);
    EXPECT_NEAR(c->unseenAfterM2, 50.0, 5.0);
    // Not even that from x >= 30: nothing to take.
    auto none = chooseSpotPhotos(
        ground, {}, [](const Vec2& p) { return p.x() >= 30.0; }, o);
    ASSERT_TRUE(none.ok());
    EXPECT_TRUE(none->photos.empty());
}

TEST(SpotPhotos, ASmallPatchWaitsForTheCoverageGoal) {
    // A 200 m square the photos cover, and 9 m2 beside it they leave: 99.98 % seen.
    const geo::MultiPolygon ground{rect(0, 0, 200, 200), rect(201, 0, 204, 3)};
    auto o = spotOptions();
    o.realAcrossM = 40.0;
    std::vector<sensor::PhotoFootprint> photos;
    for (double x = 20; x < 200; x += 40)
        for (double y = 10; y < 200; y += 20)
            photos.push_back(sensor::PhotoFootprint{Vec2(x, y), 0.0, 40.0, 20.0});
    auto anywhere = [](const Vec2&) { return true; };
    auto c = chooseSpotPhotos(ground, photos, anywhere, o);
    ASSERT_TRUE(c.ok());
    EXPECT_NEAR(c->unseenBeforeM2, 9.0, 2.0);
    EXPECT_TRUE(c->photos.empty()); // below the patch size always taken, and 99.9 % is seen
    o.coverageGoal = 1.0;
    auto all = chooseSpotPhotos(ground, photos, anywhere, o);
    ASSERT_TRUE(all.ok());
    ASSERT_EQ(all->photos.size(), 1u);
    EXPECT_TRUE(inFootprint(all->photos[0], Vec2(202.5, 1.5), o));
    o.wholePatchM2 = 5.0; // a patch that size is always taken
    o.coverageGoal = 0.5;
    auto whole = chooseSpotPhotos(ground, photos, anywhere, o);
    ASSERT_TRUE(whole.ok());
    EXPECT_EQ(whole->photos.size(), 1u);
}

TEST(SpotPhotos, BadOptionsAreAnError) {
    auto o = spotOptions();
    o.realAlongM = 0.0;
    auto c = chooseSpotPhotos(
        geo::MultiPolygon{rect(0, 0, 10, 10)}, {}, [](const Vec2&) { return true; }, o);
    ASSERT_FALSE(c.ok());
    EXPECT_NE(c.error().message.find("positive"), std::string::npos);
}

namespace {

// Straight ways at 10 m/s between the places added.
struct StraightRouting {
    std::vector<Vec2> pts;
    SpotRouting routing() {
        SpotRouting r;
        r.add = [this](const Vec2& p, const Vec2&) {
            pts.push_back(p);
            return static_cast<int>(pts.size()) - 1;
        };
        r.timeS = [this](int a, int b) {
            return (pts[static_cast<std::size_t>(b)] - pts[static_cast<std::size_t>(a)]).norm() /
                   10.0;
        };
        r.way = [](int, int) { return std::vector<Vec2>{}; };
        return r;
    }
};

Lane eastLane(double y, bool east) {
    Lane l;
    for (double x = 0; x <= 100; x += 20)
        l.photos.emplace_back(x, y);
    if (!east)
        std::reverse(l.photos.begin(), l.photos.end());
    l.stripStart = l.photos.front();
    l.stripEnd = l.photos.back();
    l.headingDeg = east ? 90.0 : 270.0;
    return l;
}

} // namespace

TEST(SpotPhotos, PlacedWhereTheyAddLeastTime) {
    std::vector<Lane> lanes{eastLane(0, true), eastLane(50, false)};
    std::vector<std::vector<Vec2>> links{{}};
    std::vector<Vec2> homeLink, landingLink;
    std::vector<int> cells{3, 3};
    const std::optional<Vec2> home = Vec2(0, -20);
    // One beyond the turn between the lanes, one by home, one beyond the last lane's end.
    const std::vector<SpotPhoto> spots{
        {Vec2(110, 25), 0.0, 10.0}, {Vec2(-5, -12), 0.0, 10.0}, {Vec2(-10, 60), 0.0, 10.0}};
    StraightRouting sr;
    const int placed = placeSpotPhotos(lanes, links, homeLink, landingLink, cells, spots, home,
                                       std::nullopt, sr.routing());
    EXPECT_EQ(placed, 3);
    ASSERT_EQ(lanes.size(), 5u);
    ASSERT_EQ(cells.size(), 5u);
    EXPECT_EQ(links.size(), 4u);
    // home -> spot by home -> lane 0 -> spot at the turn -> lane 1 -> spot past its end (no
    // landing)
    EXPECT_EQ(lanes[0].photos, std::vector<Vec2>{Vec2(-5, -12)});
    EXPECT_EQ(lanes[1].photos.size(), 6u);
    EXPECT_EQ(lanes[2].photos, std::vector<Vec2>{Vec2(110, 25)});
    EXPECT_EQ(lanes[3].photos.front(), Vec2(100, 50));
    EXPECT_EQ(lanes[4].photos, std::vector<Vec2>{Vec2(-10, 60)});
    EXPECT_EQ(cells, (std::vector<int>{-1, 3, -1, 3, -1}));
}

TEST(SpotPhotos, TheSweepSeesMoreAndStaysOutOfTheMargins) {
    const Camera cam;
    int withSpots = 0;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const Area a = generateArea(seed + 500, 12 + static_cast<int>(seed % 8));
        SweepOptions o = options(cam);
        o.home = geo::bounds(a.region).min;
        // The same lanes with and without spot photos: the cells' own spacing only (shared lines are
        // kept only when their spot photos complete them, tested in sweep_planner_test), and the
        // direction the planner chooses with them (it compares the finished flights, spot photos
        // included, so without them it may choose another).
        o.sharedLines = false;
        auto chosen = planSweep(a.region, a.zones, o);
        ASSERT_TRUE(chosen.ok()) << a.name;
        o.anglesDeg = {chosen->stats.angleDeg};
        o.spotPhotos = false;
        auto without = planSweep(a.region, a.zones, o);
        o.spotPhotos = true;
        auto with = planSweep(a.region, a.zones, o);
        ASSERT_TRUE(with.ok() && without.ok()) << a.name;
        EXPECT_EQ(photoCount(*with), photoCount(*chosen)) << a.name;
        double unseenWith = 0.0, unseenWithout = 0.0;
        const double covWith = coverage(a, *with, cam, &unseenWith);
        const double covWithout = coverage(a, *without, cam, &unseenWithout);
        EXPECT_GE(covWith, covWithout - 1e-9) << a.name;
        EXPECT_EQ(photoCount(*with), photoCount(*without) + with->stats.spotPhotos) << a.name;
        if (with->stats.spotPhotos > 0) {
            ++withSpots;
            EXPECT_LT(unseenWith, unseenWithout) << a.name;
            EXPECT_GT(with->time.totalS, without->time.totalS) << a.name;
        }
        const auto path = sweepFlightPath(*with, o.home, o.home);
        FlightTimeAccumulator acc(o.time);
        for (const auto& p : path)
            acc.add(p);
        EXPECT_NEAR(acc.result().totalS, with->time.totalS, 1e-6) << a.name;
        const auto v = countNoFlyViolations({path}, a.zones, o.safetyMarginM);
        EXPECT_EQ(v.total(), 0) << a.name;
        EXPECT_EQ(with->lanes.size(), with->laneCells.size());
        EXPECT_EQ(with->links.size() + 1, with->lanes.size());
    }
    EXPECT_GE(withSpots, 3);
}
