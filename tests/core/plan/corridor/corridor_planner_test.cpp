// The corridor planner on generated corridors: lanes along the line cover the corridor's ground
// through bends of 10 to 120 degrees with no more photos than a Survey of its polygon would take,
// and keep every no-fly margin.
#include "core/geo/polygon_ops.h"
#include "core/plan/corridor/corridor_planner.h"
#include "corridor_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace pf::plan {
namespace {

using namespace corridortest;
using geo::Vec2;

TEST(CorridorPlanner, StraightCorridorIsLanesBackAndForth) {
    const Camera cam;
    const double width = widthFor(4, cam);
    auto p = planCorridor({Vec2(0, 0), Vec2(1000, 0)}, {}, optionsFor(width, cam));
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->stats.lanes, 4);
    ASSERT_EQ(p->runs.size(), 4u);
    const int perLane = static_cast<int>(std::ceil(1000.0 / cam.photo() - 1e-9));
    EXPECT_EQ(p->stats.photos, 4 * perLane);
    // Back and forth: each run starts at the end the last one finished.
    for (std::size_t i = 1; i < p->runs.size(); ++i) {
        const Vec2 end = p->runs[i - 1].points.back().pos, start = p->runs[i].points.front().pos;
        EXPECT_NEAR(end.x(), start.x(), 1e-6);
        EXPECT_LE((end - start).norm(), cam.track() + 1e-6);
        EXPECT_TRUE(p->links[i - 1].empty());
    }
    EXPECT_GE(coverage(*p, corridorGround({Vec2(0, 0), Vec2(1000, 0)}, width), cam), 0.999);
}

struct BendCase {
    double bendDeg;
    int lanes;
    double front, side;
};

std::string caseName(const BendCase& c) {
    return std::to_string(static_cast<int>(c.bendDeg)) + " deg, " + std::to_string(c.lanes) +
           " lanes, overlaps " + std::to_string(c.front) + "/" + std::to_string(c.side);
}

// Bends of 10 to 120 degrees both ways and widths of one to six lanes, with little overlap (20 %,
// the hardest case for the outside of a bend) and with a mapping overlap (75 % / 60 %): the real
// footprints see 99.5 % of the ground, and the photos stay within 1.10 times those of the Survey
// pattern over the corridor's polygon.
TEST(CorridorPlanner, BentCorridorsAreCoveredWithoutWastedPhotos) {
    std::vector<BendCase> cases;
    for (double bend : {10.0, 30.0, 60.0, 90.0, 120.0})
        for (int lanes : {1, 2, 3, 4, 5, 6})
            cases.push_back({bend, lanes, 0.2, 0.2});
    for (double bend : {10.0, 60.0, 120.0})
        for (int lanes : {1, 3, 6})
            cases.push_back({bend, lanes, 0.75, 0.6});
    double worstCover = 1.0, worstRatio = 0.0;
    for (const auto& c : cases) {
        Camera cam;
        cam.front = c.front;
        cam.side = c.side;
        const Polyline line = bentLine(400.0, {c.bendDeg, -c.bendDeg, c.bendDeg});
        const double width = widthFor(c.lanes, cam);
        auto p = planCorridor(line, {}, optionsFor(width, cam));
        ASSERT_TRUE(p.ok()) << caseName(c) << ": " << p.error().message;
        EXPECT_EQ(p->stats.lanes, c.lanes) << caseName(c);
        const auto ground = corridorGround(line, width);
        const double cover = coverage(*p, ground, cam);
        EXPECT_GE(cover, 0.995) << caseName(c);
        const int survey = lawnmowerPhotos(ground, cam);
        ASSERT_GT(survey, 0);
        const double ratio = static_cast<double>(photoCount(*p)) / survey;
        EXPECT_LE(ratio, 1.10) << caseName(c) << ": " << photoCount(*p) << " photos, the Survey "
                               << survey;
        worstCover = std::min(worstCover, cover);
        worstRatio = std::max(worstRatio, ratio);
    }
    std::printf("bent corridors: lowest coverage %.4f, highest photos / Survey %.3f\n", worstCover,
                worstRatio);
}

// Zones across and beside a bent corridor: no photo and no leg within the margin, the rest covered.
TEST(CorridorPlanner, ZonesAreFlownRoundAndTheirMarginsKept) {
    const Camera cam;
    const Polyline line = bentLine(400.0, {60.0, -90.0});
    const double width = widthFor(4, cam), margin = 5.0;
    const std::vector<geo::Polygon> zones{
        geo::Polygon{{Vec2(150, 30), Vec2(190, 30), Vec2(190, 90), Vec2(150, 90)},
                     {}},                                                   // inside, cutting lanes
        geo::Polygon{{Vec2(480, 250), Vec2(520, 330), Vec2(560, 300)}, {}}, // near the first bend
    };
    CorridorOptions o = optionsFor(width, cam);
    o.safetyMarginM = margin;
    o.home = Vec2(-60, -60);
    auto p = planCorridor(line, zones, o);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_GT(p->stats.runs, p->stats.lanes); // the zone cuts some lanes
    const auto path = corridorFlightPath(*p, o.home, o.landing);
    const NoFlyViolations v = countNoFlyViolations({path}, zones, margin);
    EXPECT_EQ(v.total(), 0);
    // The ground outside the zones (their margins included: seen from outside) is covered.
    const auto ground =
        geo::difference(corridorGround(line, width), geo::MultiPolygon(zones.begin(), zones.end()));
    EXPECT_GE(coverage(*p, ground, cam), 0.99);
}

// A zone right across the corridor: the lanes on either side are flown section by section, so the
// aircraft goes round the zone once rather than on every lane.
TEST(CorridorPlanner, ZoneAcrossTheCorridorSplitsItIntoSections) {
    const Camera cam;
    const Polyline line{Vec2(0, 0), Vec2(2000, 0)};
    const double width = widthFor(3, cam);
    const std::vector<geo::Polygon> zones{
        geo::Polygon{{Vec2(990, -200), Vec2(1010, -200), Vec2(1010, 200), Vec2(990, 200)}, {}}};
    CorridorOptions o = optionsFor(width, cam);
    o.home = Vec2(0, -80);
    auto p = planCorridor(line, zones, o);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->stats.sections, 2);
    int detours = 0;
    for (const auto& l : p->links)
        detours += !l.empty();
    EXPECT_EQ(detours, 1);
    EXPECT_EQ(
        countNoFlyViolations({corridorFlightPath(*p, o.home, o.landing)}, zones, o.safetyMarginM)
            .total(),
        0);
}

TEST(CorridorPlanner, BadInputIsRefusedWithAReason) {
    const Camera cam;
    auto o = optionsFor(50.0, cam);
    EXPECT_FALSE(planCorridor({Vec2(0, 0)}, {}, o).ok());
    EXPECT_FALSE(planCorridor({Vec2(0, 0), Vec2(0, 0.001)}, {}, o).ok());
    o.widthM = 0;
    auto p = planCorridor({Vec2(0, 0), Vec2(100, 0)}, {}, o);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("width"), std::string::npos);
    o = optionsFor(50.0, cam);
    o.home = Vec2(50, 0);
    const std::vector<geo::Polygon> zone{
        geo::Polygon{{Vec2(40, -10), Vec2(60, -10), Vec2(60, 10), Vec2(40, 10)}, {}}};
    EXPECT_FALSE(planCorridor({Vec2(0, 0), Vec2(100, 0)}, zone, o).ok());
}

} // namespace
} // namespace pf::plan
