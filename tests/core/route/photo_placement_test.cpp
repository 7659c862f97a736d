// Safe photo placement (photoWaypoints): photos are made outside every no-fly margin, slid back along
// the track, and the ground stays covered as the independent coverage check measures it; end to end the
// no-fly stage then has no waypoint to move.
#include "core/geo/polygon_ops.h"
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mission/validation.h"
#include "core/plan/coverage_check.h"
#include "core/plan/evaluation.h"
#include "core/plan/planner.h"
#include "core/route/photo_waypoints.h"
#include "core/route/safety.h"
#include "tests/sample_missions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace pf::route {
namespace {

using geo::Vec2;

geo::Polygon rect(double x0, double y0, double x1, double y1) {
    return geo::Polygon{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}, {}};
}

sensor::EffectiveFootprint footprint(double across, double along, double realLong, double realShort) {
    sensor::EffectiveFootprint fp;
    fp.acrossM = across;
    fp.alongM = along;
    fp.real.longSideM = realLong;
    fp.real.shortSideM = realShort;
    return fp;
}

std::vector<plan::PhotoFootprint> realFootprints(const std::vector<LocalWaypoint>& wps,
                                                 const sensor::EffectiveFootprint& fp) {
    std::vector<plan::PhotoFootprint> out;
    for (const auto& w : wps)
        if (w.kind == WaypointKind::Photo)
            out.push_back({w.pos, w.headingDeg, fp.real.longSideM, fp.real.shortSideM});
    return out;
}

int countPhotos(const std::vector<LocalWaypoint>& wps) {
    int n = 0;
    for (const auto& w : wps)
        n += w.kind == WaypointKind::Photo;
    return n;
}

// A row of five 20 m cells flown east towards a zone east of the area: the last cell's centre keeps the
// 10 m margin, its forward photo (2 per cell) does not.
struct RowFixture {
    geo::Polygon area = rect(0, 0, 100, 20);
    std::vector<geo::Polygon> zones;
    grid::Grid grid;
    plan::CellPath path;

    explicit RowFixture(double zoneX) : zones{rect(zoneX, -10, zoneX + 20, 30)} {
        grid::GridOptions opt;
        opt.cellSize = 20;
        opt.safetyMarginM = 10;
        auto g = grid::Grid::build(area, zones, opt);
        EXPECT_TRUE(g.ok()) << (g.ok() ? "" : g.error().message);
        if (g.ok())
            grid = std::move(*g);
        for (int c = 0; c < 5; ++c) {
            path.cells.push_back(grid.index(c, 0));
            path.revisit.push_back(false);
        }
    }
};

TEST(PhotoPlacement, PhotoInAMarginSlidesBackAlongTheTrackToTheMarginAndKeepsTheCellCovered) {
    RowFixture fx(104.0); // the margin reaches back to x = 94 (93.8 with the grid's buffer)
    ASSERT_EQ(fx.grid.cols(), 5);
    ASSERT_EQ(fx.grid.state(fx.grid.index(4, 0)), grid::CellState::Free);
    const auto fp = footprint(20, 10, 40, 30);
    PhotoPlacement placed;
    const auto wps = photoWaypoints(fx.grid, fx.path, fp, &placed, PhotoRule::PerCell);
    ASSERT_EQ(wps.size(), 10u);
    EXPECT_EQ(placed.slid, 1);
    EXPECT_EQ(placed.merged, 0);
    // Only the last photo moved: back along the track (same y, same heading), to the margin's edge.
    for (std::size_t k = 0; k + 1 < wps.size(); ++k)
        EXPECT_NEAR(wps[k].pos.x(), 5.0 + 10.0 * static_cast<double>(k), 1e-9);
    const LocalWaypoint& last = wps.back();
    EXPECT_EQ(last.kind, WaypointKind::Photo);
    EXPECT_EQ(last.cell, fx.grid.index(4, 0));
    EXPECT_DOUBLE_EQ(last.headingDeg, 90.0);
    EXPECT_NEAR(last.pos.y(), 10.0, 1e-9);
    EXPECT_LT(last.pos.x(), 94.0 + 1e-6);
    EXPECT_GT(last.pos.x(), 93.0); // not further back than the buffered margin needs
    EXPECT_NEAR(placed.maxSlideM, 95.0 - last.pos.x(), 1e-9);
    EXPECT_TRUE(fx.grid.pointIsSafe(last.pos));

    // The exact field agrees: nothing for the no-fly stage to move, no detour.
    const SafePathFinder finder(NoFlyField(fx.zones, 10));
    SafetyReport rep;
    auto safe = enforceNoFly(wps, finder, &rep);
    ASSERT_TRUE(safe.ok());
    EXPECT_EQ(rep.waypointsMoved, 0);
    EXPECT_EQ(rep.detours, 0);
    EXPECT_TRUE(rep.warnings.empty());

    // The whole area, the margin strip x in [94, 100] included, is still on the photos.
    auto cov = plan::checkCoverage({fx.area}, realFootprints(wps, fp));
    ASSERT_TRUE(cov.ok());
    EXPECT_GE(cov->coveredFraction, 0.9999);
}

// The same row as one lane: it ends at the margin, the last photo moved back to the margin's edge by the
// lane rule (nothing left to slide), the other photos at the trigger distance, the area still covered.
TEST(PhotoPlacement, LaneIntoAMarginEndsAtTheMarginAndKeepsTheAreaCovered) {
    RowFixture fx(104.0);
    const auto fp = footprint(20, 10, 40, 30);
    PhotoPlacement placed;
    const auto wps = photoWaypoints(fx.grid, fx.path, fp, &placed);
    ASSERT_EQ(wps.size(), 10u);
    EXPECT_EQ(placed.slid, 0);
    for (std::size_t k = 0; k + 1 < wps.size(); ++k) {
        EXPECT_NEAR(wps[k].pos.x(), 5.0 + 10.0 * static_cast<double>(k), 1e-9);
        EXPECT_NEAR(wps[k].pos.y(), 10.0, 1e-9);
    }
    EXPECT_LT(wps.back().pos.x(), 94.0 + 1e-6);
    EXPECT_GT(wps.back().pos.x(), 93.0);
    EXPECT_NEAR(wps.back().pos.y(), 10.0, 1e-9);
    EXPECT_TRUE(fx.grid.pointIsSafe(wps.back().pos));
    const SafePathFinder finder(NoFlyField(fx.zones, 10));
    SafetyReport rep;
    auto safe = enforceNoFly(wps, finder, &rep);
    ASSERT_TRUE(safe.ok());
    EXPECT_EQ(rep.waypointsMoved, 0);
    EXPECT_EQ(rep.detours, 0);
    auto cov = plan::checkCoverage({fx.area}, realFootprints(wps, fp));
    ASSERT_TRUE(cov.ok());
    EXPECT_GE(cov->coveredFraction, 0.9999);
}

TEST(PhotoPlacement, TwoPhotosSlidOntoTheSamePointBecomeOne) {
    // Four photos per cell (at 82.5, 87.5, 92.5, 97.5 in the last cell); the margin ends at 91.8, so the
    // last two slide to the same point and the second is dropped.
    RowFixture fx(102.0);
    ASSERT_EQ(fx.grid.state(fx.grid.index(4, 0)), grid::CellState::Free);
    const auto fp = footprint(20, 5, 30, 22);
    PhotoPlacement placed;
    const auto wps = photoWaypoints(fx.grid, fx.path, fp, &placed, PhotoRule::PerCell);
    EXPECT_EQ(placed.slid, 2);
    EXPECT_EQ(placed.merged, 1);
    EXPECT_EQ(countPhotos(wps), 19);
    for (std::size_t k = 1; k < wps.size(); ++k)
        EXPECT_GT((wps[k].pos - wps[k - 1].pos).norm(), 0.01);
    for (const auto& w : wps)
        EXPECT_TRUE(fx.grid.pointIsSafe(w.pos)) << w.pos.transpose();
    auto cov = plan::checkCoverage({fx.area}, realFootprints(wps, fp));
    ASSERT_TRUE(cov.ok());
    EXPECT_GE(cov->coveredFraction, 0.9999);
    const auto violations =
        plan::countNoFlyViolations({[&] {
                                       std::vector<Vec2> p;
                                       for (const auto& w : wps)
                                           p.push_back(w.pos);
                                       return p;
                                   }()},
                                   fx.zones, 10);
    EXPECT_EQ(violations.total(), 0);
}

// A star-shaped area around the origin with `n` vertices at radii in [0.6, 1] x r.
geo::Polygon randomArea(std::mt19937& rng, double r) {
    std::uniform_real_distribution<double> rad(0.6 * r, r);
    const int n = 7 + static_cast<int>(rng() % 6);
    geo::Ring ring;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n;
        const double d = rad(rng);
        ring.emplace_back(d * std::cos(a), d * std::sin(a));
    }
    return {ring, {}};
}

struct GeneratedStats {
    int shapes = 0;
    int slid = 0;
    int added = 0;
    double minCoverage = 1.0;
    double meanCoverage = 0.0;
};

// Seeded generated missions (a star-shaped area, 1 to 3 zones, margin, a 4:3 sensor, overlaps with the
// side overlap in [sideLo, sideHi], grid angle), each checked for: every waypoint safe, every leg whose
// cells the grid joins straight safe (except the legs of extra photos, which the detours fly), nothing
// for the exact no-fly stage to move, no margin breached once it has added its detours. Returns the
// coverage of the admissible area by the real footprints.
GeneratedStats placeGeneratedMissions(unsigned seed, double sideLo, double sideHi, PhotoRule rule) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    GeneratedStats st;
    for (int trial = 0; trial < 40; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const double r = 150 + 150 * u(rng);
        const geo::Polygon area = randomArea(rng, r);
        std::vector<geo::Polygon> zones;
        const int nz = 1 + static_cast<int>(rng() % 3);
        for (int z = 0; z < nz; ++z) {
            const double cx = (u(rng) - 0.5) * r, cy = (u(rng) - 0.5) * r;
            const double w = 10 + 30 * u(rng), h = 10 + 30 * u(rng);
            zones.push_back(rect(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2));
        }
        const double margin = 3 + 12 * u(rng);
        const double longSide = 30 + 50 * u(rng), shortSide = 0.75 * longSide;
        const double side = sideLo + (sideHi - sideLo) * u(rng), front = 0.6 + 0.25 * u(rng);
        const auto fp = footprint(longSide * (1 - side), shortSide * (1 - front), longSide, shortSide);
        grid::GridOptions opt;
        opt.cellSize = sensor::cellSizeFor(fp);
        opt.angleDeg = 180 * u(rng);
        opt.safetyMarginM = margin;
        auto g = grid::Grid::build(area, zones, opt);
        if (!g.ok())
            continue; // a zone covering the area: nothing to place
        auto path = plan::planCoverage(*g, {}, {});
        EXPECT_TRUE(path.ok()) << path.error().message;
        if (!path.ok())
            continue;
        ++st.shapes;
        PhotoPlacement placed;
        const auto wps = photoWaypoints(*g, *path, fp, &placed, rule);
        st.slid += placed.slid;
        st.added += placed.added;

        for (std::size_t k = 0; k < wps.size(); ++k) {
            EXPECT_TRUE(g->pointIsSafe(wps[k].pos)) << "waypoint " << k;
            if (placed.added == 0 && k > 0 &&
                g->segmentIsSafe(g->flightPosition(wps[k - 1].cell), g->flightPosition(wps[k].cell))) {
                EXPECT_TRUE(g->segmentIsSafe(wps[k - 1].pos, wps[k].pos)) << "leg to waypoint " << k << [&] {
                    std::string s;
                    for (std::size_t j = k >= 3 ? k - 3 : 0; j < std::min(wps.size(), k + 3); ++j)
                        s += "\n  " + std::to_string(j) + " kind " + std::to_string(int(wps[j].kind)) + " cell " +
                             std::to_string(wps[j].cell) + " (" + std::to_string(g->col(wps[j].cell)) + "," +
                             std::to_string(g->row(wps[j].cell)) + ") pos " + std::to_string(wps[j].pos.x()) + " " +
                             std::to_string(wps[j].pos.y()) + " fp " + std::to_string(g->flightPosition(wps[j].cell).x()) +
                             " " + std::to_string(g->flightPosition(wps[j].cell).y()) + " state " +
                             std::to_string(int(g->state(wps[j].cell)));
                    return s;
                }();
            }
        }
        const SafePathFinder finder(NoFlyField(zones, margin));
        SafetyReport rep;
        auto safe = enforceNoFly(wps, finder, &rep);
        EXPECT_TRUE(safe.ok()) << safe.error().message;
        if (!safe.ok())
            continue;
        EXPECT_EQ(rep.waypointsMoved, 0);
        std::vector<Vec2> flown;
        for (const auto& w : *safe)
            flown.push_back(w.pos);
        EXPECT_EQ(plan::countNoFlyViolations({flown}, zones, margin).total(), 0);

        auto cov = plan::checkCoverage(geo::difference(area, zones), realFootprints(*safe, fp));
        EXPECT_TRUE(cov.ok());
        if (!cov.ok())
            continue;
        st.minCoverage = std::min(st.minCoverage, cov->coveredFraction);
        st.meanCoverage += cov->coveredFraction;
    }
    if (st.shapes > 0)
        st.meanCoverage /= st.shapes;
    return st;
}

// Usual overlaps (side >= 0.3): the real short side is at least the cell side, so a slid photo always
// keeps its share of the cell in view: no extra photo, and coverage >= 0.995 on every mission.
TEST(PhotoPlacement, GeneratedMissionsArePlacedSafeAndStayCovered) {
    for (PhotoRule rule : {PhotoRule::PerCell, PhotoRule::Lanes}) {
        const char* name = rule == PhotoRule::Lanes ? "lanes" : "per cell";
        const GeneratedStats st = placeGeneratedMissions(20261122, 0.3, 0.8, rule);
        std::printf("usual overlaps, %s: %d missions, %d photos slid, %d added, coverage min %.4f mean %.4f\n", name,
                    st.shapes, st.slid, st.added, st.minCoverage, st.meanCoverage);
        EXPECT_GE(st.shapes, 30) << name;
        EXPECT_GT(st.slid, 0) << name; // the generated zones do put photos in margins
        EXPECT_EQ(st.added, 0) << name;
        EXPECT_GE(st.minCoverage, 0.995) << name;
    }
}

// A low side overlap (< 0.2) makes the real short side shorter than the cell: slid photos may lose part
// of their share in a margin, and an extra photo beside the margin takes it back. Such missions lose
// some ground whatever the placement (the ground deep in a margin is seen only from inside it); the
// bounds below are what this placement keeps, measured with the independent check.
TEST(PhotoPlacement, LowSideOverlapAddsPhotosBesideTheMargins) {
    for (PhotoRule rule : {PhotoRule::PerCell, PhotoRule::Lanes}) {
        const char* name = rule == PhotoRule::Lanes ? "lanes" : "per cell";
        const GeneratedStats st = placeGeneratedMissions(20261122, 0.0, 0.2, rule);
        std::printf("low side overlap, %s: %d missions, %d photos slid, %d added, coverage min %.4f mean %.4f\n",
                    name, st.shapes, st.slid, st.added, st.minCoverage, st.meanCoverage);
        EXPECT_GE(st.shapes, 30) << name;
        EXPECT_GT(st.added, 0) << name;
        EXPECT_GE(st.minCoverage, 0.99) << name;
        EXPECT_GE(st.meanCoverage, 0.998) << name;
    }
}

// ---- end to end -------------------------------------------------------------------------------------

// The ground of every cell of the plan's grids that lies wholly within a margin (Unflyable: never flown
// over) is on the real footprints of the plan's photos; returns how many such cells there were.
int expectUnflyableGroundPhotographed(const mission::MissionPlan& plan, const geo::MultiPolygon& admissible,
                                      const std::string& what) {
    std::vector<plan::PhotoFootprint> photos;
    for (const auto& a : plan.aircraft)
        for (const auto& w : a.localWaypoints)
            if (w.kind == WaypointKind::Photo)
                photos.push_back({w.pos, w.headingDeg, a.footprint.real.longSideM, a.footprint.real.shortSideM});
    int cells = 0;
    for (const auto& a : plan.aircraft) {
        const grid::Grid& g = a.grid;
        for (int c = 0; c < g.cellCount(); ++c) {
            if (g.state(c) != grid::CellState::Unflyable)
                continue;
            const auto ground = geo::intersection(admissible, geo::Polygon{g.cellCorners(c), {}});
            if (geo::area(ground) <= 1e-6)
                continue;
            ++cells;
            auto cov = plan::checkCoverage(ground, photos);
            EXPECT_TRUE(cov.ok());
            if (cov.ok()) {
                EXPECT_GE(cov->coveredFraction, 0.995) << what << ", " << a.aircraft << ", cell " << c;
            }
        }
    }
    return cells;
}

void expectNothingMoved(const mission::MissionPlan& plan, const std::string& what) {
    for (const auto& a : plan.aircraft)
        EXPECT_EQ(a.waypointsMoved, 0) << what << ", " << a.aircraft;
    for (const auto& w : plan.warnings)
        EXPECT_EQ(w.find("moved"), std::string::npos) << what << ": " << w;
    EXPECT_GE(plan.coverageRatio, 0.995) << what;
    EXPECT_EQ(plan.noFlyViolations, 0) << what;
}

TEST(PhotoPlacement, DemoMissionHasNothingToMoveAndStaysCovered) {
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    ASSERT_TRUE(m.ok()) << m.error().message;
    auto plan = mission::planMission(*m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    ASSERT_GE(plan->aircraft.size(), 2u);
    expectNothingMoved(*plan, "demo");
}

// The sample areas as the fleet target tests plan them: one catalog-like aircraft, home 30 m south.
mission::Mission sampleMission(const std::string& name) {
    auto ea = plan::loadEvalArea(std::string(PF_RESOURCES_DIR) + "/areas/" + name + ".geojson");
    EXPECT_TRUE(ea.ok()) << name;
    if (!ea.ok())
        return {};
    mission::Mission m = test::sampleAreaMission(*ea);
    m.name = name;
    mission::AircraftConfig a;
    a.name = "survey";
    a.camera.hfovDeg = 61.93;
    a.camera.vfovDeg = 48.46;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = 50;
    a.cruiseSpeedMps = 10;
    a.enduranceMin = 60;
    m.aircraft = {a};
    return m;
}

TEST(PhotoPlacement, SampleAreasHaveNothingToMoveAndStayCovered) {
    int unflyable = 0;
    for (const std::string name : {"a_concave", "b_teeth", "c_l_shape", "d_nofly", "e_staircase", "f_complex"}) {
        for (auto kind : {mission::PlannerKind::Stride, mission::PlannerKind::Wavefront}) {
            mission::Mission m = sampleMission(name);
            m.options.planner = kind;
            auto plan = mission::planMission(m);
            ASSERT_TRUE(plan.ok()) << name << ": " << plan.error().message;
            const std::string what = name + (kind == mission::PlannerKind::Stride ? " stride" : " wavefront");
            expectNothingMoved(*plan, what);
            auto geom = mission::localGeometry(m);
            ASSERT_TRUE(geom.ok());
            unflyable += expectUnflyableGroundPhotographed(*plan, geo::difference(geom->area, geom->noFly), what);
        }
    }
    std::printf("cells wholly within a margin, their ground photographed: %d\n", unflyable);
}

// What validation says of the cells wholly inside a safety margin (Unflyable): they are not flown over,
// and the photos of the planned flight still see their ground. On the demo, every such cell of the grid
// validation builds has its admissible part on the plan's real footprints.
TEST(PhotoPlacement, DemoCellsInsideAMarginAreNotFlownButTheirGroundIsPhotographed) {
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    ASSERT_TRUE(m.ok()) << m.error().message;
    auto geom = mission::localGeometry(*m);
    ASSERT_TRUE(geom.ok());
    auto plan = mission::planMission(*m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    std::vector<plan::PhotoFootprint> photos;
    for (const auto& a : plan->aircraft)
        for (const auto& w : a.localWaypoints)
            if (w.kind == WaypointKind::Photo)
                photos.push_back({w.pos, w.headingDeg, a.footprint.real.longSideM, a.footprint.real.shortSideM});
    const geo::MultiPolygon admissible = geo::difference(geom->area, geom->noFly);
    int unflyable = 0;
    for (std::size_t k = 0; k < m->aircraft.size(); ++k) {
        auto gopt = mission::gridOptionsFor(*m, k);
        ASSERT_TRUE(gopt.ok());
        auto g = grid::Grid::build(geom->area, geom->noFly, *gopt);
        ASSERT_TRUE(g.ok());
        for (int c = 0; c < g->cellCount(); ++c) {
            if (g->state(c) != grid::CellState::Unflyable)
                continue;
            ++unflyable;
            const auto ground = geo::intersection(admissible, geo::Polygon{g->cellCorners(c), {}});
            ASSERT_GT(geo::area(ground), 0.0);
            auto cov = plan::checkCoverage(ground, photos);
            ASSERT_TRUE(cov.ok());
            EXPECT_GE(cov->coveredFraction, 0.995) << "cell " << c << " of aircraft " << k;
        }
    }
    EXPECT_GT(unflyable, 0); // the demo has such cells: the test checks something
}

} // namespace
} // namespace pf::route
