// Photo spacing per lane over terrain: each lane's trigger distance from the lowest height above
// ground along it (terrain_stage.h's laneSpacing). On a Gaussian hill every planner takes fewer
// photos than with the area-wide spacing, with the front overlap from the footprints on the terrain
// never below the setting on any lane, the GSD and the coverage kept, and no photo in a no-fly
// margin; on flat ground the plan is the one without per-lane spacing; the demo mission over the
// demo DEM saves photos too.
#include "core/geo/polygon_ops.h"
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/terrain_stage.h"
#include "core/mission/validation.h"
#include "core/sensor/camera.h"
#include "core/terrain/terrain_footprint.h"

#include "tests/core/terrain/terrain_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace pf::mission {
namespace {

using terrain::test::overlapAlong;

const geo::LonLat kOrigin{8.33, 49.012};

std::string tmp(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / "pf_terrain_lane_spacing_test";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

// A 360 x 260 m field, one aircraft with a 60 x 45 degree camera at 40 m above the ground, a small
// no-fly zone in the north-west.
Mission fieldMission(PlannerKind planner) {
    const auto f = *geo::LocalFrame::create(kOrigin);
    Mission m;
    m.name = "terrain field";
    for (const geo::Vec2& p :
         {geo::Vec2(-180, -130), geo::Vec2(180, -130), geo::Vec2(180, 130), geo::Vec2(-180, 130)})
        m.area.outer.push_back(f.toGeo(p));
    NoFlyZone z;
    z.name = "Shed";
    for (const geo::Vec2& p :
         {geo::Vec2(-120, 50), geo::Vec2(-95, 50), geo::Vec2(-95, 75), geo::Vec2(-120, 75)})
        z.polygon.outer.push_back(f.toGeo(p));
    m.noFlyZones.push_back(z);
    m.home = f.toGeo(geo::Vec2(-200, -150));
    AircraftConfig a;
    a.name = "Quad";
    a.model = "custom";
    a.camera.name = "60x45";
    a.camera.hfovDeg = 60.0;
    a.camera.vfovDeg = 45.0;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = 40.0;
    a.overlap = {0.7, 0.6};
    a.enduranceMin = 60.0;
    m.aircraft.push_back(a);
    m.options.planner = planner;
    m.options.gridAngleDeg = 0.0;
    m.terrain.mode = TerrainMode::Follow;
    m.terrain.minClearanceM = 15.0;
    return m;
}

struct Pair {
    Mission mission;
    MissionPlan perLane;  // photo spacing per lane
    MissionPlan areaWide; // every lane at the area's lowest height above ground
    geo::LocalFrame frame;
};

Pair planBoth(PlannerKind planner, const terrain::test::HeightFn& fn, const std::string& file) {
    Mission m = fieldMission(planner);
    m.terrain.demPath = tmp(file);
    auto geom = localGeometry(m);
    EXPECT_TRUE(geom.ok());
    terrain::test::DemSpec spec;
    spec.boxMin = {-260, -220};
    spec.boxMax = {260, 220};
    spec.marginM = 60;
    EXPECT_EQ(terrain::test::writeDem(m.terrain.demPath, geom->frame, fn, spec), "");
    auto t = loadMissionTerrain(m, *geom);
    EXPECT_TRUE(t.ok()) << t.error().message;
    auto areaWide = std::make_shared<MissionTerrain>(**t);
    areaWide->spacingPerLane = false;
    auto a =
        planMission(planningMission(m, *t)); // the terrain read: planned as planMission(m) plans it
    auto b = planMission(planningMission(m, areaWide));
    EXPECT_TRUE(a.ok()) << a.error().message;
    EXPECT_TRUE(b.ok()) << b.error().message;
    return {m, std::move(*a), std::move(*b), geom->frame};
}

int photosOf(const MissionPlan& p) {
    int n = 0;
    for (const auto& w : p.aircraft[0].route.waypoints)
        n += w.kind == route::WaypointKind::Photo;
    return n;
}

struct Measured {
    double worstFront = 1.0;
    int fronts = 0;
    double worstGsd = 0.0;
    double longestGapM = 0.0;
};

// Front overlap of every pair of consecutive photos of one lane (same heading, on one line,
// whatever waypoints terrain following inserted between them), and the GSD of every photo.
Measured measure(const Mission& mission, const MissionPlan& plan, const terrain::test::HeightFn& fn,
                 std::size_t k = 0) {
    const geo::LocalFrame& frame = *plan.frame;
    const AircraftConfig& a = mission.aircraft[k];
    const AircraftPlan& ap = plan.aircraft[k];
    const double home = *ap.route.homeElevationM;
    const double H = ap.terrain.heightAboveGroundM;
    const double target = *sensor::gsdCmAt(a.camera, H);
    const double tanAcross = std::tan(sensor::horizontalFovDeg(a.camera) * M_PI / 360.0);
    const double tanAlong = std::tan(sensor::verticalFovDeg(a.camera) * M_PI / 360.0);
    const double maxGap = sensor::effectiveFootprint(a.camera, H, a.overlap)->alongM * 1.001;
    struct Photo {
        geo::Vec2 pos;
        double heading;
        geo::Ring ring;
    };
    std::vector<Photo> photos;
    Measured out;
    for (const auto& w : ap.route.waypoints) {
        if (w.kind != route::WaypointKind::Photo)
            continue;
        const geo::Vec2 p = frame.toLocal(w.position);
        const double agl = home + w.altitudeM - fn(p);
        out.worstGsd =
            std::max(out.worstGsd, std::fabs(*sensor::gsdCmAt(a.camera, agl) / target - 1.0));
        const terrain::NadirCamera cam{p, home + w.altitudeM, w.headingDeg, tanAcross, tanAlong};
        photos.push_back({p, w.headingDeg, terrain::footprintOnTerrain(*plan.terrain, cam, 8)});
    }
    for (std::size_t k = 0; k + 1 < photos.size(); ++k) {
        const Photo& p = photos[k];
        const Photo& q = photos[k + 1];
        const double hd = p.heading * M_PI / 180.0;
        const geo::Vec2 ahead(std::sin(hd), std::cos(hd));
        const geo::Vec2 d = q.pos - p.pos;
        const double across = std::fabs(d.x() * ahead.y() - d.y() * ahead.x());
        if (std::fabs(std::remainder(q.heading - p.heading, 360.0)) > 1.0 || across > 0.5 ||
            d.dot(ahead) < 0.05 || d.norm() > maxGap)
            continue; // not the next photo of the same lane
        out.worstFront = std::min(out.worstFront, overlapAlong(p.ring, q.ring, p.pos, q.pos));
        out.longestGapM = std::max(out.longestGapM, d.norm());
        ++out.fronts;
    }
    return out;
}

// The Gaussian hill of 40 m of the terrain stage's targets, off the field's centre.
const terrain::test::HeightFn kHill =
    terrain::test::slopeAndHill(100.0, 0.0, 40.0, geo::Vec2(20, -10), 45.0);

void checkHill(PlannerKind planner, bool coverageTarget = true) {
    SCOPED_TRACE(plannerKindInfo(planner).id);
    const Pair pr =
        planBoth(planner, kHill, std::string("hill_") + plannerKindInfo(planner).id + ".tif");
    const AircraftPlan& ap = pr.perLane.aircraft[0];
    const int perLane = photosOf(pr.perLane), areaWide = photosOf(pr.areaWide);
    // (1) Fewer photos: lanes over the plain away from the hill space theirs for the full 40 m.
    EXPECT_LT(perLane, areaWide);
    EXPECT_LT(perLane, 0.9 * areaWide) << perLane << " against " << areaWide;
    EXPECT_GT(ap.terrain.lanesRespaced, 0);
    EXPECT_GT(ap.terrain.photosSavedPerLane, 0);
    EXPECT_EQ(pr.areaWide.aircraft[0].terrain.lanesRespaced, 0);
    // (2) Front overlap on the terrain never below the setting on any lane, and the lanes now wider
    // apart than the area-wide spacing somewhere.
    const Measured m = measure(pr.mission, pr.perLane, kHill);
    const Measured ref = measure(pr.mission, pr.areaWide, kHill);
    EXPECT_GT(m.fronts, 20);
    EXPECT_GE(m.worstFront, pr.mission.aircraft[0].overlap.front - 0.005)
        << "front overlap on the terrain";
    EXPECT_GT(m.longestGapM, ref.longestGapM + 1.0);
    // (3) GSD of every photo within 2 % of the target, the coverage check passing as before, no
    // margin breached.
    EXPECT_LT(m.worstGsd, 0.02);
    if (coverageTarget) {
        EXPECT_GE(pr.perLane.coverageRatio, 0.995);
    }
    EXPECT_GE(pr.perLane.coverageRatio, pr.areaWide.coverageRatio - 0.002);
    if (planner != PlannerKind::Lawnmower) {
        EXPECT_EQ(pr.perLane.noFlyViolations, 0);
    }
    // The time does not grow (the same lines, fewer photos).
    EXPECT_LE(ap.timeS, pr.areaWide.aircraft[0].timeS * 1.01);
}

TEST(TerrainLaneSpacing, HillStride) {
    checkHill(PlannerKind::Stride);
}
TEST(TerrainLaneSpacing, HillSweep) {
    checkHill(PlannerKind::Sweep);
}
TEST(TerrainLaneSpacing, HillRaster) {
    checkHill(PlannerKind::Raster);
}
TEST(TerrainLaneSpacing, HillWavefront) {
    checkHill(PlannerKind::Wavefront);
}
TEST(TerrainLaneSpacing, HillLawnmower) {
    checkHill(PlannerKind::Lawnmower, false);
}
TEST(TerrainLaneSpacing, HillAuto) {
    checkHill(PlannerKind::Auto);
}

TEST(TerrainLaneSpacing, SlopeKeepsTheFrontOverlap) {
    // A plane at 15 %: every lane sees the same rise, so per-lane spacing saves little; the overlap
    // holds.
    const auto fn = terrain::test::slopeAndHill(100.0, 0.15, 0.0, geo::Vec2(0, 0), 50.0);
    const Pair pr = planBoth(PlannerKind::Stride, fn, "slope.tif");
    EXPECT_LE(photosOf(pr.perLane), photosOf(pr.areaWide));
    const Measured m = measure(pr.mission, pr.perLane, fn);
    EXPECT_GT(m.fronts, 20);
    EXPECT_GE(m.worstFront, pr.mission.aircraft[0].overlap.front - 0.005);
    EXPECT_LT(m.worstGsd, 0.02);
    EXPECT_GE(pr.perLane.coverageRatio, 0.995);
}

TEST(TerrainLaneSpacing, DemoMissionTakesFewerPhotosWithTheOverlapKept) {
    // The demo mission over the synthetic demo DEM (a hill and a valley), two aircraft, automatic
    // choice.
    if (demoDemPath().empty())
        GTEST_SKIP() << "the demo DEM is not built";
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission_terrain.json");
    ASSERT_TRUE(m.ok()) << m.error().message;
    auto geom = localGeometry(*m);
    ASSERT_TRUE(geom.ok());
    auto t = loadMissionTerrain(*m, *geom);
    ASSERT_TRUE(t.ok()) << t.error().message;
    auto off = std::make_shared<MissionTerrain>(**t);
    off->spacingPerLane = false;
    auto perLane = planMission(planningMission(*m, *t));
    auto areaWide = planMission(planningMission(*m, off));
    ASSERT_TRUE(perLane.ok()) << perLane.error().message;
    ASSERT_TRUE(areaWide.ok()) << areaWide.error().message;
    const terrain::HeightGrid& grid = *perLane->terrain;
    const terrain::test::HeightFn ground = [&grid](const geo::Vec2& p) {
        return grid.heightOr(p, 0.0);
    };
    EXPECT_LT(perLane->totals.photos, areaWide->totals.photos);
    for (std::size_t k = 0; k < m->aircraft.size(); ++k) {
        SCOPED_TRACE(m->aircraft[k].name);
        const Measured r = measure(*m, *perLane, ground, k);
        EXPECT_GT(r.fronts, 100);
        EXPECT_GE(r.worstFront, m->aircraft[k].overlap.front - 0.005);
        EXPECT_LT(r.worstGsd, 0.02);
        EXPECT_LE(perLane->aircraft[k].timeS, areaWide->aircraft[k].timeS * 1.01);
    }
    EXPECT_GE(perLane->coverageRatio, 0.995);
    EXPECT_EQ(perLane->noFlyViolations, 0);
}

TEST(TerrainLaneSpacing, FlatGroundPlansAsBefore) {
    // (4) On flat ground every lane's lowest height above ground is the area's: the plan is the one
    // without per-lane spacing, and the one without terrain at the same height.
    const auto flat = terrain::test::slopeAndHill(100.0, 0.0, 0.0, geo::Vec2(0, 0), 50.0);
    for (PlannerKind planner : {PlannerKind::Stride, PlannerKind::Sweep, PlannerKind::Lawnmower}) {
        SCOPED_TRACE(plannerKindInfo(planner).id);
        const Pair pr =
            planBoth(planner, flat, std::string("flat_") + plannerKindInfo(planner).id + ".tif");
        Mission off = pr.mission;
        off.terrain.mode = TerrainMode::Off;
        auto noTerrain = planMission(off);
        ASSERT_TRUE(noTerrain.ok()) << noTerrain.error().message;
        const auto& a = pr.perLane.aircraft[0].route.waypoints;
        EXPECT_EQ(pr.perLane.aircraft[0].terrain.lanesRespaced, 0);
        const std::vector<route::Waypoint>* others[] = {&pr.areaWide.aircraft[0].route.waypoints,
                                                        &noTerrain->aircraft[0].route.waypoints};
        for (const auto* other : others) {
            ASSERT_EQ(a.size(), other->size());
            for (std::size_t i = 0; i < a.size(); ++i) {
                EXPECT_NEAR(a[i].position.lon, (*other)[i].position.lon, 1e-9);
                EXPECT_NEAR(a[i].position.lat, (*other)[i].position.lat, 1e-9);
                EXPECT_EQ(a[i].kind, (*other)[i].kind);
                EXPECT_EQ(a[i].headingDeg, (*other)[i].headingDeg);
            }
        }
        EXPECT_EQ(pr.perLane.coverageRatio, pr.areaWide.coverageRatio);
        EXPECT_EQ(pr.perLane.aircraft[0].timeS, pr.areaWide.aircraft[0].timeS);
    }
}

} // namespace
} // namespace pf::mission
