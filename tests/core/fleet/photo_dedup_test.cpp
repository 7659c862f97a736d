#include "core/fleet/photo_dedup.h"

#include "core/geo/polygon_ops.h"
#include "core/plan/coverage_check.h"

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::fleet;
using geo::Vec2;

namespace {

geo::Polygon rect(double x0, double y0, double x1, double y1) {
    return geo::Polygon{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}, {}};
}

// Back-and-forth photo tracks flown east-west over [x0, x1] x [y0, y1] with the given effective
// spacing, the way a single-aircraft plan lays them out (tracks `across` apart, photos `along`).
AircraftPhotos survey(double x0, double x1, double y0, double y1, double across, double along, double realAcross,
                      double realAlong) {
    AircraftPhotos a;
    a.effectiveAcrossM = across;
    a.effectiveAlongM = along;
    a.realAcrossM = realAcross;
    a.realAlongM = realAlong;
    int track = 0;
    for (double y = y0 + across / 2; y < y1; y += across, ++track) {
        std::vector<route::LocalWaypoint> row;
        for (double x = x0 + along / 2; x < x1; x += along) {
            route::LocalWaypoint w;
            w.pos = Vec2(x, y);
            w.headingDeg = 90;
            row.push_back(w);
        }
        if (track % 2 == 1) {
            std::reverse(row.begin(), row.end());
            for (auto& w : row)
                w.headingDeg = 270;
        }
        a.waypoints.insert(a.waypoints.end(), row.begin(), row.end());
    }
    return a;
}

std::vector<plan::PhotoFootprint> realFootprints(const std::vector<AircraftPhotos>& fleet) {
    std::vector<plan::PhotoFootprint> out;
    for (const auto& a : fleet)
        for (const auto& w : a.waypoints)
            if (w.kind == route::WaypointKind::Photo)
                out.push_back({w.pos, w.headingDeg, a.realAcrossM, a.realAlongM});
    return out;
}

int photoCount(const AircraftPhotos& a) {
    int n = 0;
    for (const auto& w : a.waypoints)
        n += w.kind == route::WaypointKind::Photo;
    return n;
}

} // namespace

// A small-footprint aircraft over the south half and a large-footprint one over the north half,
// their per-aircraft grids overlapping by a band: the band's small photos are saved, and the
// independent checker finds the area exactly as covered as before.
TEST(PhotoDedup, SavesPhotosWithoutOpeningAGap) {
    std::vector<AircraftPhotos> fleet{survey(0, 120, 0, 60, 10, 6, 25, 15),
                                      survey(0, 120, 40, 120, 30, 18, 60, 40)};
    const geo::MultiPolygon area{rect(0, 0, 120, 120)};
    auto before = plan::checkCoverage(area, realFootprints(fleet));
    ASSERT_TRUE(before.ok());
    ASSERT_DOUBLE_EQ(before->coveredFraction, 1.0);
    const int photos0 = photoCount(fleet[0]), photos1 = photoCount(fleet[1]);
    auto rep = dropDuplicatePhotos(fleet);
    ASSERT_TRUE(rep.ok()) << rep.error().message;
    EXPECT_GT(rep->photosSaved[0], 0);
    EXPECT_EQ(rep->photosSaved[0] + rep->photosSaved[1], rep->totalSaved);
    EXPECT_EQ(photoCount(fleet[0]), photos0 - rep->photosSaved[0]);
    EXPECT_EQ(photoCount(fleet[1]), photos1 - rep->photosSaved[1]);
    auto after = plan::checkCoverage(area, realFootprints(fleet));
    ASSERT_TRUE(after.ok());
    EXPECT_DOUBLE_EQ(after->coveredFraction, 1.0);
    // Every photo kept still ends a leg of its route: no waypoint dangles past the last photo.
    for (const auto& a : fleet) {
        ASSERT_FALSE(a.waypoints.empty());
        EXPECT_EQ(a.waypoints.front().kind, route::WaypointKind::Photo);
        EXPECT_EQ(a.waypoints.back().kind, route::WaypointKind::Photo);
    }
}

// A photo whose effective footprint is only partly under the other aircraft's footprints keeps
// its picture.
TEST(PhotoDedup, PartialOverlapKeepsThePhoto) {
    std::vector<AircraftPhotos> fleet{survey(0, 12, 0, 20, 20, 12, 30, 20), survey(10, 40, 0, 20, 20, 30, 30, 20)};
    // Aircraft 0: one photo at (6, 10), effective [0, 12] x [0, 20]. Aircraft 1: one photo at (25, 10),
    // real [15, 35] x [-5, 25]: covers x >= 15 only.
    ASSERT_EQ(fleet[0].waypoints.size(), 1u);
    ASSERT_EQ(fleet[1].waypoints.size(), 1u);
    auto rep = dropDuplicatePhotos(fleet);
    ASSERT_TRUE(rep.ok());
    EXPECT_EQ(rep->totalSaved, 0);
    EXPECT_EQ(fleet[0].waypoints.size(), 1u);
}

// Two photos covering each other: only one of them may go.
TEST(PhotoDedup, MutualCoverDropsOnlyOne) {
    std::vector<AircraftPhotos> fleet{survey(0, 10, 0, 10, 10, 10, 40, 40), survey(0, 10, 0, 10, 10, 10, 40, 40)};
    auto rep = dropDuplicatePhotos(fleet);
    ASSERT_TRUE(rep.ok());
    EXPECT_EQ(rep->totalSaved, 1);
    EXPECT_EQ(photoCount(fleet[0]) + photoCount(fleet[1]), 1);
}

TEST(PhotoDedup, StraightThroughWaypointsGoAndBendsBecomeTurns) {
    // Aircraft 0 flies a hook (east, then north); all its photos lie under aircraft 1's big photo
    // except the last one.
    AircraftPhotos a;
    a.effectiveAcrossM = 4;
    a.effectiveAlongM = 4;
    a.realAcrossM = 6;
    a.realAlongM = 6;
    for (Vec2 p : {Vec2(2, 2), Vec2(6, 2), Vec2(10, 2), Vec2(10, 6), Vec2(10, 40)}) {
        route::LocalWaypoint w;
        w.pos = p;
        a.waypoints.push_back(w);
    }
    AircraftPhotos b;
    b.effectiveAcrossM = 10;
    b.effectiveAlongM = 10;
    b.realAcrossM = 30;
    b.realAlongM = 30;
    route::LocalWaypoint big;
    big.pos = Vec2(8, 8);
    b.waypoints.push_back(big);
    std::vector<AircraftPhotos> fleet{a, b};
    auto rep = dropDuplicatePhotos(fleet);
    ASSERT_TRUE(rep.ok());
    EXPECT_EQ(rep->photosSaved[0], 4);
    // (2,2) and (6,2) lead nowhere and are trimmed; (10,2) is a bend: a Turn; (10,6) runs straight.
    ASSERT_EQ(fleet[0].waypoints.size(), 1u);
    EXPECT_EQ(fleet[0].waypoints[0].pos, Vec2(10, 40));
    EXPECT_EQ(photoCount(fleet[1]), 1);
}

TEST(PhotoDedup, BadFootprintIsRejected) {
    std::vector<AircraftPhotos> fleet{AircraftPhotos{}, AircraftPhotos{}};
    auto rep = dropDuplicatePhotos(fleet);
    ASSERT_FALSE(rep.ok());
    EXPECT_EQ(rep.error().message, "Aircraft 1 has a photo footprint side that is not positive.");
}

namespace {

AircraftPhotos photosAt(std::vector<std::pair<Vec2, double>> posHeading, double effAcross, double effAlong,
                        double realAcross, double realAlong) {
    AircraftPhotos a;
    a.effectiveAcrossM = effAcross;
    a.effectiveAlongM = effAlong;
    a.realAcrossM = realAcross;
    a.realAlongM = realAlong;
    for (const auto& [p, h] : posHeading) {
        route::LocalWaypoint w;
        w.pos = p;
        w.headingDeg = h;
        a.waypoints.push_back(w);
    }
    return a;
}

} // namespace

// The three ways a photo is decided: inside one neighbour's photo (even turned 45 degrees to it),
// under two neighbours' photos together (neither alone covers it), and under two photos whose
// overlaps add up to more than its area while a strip of it stays unseen.
TEST(PhotoDedup, CoveredAloneJointlyOrNotAtAll) {
    // A 10 x 10 m effective footprint at (5, 5), heading 45: its corners 7.07 m from the centre,
    // inside a 16 x 16 m photo of the other aircraft.
    {
        std::vector<AircraftPhotos> fleet{photosAt({{Vec2(5, 5), 45}}, 10, 10, 12, 12),
                                          photosAt({{Vec2(5, 5), 0}}, 11, 11, 16, 16)};
        auto rep = dropDuplicatePhotos(fleet);
        ASSERT_TRUE(rep.ok());
        EXPECT_EQ(rep->photosSaved[0], 1);
    }
    // Heading 90: along = x. Two 14 x 8 m photos at y 2 and 8 span y -2..12 together.
    {
        std::vector<AircraftPhotos> fleet{photosAt({{Vec2(5, 5), 90}}, 10, 10, 12, 12),
                                          photosAt({{Vec2(5, 2), 90}, {Vec2(5, 8), 90}}, 11, 11, 8, 14)};
        auto rep = dropDuplicatePhotos(fleet);
        ASSERT_TRUE(rep.ok());
        EXPECT_EQ(rep->photosSaved[0], 1);
        EXPECT_EQ(photoCount(fleet[1]), 2);
    }
    // At y 3 and 3.5 they see 70 and 75 m2 of the 100 m2, 145 m2 in all, but nothing above y 7.5.
    {
        std::vector<AircraftPhotos> fleet{photosAt({{Vec2(5, 5), 90}}, 10, 10, 12, 12),
                                          photosAt({{Vec2(5, 3), 90}, {Vec2(5, 3.5), 90}}, 11, 11, 8, 14)};
        auto rep = dropDuplicatePhotos(fleet);
        ASSERT_TRUE(rep.ok());
        EXPECT_EQ(rep->photosSaved[0], 0);
        EXPECT_EQ(photoCount(fleet[0]), 1);
    }
}
