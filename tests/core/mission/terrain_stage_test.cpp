// Terrain following end to end (issue 18's targets) on synthetic DEMs written through GDAL: a plane
// at 15 % slope and a Gaussian hill of 40 m. GSD of every photo within 2 % of the target, side and
// front overlap from the footprints on the terrain never below the setting, no leg closer to the
// ground than the clearance (sampled every metre), and the DEM's errors.
#include "core/mission/plan_mission.h"
#include "core/mission/terrain_stage.h"
#include "core/mission/validation.h"
#include "core/geo/polygon_ops.h"
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
    const auto dir = std::filesystem::temp_directory_path() / "pf_terrain_stage_test";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

// A 360 x 260 m field, one aircraft with a 60 x 45 degree camera at 40 m above the ground.
Mission fieldMission(double altitudeM = 40.0) {
    const auto f = *geo::LocalFrame::create(kOrigin);
    Mission m;
    m.name = "terrain field";
    for (const geo::Vec2& p : {geo::Vec2(-180, -130), geo::Vec2(180, -130), geo::Vec2(180, 130), geo::Vec2(-180, 130)})
        m.area.outer.push_back(f.toGeo(p));
    m.home = f.toGeo(geo::Vec2(-200, -150));
    AircraftConfig a;
    a.name = "Quad";
    a.model = "custom";
    a.camera.name = "60x45";
    a.camera.hfovDeg = 60.0;
    a.camera.vfovDeg = 45.0;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = altitudeM;
    a.overlap = {0.7, 0.6};
    a.enduranceMin = 60.0;
    m.aircraft.push_back(a);
    m.options.planner = PlannerKind::Stride;
    m.options.gridAngleDeg = 0.0;
    m.terrain.mode = TerrainMode::Follow;
    m.terrain.minClearanceM = 15.0;
    return m;
}

struct Planned {
    Mission mission;
    MissionPlan plan;
    geo::LocalFrame frame;
};

Planned planOver(const terrain::test::HeightFn& fn, const std::string& file) {
    Mission m = fieldMission();
    m.terrain.demPath = tmp(file);
    auto geom = localGeometry(m);
    EXPECT_TRUE(geom.ok());
    terrain::test::DemSpec spec;
    spec.boxMin = {-260, -220};
    spec.boxMax = {260, 220};
    spec.marginM = 60;
    EXPECT_EQ(terrain::test::writeDem(m.terrain.demPath, geom->frame, fn, spec), "");
    auto plan = planMission(m);
    EXPECT_TRUE(plan.ok()) << plan.error().message;
    return {m, std::move(*plan), geom->frame};
}

void checkTargets(const Planned& pl, const terrain::test::HeightFn& fn) {
    const AircraftConfig& a = pl.mission.aircraft[0];
    const AircraftPlan& ap = pl.plan.aircraft[0];
    ASSERT_TRUE(ap.terrain.active);
    ASSERT_TRUE(ap.route.hasTerrain());
    const double home = *ap.route.homeElevationM;
    EXPECT_NEAR(home, fn(pl.frame.toLocal(*pl.mission.home)), 0.1);
    const double H = *a.altitudeM;
    const double target = *sensor::gsdCmAt(a.camera, H);
    const double tanAcross = std::tan(sensor::horizontalFovDeg(a.camera) * M_PI / 360.0);
    const double tanAlong = std::tan(sensor::verticalFovDeg(a.camera) * M_PI / 360.0);

    // Photos: GSD from the true ground under each, footprints on the terrain.
    struct Photo {
        geo::Vec2 pos;
        double heading;
        geo::Ring ring;
        std::size_t index;
    };
    std::vector<Photo> photos;
    const auto& grid = *pl.plan.terrain;
    double worstGsd = 0.0;
    for (std::size_t i = 0; i < ap.route.waypoints.size(); ++i) {
        const auto& w = ap.route.waypoints[i];
        if (w.kind != route::WaypointKind::Photo)
            continue;
        const geo::Vec2 p = pl.frame.toLocal(w.position);
        const double agl = home + w.altitudeM - fn(p);
        worstGsd = std::max(worstGsd, std::fabs(*sensor::gsdCmAt(a.camera, agl) / target - 1.0));
        const terrain::NadirCamera cam{p, home + w.altitudeM, w.headingDeg, tanAcross, tanAlong};
        photos.push_back({p, w.headingDeg, terrain::footprintOnTerrain(grid, cam, 8), i});
    }
    ASSERT_GT(photos.size(), 20u);
    EXPECT_LT(worstGsd, 0.02) << "GSD off the target by up to " << 100 * worstGsd << " %";

    // Front overlap: consecutive photos of one lane. Side overlap: each photo and the nearest photo
    // of the next lane beside it.
    const double trackSpacing = ap.footprint.acrossM;
    double worstFront = 1.0, worstSide = 1.0;
    int fronts = 0, sides = 0;
    for (std::size_t k = 0; k + 1 < photos.size(); ++k) {
        const auto& p = photos[k];
        const auto& q = photos[k + 1];
        if (q.index == p.index + 1 && std::fabs(q.heading - p.heading) < 1.0) {
            worstFront = std::min(worstFront, overlapAlong(p.ring, q.ring, p.pos, q.pos));
            ++fronts;
        }
        const double hd = p.heading * M_PI / 180.0;
        const geo::Vec2 ahead(std::sin(hd), std::cos(hd));
        const Photo* best = nullptr;
        double bestD = 1e9;
        for (const auto& o : photos) {
            const geo::Vec2 d = o.pos - p.pos;
            const double along = d.dot(ahead), across = std::fabs(d.x() * ahead.y() - d.y() * ahead.x());
            if (across < 0.5 * trackSpacing || across > 1.5 * trackSpacing || std::fabs(along) > 0.3 * trackSpacing)
                continue;
            if (d.norm() < bestD) {
                bestD = d.norm();
                best = &o;
            }
        }
        if (best) {
            // Across the track only: the line through the two centres, straightened across.
            const geo::Vec2 right(ahead.y(), -ahead.x());
            const double side = (best->pos - p.pos).dot(right) > 0 ? 1.0 : -1.0;
            worstSide = std::min(worstSide, overlapAlong(p.ring, best->ring, p.pos, p.pos + right * side));
            ++sides;
        }
    }
    EXPECT_GT(fronts, 10);
    EXPECT_GT(sides, 10);
    EXPECT_GE(worstFront, a.overlap.front - 0.005) << "front overlap on the terrain";
    EXPECT_GE(worstSide, a.overlap.side - 0.005) << "side overlap on the terrain";

    // Clearance along every leg, every metre: straight between the waypoints' altitudes, level at
    // the first altitude out of home and at the last back home (the model of route::followTerrain).
    std::vector<geo::Vec2> pos{pl.frame.toLocal(*pl.mission.home)};
    std::vector<double> z{home + ap.route.waypoints.front().altitudeM};
    for (const auto& w : ap.route.waypoints) {
        pos.push_back(pl.frame.toLocal(w.position));
        z.push_back(home + w.altitudeM);
    }
    pos.push_back(pos.front());
    z.push_back(z.back());
    double lowest = 1e9;
    for (std::size_t i = 0; i + 1 < pos.size(); ++i) {
        const double len = (pos[i + 1] - pos[i]).norm();
        for (double s = (i == 0 ? 1.0 : 0.0); s <= len - (i + 2 == pos.size() ? 1.0 : 0.0); s += 1.0) {
            const double t = len > 0 ? s / len : 0.0;
            lowest = std::min(lowest, z[i] + (z[i + 1] - z[i]) * t - fn(pos[i] + (pos[i + 1] - pos[i]) * t));
        }
    }
    EXPECT_GE(lowest, pl.mission.terrain.minClearanceM - 0.2);
    EXPECT_NEAR(ap.terrain.lowestClearanceM, lowest, 0.5);
    // Coverage with the footprints on the terrain.
    EXPECT_GE(pl.plan.coverageRatio, 0.995);
}

TEST(TerrainStage, PlaneAtFifteenPercentKeepsGsdOverlapAndClearance) {
    const auto fn = terrain::test::slopeAndHill(100.0, 0.15, 0.0, geo::Vec2(0, 0), 50.0);
    const Planned pl = planOver(fn, "slope.tif");
    checkTargets(pl, fn);
    // 15 % over 360 m: the photos climb 54 m from west to east.
    const auto& wps = pl.plan.aircraft[0].route.waypoints;
    double lo = 1e9, hi = -1e9;
    for (const auto& w : wps) {
        lo = std::min(lo, w.altitudeM);
        hi = std::max(hi, w.altitudeM);
    }
    EXPECT_GT(hi - lo, 45.0);
}

TEST(TerrainStage, GaussianHillKeepsGsdOverlapAndClearanceAndInsertsWaypoints) {
    const auto fn = terrain::test::slopeAndHill(100.0, 0.0, 40.0, geo::Vec2(20, -10), 45.0);
    const Planned pl = planOver(fn, "hill.tif");
    checkTargets(pl, fn);
    const auto& t = pl.plan.aircraft[0].terrain;
    EXPECT_LT(t.planningHeightM, t.heightAboveGroundM); // denser lanes where the hill comes closer
    EXPECT_NEAR(t.gsdCm, *sensor::gsdCmAt(pl.mission.aircraft[0].camera, 40.0), 1e-9);
}

TEST(TerrainStage, FlatPlanIsUnchangedWithTerrainOff) {
    Mission m = fieldMission();
    m.terrain.mode = TerrainMode::Off;
    m.terrain.demPath = tmp("does_not_exist.tif"); // not read when off
    auto plan = planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    EXPECT_FALSE(plan->aircraft[0].terrain.active);
    EXPECT_FALSE(plan->aircraft[0].route.hasTerrain());
    for (const auto& w : plan->aircraft[0].route.waypoints)
        EXPECT_EQ(w.altitudeM, 40.0);
}

TEST(TerrainStage, DemErrorsAreBadInputNamingTheProblem) {
    const auto fn = terrain::test::slopeAndHill(100.0, 0.05, 0.0, geo::Vec2(0, 0), 50.0);
    Mission m = fieldMission();
    auto geom = localGeometry(m);
    ASSERT_TRUE(geom.ok());
    // Covers only the western half of the field.
    terrain::test::DemSpec half;
    half.boxMin = {-260, -220};
    half.boxMax = {0, 220};
    half.marginM = 0;
    m.terrain.demPath = tmp("half.tif");
    ASSERT_EQ(terrain::test::writeDem(m.terrain.demPath, geom->frame, fn, half), "");
    auto p = planMission(m);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(p.error().message.find("does not cover the whole area: its east part"), std::string::npos)
        << p.error().message;

    terrain::test::DemSpec none;
    none.boxMin = {-260, -220};
    none.boxMax = {260, 220};
    none.allNoData = true;
    m.terrain.demPath = tmp("none.tif");
    ASSERT_EQ(terrain::test::writeDem(m.terrain.demPath, geom->frame, fn, none), "");
    p = planMission(m);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("no height at the take-off point"), std::string::npos) << p.error().message;
    m.terrain.homeElevationM = 100.0; // the take-off given: the area itself is all no-data
    p = planMission(m);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("every pixel there is no-data"), std::string::npos) << p.error().message;

    m.terrain.demPath = tmp("missing.tif");
    p = planMission(m);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("missing.tif\" cannot be read"), std::string::npos) << p.error().message;

    // A clearance above the height above ground cannot be kept.
    m.terrain.demPath = tmp("half.tif");
    m.terrain.minClearanceM = 50.0;
    p = planMission(m);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("minimum clearance of 50.0 m is more than its height above ground"),
              std::string::npos)
        << p.error().message;
}

} // namespace
} // namespace pf::mission
