#include "core/mission/plan_mission.h"

#include "core/mission/validation.h"
#include "core/plan/planner.h"
#include "core/route/photo_waypoints.h"

#include <cpl_json.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace pf::mission {

namespace {

plan::PlannerKind toPlanKind(PlannerKind k) {
    switch (k) {
    case PlannerKind::Stride:
        return plan::PlannerKind::Stride;
    case PlannerKind::Raster:
        return plan::PlannerKind::Raster;
    case PlannerKind::Wavefront:
        return plan::PlannerKind::Wavefront;
    }
    return plan::PlannerKind::Stride;
}

double normaliseAngle(double a) {
    a = std::fmod(a, 180.0);
    if (a < 0)
        a += 180.0;
    return a;
}

} // namespace

std::vector<double> candidateAngles(const geo::MultiPolygon& region) {
    std::vector<double> angles;
    for (int a = 0; a < 180; a += 5)
        angles.push_back(a);
    // The directions of the two longest edges: areas are often drawn along a road or a field's side.
    std::vector<std::pair<double, double>> edges; // length, angle
    for (const auto& poly : region) {
        const auto& r = poly.outer;
        for (std::size_t i = 0; i < r.size(); ++i) {
            const geo::Vec2 d = r[(i + 1) % r.size()] - r[i];
            edges.push_back({d.norm(), normaliseAngle(std::atan2(d.y(), d.x()) * 180.0 / M_PI)});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t i = 0; i < edges.size() && i < 2; ++i) {
        const double a = std::round(edges[i].second * 1000.0) / 1000.0;
        bool known = false;
        for (double b : angles)
            known = known || std::fabs(a - b) < 1e-6;
        if (!known)
            angles.push_back(a);
    }
    return angles;
}

Result<AircraftPlan> planRegion(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                                const AircraftConfig& aircraft, const PlannerOptions& options,
                                const geo::LocalFrame& frame, const std::optional<geo::Vec2>& home,
                                const std::optional<geo::Vec2>& landing) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::string who = aircraft.name.empty() ? std::string("the aircraft") : "aircraft \"" + aircraft.name + "\"";
    auto alt = resolvedAltitude(aircraft);
    if (!alt)
        return makeError(alt.error().code, who + ": " + alt.error().message);
    auto eff = sensor::effectiveFootprint(aircraft.camera, *alt, aircraft.overlap);
    if (!eff)
        return makeError(eff.error().code, who + ": " + eff.error().message);
    const double cell = sensor::cellSizeFor(*eff);

    const std::vector<double> angles =
        options.gridAngleDeg ? std::vector<double>{*options.gridAngleDeg} : candidateAngles(region);
    plan::PlanOptions popt;
    popt.kind = toPlanKind(options.planner);
    popt.wavefront.speedMps = aircraft.cruiseSpeedMps;
    popt.wavefront.turnRateDegS = aircraft.turnRateDegS;
    plan::MetricsOptions mopt;
    mopt.speedMps = aircraft.cruiseSpeedMps;
    mopt.turnRateDegS = aircraft.turnRateDegS;
    mopt.diagonalSteps = popt.kind == plan::PlannerKind::Wavefront && popt.wavefront.moore;
    mopt.turnLowerBound = false;

    std::optional<AircraftPlan> best;
    std::optional<Error> firstError;
    int tried = 0;
    for (double angle : angles) {
        grid::GridOptions gopt;
        gopt.cellSize = cell;
        gopt.angleDeg = angle;
        gopt.safetyMarginM = options.safetyMarginM;
        gopt.maxCells = options.maxCells;
        auto g = grid::Grid::build(region, noFly, gopt);
        if (!g) {
            if (!firstError)
                firstError = g.error();
            continue;
        }
        plan::CoverageRequest req;
        if (home) {
            req.takeoff = g->nearestVisitable(*home);
            req.landing = g->nearestVisitable(landing ? *landing : *home);
        }
        auto path = plan::planCoverage(*g, req, popt);
        if (!path) {
            if (!firstError)
                firstError = path.error();
            continue;
        }
        ++tried;
        plan::PathMetrics m = plan::computeMetrics(*g, *path, mopt);
        const bool better = !best || m.estimatedTimeS < best->metrics.estimatedTimeS - 1e-9 ||
                            (std::fabs(m.estimatedTimeS - best->metrics.estimatedTimeS) <= 1e-9 &&
                             m.turns < best->metrics.turns);
        if (!better)
            continue;
        AircraftPlan p;
        p.gridAngleDeg = angle;
        p.grid = std::move(*g);
        p.path = std::move(*path);
        p.metrics = m;
        best = std::move(p);
    }
    if (!best) {
        const Error e = firstError ? *firstError : makeError(ErrorCode::Internal, "no grid angle to try");
        return makeError(e.code, who + ": " + e.message);
    }
    AircraftPlan& p = *best;
    p.aircraft = aircraft.name;
    p.altitudeM = *alt;
    p.cellSizeM = cell;
    p.footprint = *eff;
    p.anglesTried = tried;
    mopt.turnLowerBound = true;
    p.metrics = plan::computeMetrics(p.grid, p.path, mopt);
    p.localWaypoints = route::photoWaypoints(p.grid, p.path, *eff);
    p.metrics.photos = static_cast<int>(std::count_if(p.localWaypoints.begin(), p.localWaypoints.end(), [](const auto& w) {
        return w.kind == route::WaypointKind::Photo;
    }));
    p.route.aircraft = aircraft.name;
    p.route.cruiseSpeedMps = aircraft.cruiseSpeedMps;
    if (home)
        p.route.home = frame.toGeo(*home);
    p.route.waypoints.reserve(p.localWaypoints.size());
    for (const auto& w : p.localWaypoints)
        p.route.waypoints.push_back({frame.toGeo(w.pos), *alt, w.headingDeg, w.kind});
    p.metrics.planningMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return std::move(p);
}

Result<MissionPlan> planMission(const Mission& m) {
    if (m.aircraft.empty())
        return makeError(ErrorCode::InvalidInput, "the mission has no aircraft: add one to plan a flight");
    auto geom = localGeometry(m);
    if (!geom)
        return geom.error();
    MissionPlan plan;
    plan.frame = geom->frame;
    const AircraftConfig& first = m.aircraft.front();
    std::optional<geo::LonLat> homeGeo = first.home ? first.home : m.home;
    std::optional<geo::Vec2> home, landing;
    if (homeGeo)
        home = geom->frame.toLocal(*homeGeo);
    if (m.landing)
        landing = geom->frame.toLocal(*m.landing);
    if (m.aircraft.size() > 1) {
        std::string others;
        for (std::size_t i = 1; i < m.aircraft.size(); ++i)
            others += (i > 1 ? ", \"" : "\"") + m.aircraft[i].name + "\"";
        plan.warnings.push_back("multi-aircraft partitioning not available: only the first aircraft (\"" + first.name +
                                "\") was planned, over the whole area; " + others + " got no route");
    }
    const geo::MultiPolygon region{geom->area};
    auto ap = planRegion(region, geom->noFly, first, m.options, geom->frame, home, landing);
    if (!ap)
        return ap.error();
    plan.aircraft.push_back(std::move(*ap));
    PlanTotals& t = plan.totals;
    for (const auto& a : plan.aircraft) {
        ++t.aircraft;
        t.cells += a.metrics.cells;
        t.visitable += a.metrics.visitable;
        t.photos += a.metrics.photos;
        t.pathLengthM += a.metrics.pathLengthM;
        t.distanceM += a.metrics.distanceM;
        t.turns += a.metrics.turns;
        t.turnAngleDeg += a.metrics.turnAngleDeg;
        t.jumps += a.metrics.jumps;
        t.revisits += a.metrics.revisits;
        t.estimatedTimeS = std::max(t.estimatedTimeS, a.metrics.estimatedTimeS);
        t.planningMs += a.metrics.planningMs;
    }
    if (t.jumps > 0)
        plan.warnings.push_back(std::to_string(t.jumps) +
                                " jump(s) between parts of the area that no safe move joins: check the route's "
                                "transits there");
    return plan;
}

namespace {

CPLJSONArray position(const geo::LonLat& p) {
    CPLJSONArray a;
    a.Add(p.lon);
    a.Add(p.lat);
    return a;
}

void addMetrics(CPLJSONObject& o, const plan::PathMetrics& m) {
    o.Add("visitable_cells", m.visitable);
    o.Add("cells", m.cells);
    o.Add("complete", m.complete());
    o.Add("photos", m.photos);
    o.Add("path_length_m", m.pathLengthM);
    o.Add("distance_m", m.distanceM);
    o.Add("turns", m.turns);
    o.Add("turn_angle_deg", m.turnAngleDeg);
    o.Add("jumps", m.jumps);
    o.Add("revisits", m.revisits);
    o.Add("estimated_time_s", m.estimatedTimeS);
    o.Add("planning_ms", m.planningMs);
    o.Add("turn_lower_bound", m.turnLowerBound);
    o.Add("turn_ratio", m.turnRatio);
}

} // namespace

std::string planToGeoJson(const MissionPlan& plan) {
    CPLJSONDocument doc;
    CPLJSONObject root = doc.GetRoot();
    root.Add("type", "FeatureCollection");
    CPLJSONArray features;
    for (const auto& a : plan.aircraft) {
        CPLJSONObject line;
        line.Add("type", "Feature");
        CPLJSONObject props;
        props.Add("aircraft", a.aircraft);
        props.Add("kind", "path");
        line.Add("properties", props);
        CPLJSONObject geom;
        geom.Add("type", "LineString");
        CPLJSONArray coords;
        if (a.route.home)
            coords.Add(position(*a.route.home));
        for (const auto& w : a.route.waypoints)
            coords.Add(position(w.position));
        if (a.route.home)
            coords.Add(position(*a.route.home));
        geom.Add("coordinates", coords);
        line.Add("geometry", geom);
        features.Add(line);
        int seq = 0;
        for (const auto& w : a.route.waypoints) {
            if (w.kind != route::WaypointKind::Photo)
                continue;
            CPLJSONObject f;
            f.Add("type", "Feature");
            CPLJSONObject p;
            p.Add("aircraft", a.aircraft);
            p.Add("seq", ++seq);
            p.Add("alt_m", w.altitudeM);
            p.Add("heading_deg", w.headingDeg);
            f.Add("properties", p);
            CPLJSONObject g;
            g.Add("type", "Point");
            g.Add("coordinates", position(w.position));
            f.Add("geometry", g);
            features.Add(f);
        }
    }
    root.Add("features", features);
    return doc.SaveAsString();
}

std::string planMetricsJson(const MissionPlan& plan, const std::string& plannerName) {
    CPLJSONDocument doc;
    CPLJSONObject root = doc.GetRoot();
    root.Add("planner", plannerName);
    CPLJSONArray list;
    for (const auto& a : plan.aircraft) {
        CPLJSONObject o;
        o.Add("name", a.aircraft);
        o.Add("altitude_m", a.altitudeM);
        o.Add("cell_size_m", a.cellSizeM);
        o.Add("grid_angle_deg", a.gridAngleDeg);
        o.Add("angles_tried", a.anglesTried);
        addMetrics(o, a.metrics);
        list.Add(o);
    }
    root.Add("aircraft", list);
    const PlanTotals& t = plan.totals;
    CPLJSONObject total;
    total.Add("aircraft", t.aircraft);
    total.Add("visitable_cells", t.visitable);
    total.Add("cells", t.cells);
    total.Add("photos", t.photos);
    total.Add("path_length_m", t.pathLengthM);
    total.Add("distance_m", t.distanceM);
    total.Add("turns", t.turns);
    total.Add("turn_angle_deg", t.turnAngleDeg);
    total.Add("jumps", t.jumps);
    total.Add("revisits", t.revisits);
    total.Add("estimated_time_s", t.estimatedTimeS);
    total.Add("planning_ms", t.planningMs);
    root.Add("total", total);
    CPLJSONArray warnings;
    for (const auto& w : plan.warnings)
        warnings.Add(w);
    root.Add("warnings", warnings);
    return doc.SaveAsString();
}

} // namespace pf::mission
