#include "core/mission/terrain_stage.h"

#include "core/data_dir.h"
#include "core/geo/polygon_ops.h"
#include "core/mission/aircraft_naming.h"
#include "core/route/terrain_follow.h"
#include "core/sensor/camera.h"
#include "core/terrain/terrain_footprint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace pf::mission {

namespace {

std::string fmt(double v, int decimals = 1) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string label(const AircraftConfig& a) {
    return aircraftLabel(a.name);
}

bool exists(const std::string& p) {
    std::error_code ec;
    return !p.empty() && std::filesystem::is_regular_file(p, ec);
}

// A small square around a point, so that the DEM read covers it.
geo::Polygon around(const geo::Vec2& p, double r = 1.0) {
    return {{p + geo::Vec2(-r, -r), p + geo::Vec2(r, -r), p + geo::Vec2(r, r), p + geo::Vec2(-r, r)}, {}};
}

} // namespace

std::string locateDem(const std::string& path) {
    if (path.empty() || exists(path))
        return path;
    const std::string name = std::filesystem::path(path).filename().string();
    std::vector<std::string> dirs;
    if (const std::string data = pf::dataDirectory(); !data.empty())
        dirs.push_back(data + "/maps");
#ifdef PF_BUILD_MAPS_DIR
    dirs.emplace_back(PF_BUILD_MAPS_DIR);
#endif
    for (const auto& d : dirs)
        if (exists(d + "/" + name))
            return d + "/" + name;
    return path;
}

std::string demoDemPath() {
    const std::string p = locateDem("demo_dem.tif");
    return exists(p) ? p : std::string();
}

Result<std::shared_ptr<const MissionTerrain>> loadMissionTerrain(const Mission& m, const LocalGeometry& geom) {
    const TerrainOptions& opt = m.terrain;
    if (opt.demPath.empty())
        return makeError(ErrorCode::InvalidInput,
                         "terrain following needs a terrain model (DEM): give one with --dem FILE or File > Terrain model");
    if (!(opt.minClearanceM >= 0) || !std::isfinite(opt.minClearanceM))
        return makeError(ErrorCode::InvalidInput, "the minimum clearance must be a number of metres, 0 or more");
    auto dem = terrain::Dem::open(locateDem(opt.demPath));
    if (!dem)
        return dem.error();
    auto t = std::make_shared<MissionTerrain>();
    t->info = dem->info();
    const geo::LocalFrame& frame = geom.frame;
    // Heights above ground, footprint reach (the margin read around the area).
    double reach = 0.0;
    for (const auto& a : m.aircraft) {
        auto h = resolvedAltitude(a);
        if (!h)
            return makeError(h.error().code, label(a) + ": " + h.error().message);
        if (opt.minClearanceM > *h)
            return makeError(ErrorCode::InvalidInput,
                             label(a) + ": the minimum clearance of " + fmt(opt.minClearanceM) +
                                 " m is more than its height above ground of " + fmt(*h) +
                                 " m: its photos would be too close to the ground");
        t->heightAboveGroundM.push_back(*h);
        if (auto f = sensor::footprintAt(a.camera, *h))
            reach = std::max(reach, 0.5 * std::hypot(f->longSideM, f->shortSideM));
    }
    // Every take-off and landing point needs its ground: the DEM's, or the height given for the home.
    geo::MultiPolygon region{geom.area};
    auto needPoint = [&](const geo::LonLat& p, const std::string& what, bool given) -> Status {
        const geo::Vec2 q = frame.toLocal(p);
        auto one = dem->resample(frame.projString(), q.x(), q.y(), 1.0, 1, 1);
        if (one && one->heightAt(q)) {
            region.push_back(around(q));
            return {};
        }
        if (given)
            return {};
        char buf[96];
        std::snprintf(buf, sizeof buf, "%.6f, %.6f", p.lon, p.lat);
        return makeError(ErrorCode::InvalidInput,
                         "the terrain model \"" + opt.demPath + "\" has no height at " + what + " (" + buf +
                             "): use a DEM that covers it" +
                             (what == "the take-off point" ? std::string(" or give its elevation (--home-elevation)") : ""));
    };
    if (m.home)
        if (auto s = needPoint(*m.home, "the take-off point", opt.homeElevationM.has_value()); !s)
            return s.error();
    for (const auto& a : m.aircraft)
        if (a.home)
            if (auto s = needPoint(*a.home, "the take-off point of " + label(a), false); !s)
                return s.error();
    if (m.landing)
        if (auto s = needPoint(*m.landing, "the landing point", true); !s)
            return s.error();
    auto grid = dem->overRegion(frame, region, reach + 10.0);
    if (!grid)
        return grid.error();
    auto shared = std::make_shared<terrain::HeightGrid>(std::move(*grid));
    t->grid = shared;
    if (opt.homeElevationM)
        t->homeGroundM = *opt.homeElevationM;
    else if (m.home)
        t->homeGroundM = shared->heightAt(frame.toLocal(*m.home));

    // The lowest height above ground each camera sees over the area (the rises shared between
    // aircraft whose footprints reach as far).
    const geo::MultiPolygon area{geom.area};
    std::vector<double> radii;
    for (std::size_t k = 0; k < m.aircraft.size(); ++k) {
        const double h = t->heightAboveGroundM[k];
        auto f = sensor::footprintAt(m.aircraft[k].camera, h);
        const double r = f ? 0.5 * std::hypot(f->longSideM, f->shortSideM) : 0.0;
        const auto same = std::find(radii.begin(), radii.end(), r);
        if (same == radii.end())
            t->riseM.push_back(std::make_shared<const terrain::HeightGrid>(terrain::riseWithin(*shared, r)));
        else
            t->riseM.push_back(t->riseM[static_cast<std::size_t>(same - radii.begin())]);
        radii.push_back(r);
        const double rise =
            terrain::maxRiseWithin(*t->riseM.back(), [&](const geo::Vec2& p) { return geo::contains(area, p); });
        if (rise > 0.8 * h)
            return makeError(ErrorCode::InvalidInput,
                             label(m.aircraft[k]) + ": the ground rises by " + fmt(rise) + " m within the view of its camera at " +
                                 fmt(h) + " m above ground: no photo spacing keeps the overlap; fly higher");
        t->planningHeightM.push_back(h - rise);
    }
    return std::shared_ptr<const MissionTerrain>(std::move(t));
}

Mission planningMission(const Mission& m, std::shared_ptr<const MissionTerrain> t) {
    Mission p = m;
    for (std::size_t k = 0; k < p.aircraft.size() && k < t->planningHeightM.size(); ++k) {
        p.aircraft[k].altitudeM = t->planningHeightM[k];
        p.aircraft[k].gsdCm.reset();
    }
    p.terrain.prepared = std::move(t);
    return p;
}

route::LaneSpacingFn laneSpacing(const Mission& m, std::size_t k) {
    const std::shared_ptr<const MissionTerrain>& t = m.terrain.prepared;
    if (!t || !t->spacingPerLane || k >= m.aircraft.size() || k >= t->riseM.size() || !t->riseM[k])
        return {};
    const std::shared_ptr<const terrain::HeightGrid> rises = t->riseM[k];
    const double H = t->heightAboveGroundM[k];
    const sensor::Camera camera = m.aircraft[k].camera;
    const sensor::Overlap overlap = m.aircraft[k].overlap;
    return [rises, H, camera, overlap](const geo::Vec2& a, const geo::Vec2& b) {
        const double h = H - terrain::maxRiseAlong(*rises, a, b);
        if (!(h > 0))
            return 0.0;
        auto f = sensor::effectiveFootprint(camera, h, overlap);
        return f ? f->alongM : 0.0;
    };
}

bool needsTerrainStage(const Mission& m) { return m.terrain.follows() && !m.terrain.prepared; }

Result<MissionPlan> planOverTerrain(const Mission& m,
                                    const std::function<Result<MissionPlan>(const Mission&)>& plan) {
    if (m.aircraft.empty())
        return makeError(ErrorCode::InvalidInput, "the mission has no aircraft: add one to plan a flight");
    auto geom = localGeometry(m);
    if (!geom)
        return geom.error();
    auto terrain = loadMissionTerrain(m, *geom);
    if (!terrain)
        return terrain.error();
    return plan(planningMission(m, *terrain));
}

Status applyTerrain(MissionPlan& plan, const Mission& m, const geo::LocalFrame& frame,
                    const std::vector<std::optional<geo::Vec2>>& homes, const std::optional<geo::Vec2>& landing,
                    std::vector<plan::PhotoFootprint>& footprints, std::vector<geo::Ring>& outlines) {
    if (!m.terrain.prepared)
        return makeError(ErrorCode::Internal, "terrain following without a terrain model read");
    const MissionTerrain& t = *m.terrain.prepared;
    const terrain::HeightGrid& grid = *t.grid;
    footprints.clear();
    outlines.clear();
    plan.terrain = t.grid;
    for (std::size_t k = 0; k < plan.aircraft.size(); ++k) {
        AircraftPlan& ap = plan.aircraft[k];
        const AircraftConfig& cfg = m.aircraft[k];
        const std::string who = label(cfg);
        const double H = t.heightAboveGroundM[k];
        // The take-off point's ground: the mission's home (given or from the DEM), else the aircraft's own.
        double homeGround = 0.0;
        if (homes[k]) {
            const bool own = cfg.home && cfg.home != m.home;
            if (!own && t.homeGroundM)
                homeGround = *t.homeGroundM;
            else if (auto g = grid.heightAt(*homes[k]))
                homeGround = *g;
        } else if (!ap.localWaypoints.empty()) {
            homeGround = grid.heightOr(ap.localWaypoints.front().pos, 0.0); // no home: heights above the first waypoint's ground
        }
        std::vector<std::pair<int, int>> ranges;
        for (const auto& s : ap.sorties)
            ranges.push_back({s.firstWaypoint, s.lastWaypoint});
        route::TerrainFollowOptions fo;
        fo.heightAboveGroundM = H;
        fo.minClearanceM = m.terrain.minClearanceM;
        fo.homeGroundM = homeGround;
        const bool landsElsewhere = landing && homes[k] && ap.sorties.size() == 1;
        auto res = route::followTerrain(ap.localWaypoints, ranges, homes[k], grid, fo,
                                        landsElsewhere ? landing : std::nullopt);
        if (!res)
            return makeError(res.error().code, who + ": " + res.error().message);
        for (const auto& w : res->warnings)
            plan.warnings.push_back(who + ": " + w);

        // Sortie and flight times with the 3D legs (the climb at take-off and the descent at home are
        // vertical and, as without terrain, not counted).
        const plan::FlightTimeModel model = flightModel(cfg);
        const double budgetS = cfg.enduranceMin * 60.0 * (1.0 - m.options.batteryReserve);
        ap.localWaypoints = res->waypoints;
        ap.timeS = 0.0;
        ap.flightDistanceM = 0.0;
        std::vector<geo::Vec2> all;
        std::vector<double> allZ;
        for (std::size_t s = 0; s < ap.sorties.size(); ++s) {
            SortieSummary& sum = ap.sorties[s];
            sum.firstWaypoint = res->sorties[s].first;
            sum.lastWaypoint = res->sorties[s].second;
            std::vector<geo::Vec2> poly;
            std::vector<double> z;
            const auto f = static_cast<std::size_t>(sum.firstWaypoint), l = static_cast<std::size_t>(sum.lastWaypoint);
            if (homes[k]) {
                poly.push_back(*homes[k]);
                z.push_back(res->altitudeM[f]);
            }
            for (std::size_t i = f; i <= l; ++i) {
                poly.push_back(res->waypoints[i].pos);
                z.push_back(res->altitudeM[i]);
            }
            if (homes[k]) {
                poly.push_back(landsElsewhere ? *landing : *homes[k]);
                z.push_back(res->altitudeM[l]);
            }
            const plan::FlightTime ft = plan::flightTime(poly, z, model);
            sum.lengthM = ft.lengthM;
            sum.timeS = ft.totalS + sum.photos * model.photoDwellS;
            if (sum.timeS > budgetS + 1e-6)
                plan.warnings.push_back(who + ": sortie " + std::to_string(s + 1) + " needs " + fmt(sum.timeS / 60.0) +
                                        " min with its climbs over the terrain, more than the " + fmt(budgetS / 60.0) +
                                        " min of one battery");
            ap.timeS += sum.timeS;
            ap.flightDistanceM += sum.lengthM;
            all.insert(all.end(), poly.begin(), poly.end());
            allZ.insert(allZ.end(), z.begin(), z.end());
        }
        ap.flight = plan::flightTime(all, allZ, model);

        // The routes: altitudes above the take-off point, the ground under each waypoint.
        ap.route.homeElevationM = homeGround;
        ap.route.waypoints.clear();
        for (std::size_t i = 0; i < res->waypoints.size(); ++i) {
            const auto& w = res->waypoints[i];
            route::Waypoint rw{frame.toGeo(w.pos), res->altitudeM[i] - homeGround, w.headingDeg, w.kind, res->groundM[i]};
            ap.route.waypoints.push_back(rw);
        }
        ap.sortieRoutes.clear();
        for (const auto& s : ap.sorties) {
            route::Route r = ap.route;
            r.waypoints.assign(ap.route.waypoints.begin() + s.firstWaypoint, ap.route.waypoints.begin() + s.lastWaypoint + 1);
            ap.sortieRoutes.push_back(std::move(r));
        }

        // Footprints on the terrain, and the resolution each photo gets.
        TerrainSummary& ts = ap.terrain;
        ts.active = true;
        ts.heightAboveGroundM = H;
        ts.planningHeightM = t.planningHeightM[k];
        ts.homeGroundM = homeGround;
        ts.lowestClearanceM = std::isfinite(res->lowestClearanceM) ? res->lowestClearanceM : H;
        ts.waypointsInserted = res->insertedCount;
        ts.gsdCm = sensor::gsdCmAt(cfg.camera, H).ok() ? *sensor::gsdCmAt(cfg.camera, H) : 0.0;
        const double tanAcross = std::tan(sensor::horizontalFovDeg(cfg.camera) * M_PI / 360.0);
        const double tanAlong = std::tan(sensor::verticalFovDeg(cfg.camera) * M_PI / 360.0);
        double farthest = H;
        int coarse = 0;
        for (std::size_t i = 0; i < res->waypoints.size(); ++i) {
            const auto& w = res->waypoints[i];
            if (w.kind != route::WaypointKind::Photo)
                continue;
            const terrain::NadirCamera cam{w.pos, res->altitudeM[i], w.headingDeg, tanAcross, tanAlong};
            footprints.push_back({w.pos, w.headingDeg, ap.footprint.real.longSideM, ap.footprint.real.shortSideM});
            outlines.push_back(terrain::footprintOnTerrain(grid, cam));
            double far = H;
            for (const auto& q : outlines.back())
                far = std::max(far, res->altitudeM[i] - grid.heightOr(q, res->groundM[i]));
            farthest = std::max(farthest, far);
            coarse += far > 1.25 * H;
        }
        ts.coarsestGsdCm = ts.gsdCm * farthest / H;
        if (coarse > 0)
            plan.warnings.push_back(who + ": " + std::to_string(coarse) +
                                    " photo(s) see ground more than 25 % farther than their height above ground at their "
                                    "edges (down a slope or off a ridge): resolution there down to " +
                                    fmt(ts.coarsestGsdCm, 2) + " cm/px for " + fmt(ts.gsdCm, 2) + " cm/px");
        ap.altitudeM = H;
    }
    return {};
}

} // namespace pf::mission
