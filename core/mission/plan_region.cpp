#include "core/mission/plan_region.h"

#include "core/fleet/aircraft.h"
#include "core/job_scope.h"
#include "core/mission/aircraft_naming.h"
#include "core/mission/double_grid.h"
#include "core/mission/plane_region.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/validation.h"
#include "core/plan/best_candidate.h"
#include "core/plan/lawnmower_planner.h"
#include "core/plan/planner.h"
#include "core/plan/sweep/sweep_planner.h"
#include "core/route/photo_waypoints.h"
#include "core/route/safety.h"
#include "core/route/sorties.h"
#include "core/route/transit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <string>

namespace pf::mission {

namespace {

// The grid planner of a kind (the stride planner for the kinds that are not grid planners).
plan::PlannerKind toPlanKind(PlannerKind k) {
    return plannerKindInfo(k).gridPlanner.value_or(plan::PlannerKind::Stride);
}

double normaliseAngle(double a) {
    a = std::fmod(a, 180.0);
    if (a < 0)
        a += 180.0;
    return a;
}

std::string label(const AircraftConfig& a) {
    return aircraftLabel(a.name);
}

// What every planner of a region needs about the aircraft.
struct Aircraft {
    const AircraftConfig& cfg;
    std::string who;
    double altitudeM = 0.0;
    sensor::EffectiveFootprint fp;
    double cellSizeM = 0.0;
    plan::FlightTimeModel model;
};

Result<Aircraft> prepare(const AircraftConfig& cfg) {
    Aircraft a{cfg, label(cfg), 0.0, {}, 0.0, flightModel(cfg)};
    auto alt = resolvedAltitude(cfg);
    if (!alt)
        return makeError(alt.error().code, a.who + ": " + alt.error().message);
    auto eff = sensor::effectiveFootprint(cfg.camera, *alt, cfg.overlap);
    if (!eff)
        return makeError(eff.error().code, a.who + ": " + eff.error().message);
    a.altitudeM = *alt;
    a.fp = *eff;
    a.cellSizeM = sensor::cellSizeFor(*eff);
    return a;
}

// The plan's identity and its route's fields but its home and waypoints: the caller that keeps the
// plan converts them (buildPlan); converting every candidate's waypoints to WGS84 here took 40 % of
// an estimate of the fleet split, which only reads the local waypoints, and without the frame's
// transformation (not to be shared between threads) a region can be planned on any thread.
void finish(AircraftPlan& p, const Aircraft& a, PlannerKind kind) {
    p.aircraft = a.cfg.name;
    p.planner = kind;
    p.altitudeM = a.altitudeM;
    p.cellSizeM = a.cellSizeM;
    p.footprint = a.fp;
    p.metrics.photos = static_cast<int>(std::count_if(p.localWaypoints.begin(), p.localWaypoints.end(),
                                                      [](const auto& w) { return w.kind == route::WaypointKind::Photo; }));
    p.route.aircraft = a.cfg.name;
    p.route.cruiseSpeedMps = a.cfg.cruiseSpeedMps;
}

// Heading of the leg a -> b (north when a == b).
double legHeading(const geo::Vec2& a, const geo::Vec2& b) { return route::headingDeg(b - a); }

// Grid planners: the angle search (every candidate angle, or the mission's), the few angles whose cell
// paths fly soonest turned into lanes, and the one whose lane route flies soonest kept. The cell path's
// time misses where lanes end (inside their end cells, at the exact boundary), which can reorder close
// angles; lanes for every angle would cost more than the rest of the search.
constexpr std::size_t kLaneCandidates = 3;
// Above this many cells the angles are ranked on a coarse grid of about kCoarseCells cells, and the
// best kCoarseKeep planned at the real size.
constexpr double kCoarseAboveCells = 500'000;
constexpr double kCoarseCells = 60'000;
constexpr std::size_t kCoarseKeep = 3;

// The grids the grid planners built over one region, by angle and cell size: under the automatic
// choice stride and raster plan the same region on the same grids (every candidate angle when the
// angle is searched), so the second finds them built. Bounded by the cells it holds.
class GridCache {
public:
    static constexpr double kMaxCells = 2'000'000;
    const grid::Grid* find(double angle, double cellSize) const {
        const auto it = m_grids.find({angle, cellSize});
        return it == m_grids.end() ? nullptr : &it->second;
    }
    // The region's ground (admissible area, buffered zones), prepared at the first grid and shared
    // by every angle and cell size after it (a cache serves one region, like its grids: region and
    // zones are read at the first call).
    const Result<grid::GridGround>& ground(const geo::MultiPolygon& region,
                                           const std::vector<geo::Polygon>& noFly,
                                           double safetyMarginM) {
        if (!m_ground || m_groundMarginM != safetyMarginM) {
            m_ground = grid::GridGround::prepare(region, noFly, safetyMarginM);
            m_groundMarginM = safetyMarginM;
        }
        return *m_ground;
    }
    void keep(double angle, double cellSize, const grid::Grid& g) {
        const double cells = static_cast<double>(g.cellCount());
        if (m_cells + cells > kMaxCells)
            return;
        m_cells += cells;
        m_grids.emplace(std::make_pair(angle, cellSize), g);
    }

private:
    std::map<std::pair<double, double>, grid::Grid> m_grids;
    double m_cells = 0;
    std::optional<Result<grid::GridGround>> m_ground;
    double m_groundMarginM = 0.0;
};

Result<AircraftPlan> gridRegion(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                                const Aircraft& a, PlannerKind kind, const PlannerOptions& options,
                                const std::optional<geo::Vec2>& home, const std::optional<geo::Vec2>& landing,
                                GridCache* cache) {
    std::vector<double> angles =
        options.gridAngleDeg ? std::vector<double>{*options.gridAngleDeg} : candidateAngles(region);
    plan::PlanOptions popt;
    popt.kind = toPlanKind(kind);
    popt.wavefront.time = a.model;
    popt.stride = {true, a.model}; // the variant flown soonest
    plan::MetricsOptions mopt;
    mopt.time = a.model;
    mopt.diagonalSteps = popt.kind == plan::PlannerKind::Wavefront && popt.wavefront.moore;
    mopt.turnLowerBound = false;
    // The ground every angle's grid is built from, prepared once (the cache's when there is one).
    GridCache own;
    GridCache& grounds = cache ? *cache : own;
    // The grid at an angle and cell size, and the cell path's request on it (from and back to home).
    auto buildGrid = [&](double angle, double cellSize) -> Result<grid::Grid> {
        if (cache)
            if (const grid::Grid* known = cache->find(angle, cellSize))
                return *known;
        grid::GridOptions gopt;
        gopt.cellSize = cellSize;
        gopt.angleDeg = angle;
        gopt.safetyMarginM = options.safetyMarginM;
        gopt.maxCells = options.maxCells;
        // The option errors first, as Grid::build gives them.
        if (auto e = grid::Grid::checkOptions(gopt))
            return *e;
        const auto& ground = grounds.ground(region, noFly, options.safetyMarginM);
        if (!ground)
            return ground.error();
        auto g = grid::Grid::build(*ground, gopt);
        if (g && cache)
            cache->keep(angle, cellSize, *g);
        return g;
    };
    auto requestOn = [&](const grid::Grid& g) {
        plan::CoverageRequest req;
        if (home) {
            req.takeoff = g.nearestVisitable(*home);
            req.landing = g.nearestVisitable(landing ? *landing : *home);
        }
        return req;
    };
    // A big area: the angles ranked first on a coarser grid (cells a whole factor larger, about
    // kCoarseCells of them), and only the best few planned at the real cell size. The ranking by cell
    // path time holds at the coarse size as the lanes are the same lines, fewer of them; the full
    // search at 10^6 cells would cost 37 grids and cell paths of 0.7 s each.
    const double cellsEstimate = geo::area(region) / (a.cellSizeM * a.cellSizeM);
    if (angles.size() > kCoarseKeep && cellsEstimate > kCoarseAboveCells) {
        const double factor = std::ceil(std::sqrt(cellsEstimate / kCoarseCells));
        std::vector<std::pair<double, double>> scored; // estimated time, angle
        for (std::size_t ai = 0; ai < angles.size() && !stopRequested(); ++ai) {
            reportProgress(0.1 * static_cast<double>(ai) / static_cast<double>(angles.size()), "grid angles (coarse)");
            auto g = buildGrid(angles[ai], a.cellSizeM * factor);
            if (!g)
                continue;
            auto path = plan::planCoverage(*g, requestOn(*g), popt);
            if (!path)
                continue;
            scored.emplace_back(plan::computeMetrics(*g, *path, mopt).estimatedTimeS, angles[ai]);
        }
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "planning cancelled");
        if (scored.size() >= kCoarseKeep) {
            std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
            angles.clear();
            for (std::size_t i = 0; i < kCoarseKeep; ++i)
                angles.push_back(scored[i].second);
        }
    }

    std::vector<AircraftPlan> best; // the cell paths flown soonest, soonest first
    std::optional<Error> firstError;
    int tried = 0;
    auto earlier = [](const plan::PathMetrics& x, const plan::PathMetrics& y) {
        return plan::sooner(x.estimatedTimeS, y.estimatedTimeS) ||
               (plan::sameTime(x.estimatedTimeS, y.estimatedTimeS) && x.turns < y.turns);
    };
    for (std::size_t ai = 0; ai < angles.size() && !stopRequested(); ++ai) {
        const double angle = angles[ai];
        const double f0 = 0.6 * static_cast<double>(ai) / static_cast<double>(angles.size());
        const double f1 = 0.6 * static_cast<double>(ai + 1) / static_cast<double>(angles.size());
        reportProgress(f0, "grid");
        auto g = buildGrid(angle, a.cellSizeM);
        if (!g) {
            if (!firstError)
                firstError = g.error();
            continue;
        }
        reportProgress(f0 + 0.3 * (f1 - f0), "cell path");
        auto path = plan::planCoverage(*g, requestOn(*g), popt);
        if (stopRequested())
            break;
        if (!path) {
            if (!firstError)
                firstError = path.error();
            continue;
        }
        ++tried;
        plan::PathMetrics m = plan::computeMetrics(*g, *path, mopt);
        if (best.size() == kLaneCandidates && !earlier(m, best.back().metrics))
            continue;
        AircraftPlan p;
        p.gridAngleDeg = angle;
        p.grid = std::move(*g);
        p.path = std::move(*path);
        p.metrics = m;
        const auto at = std::upper_bound(best.begin(), best.end(), p,
                                         [&](const AircraftPlan& x, const AircraftPlan& y) { return earlier(x.metrics, y.metrics); });
        best.insert(at, std::move(p));
        if (best.size() > kLaneCandidates)
            best.pop_back();
    }
    if (best.empty()) {
        const Error e = firstError ? *firstError : makeError(ErrorCode::Internal, "no grid angle to try");
        return makeError(e.code, a.who + ": " + e.message);
    }
    std::size_t chosen = 0;
    auto soonest = plan::soonestTime(); // on a tie the cell path flown sooner wins
    reportProgress(0.6, "photo waypoints");
    for (std::size_t i = 0; i < best.size() && !stopRequested(); ++i) {
        AircraftPlan& p = best[i];
        p.localWaypoints = route::photoWaypoints(p.grid, p.path, a.fp);
        if (stopRequested())
            break; // each step below takes 0.1 s at 10^6 cells, none of them checks
        route::straightenTransits(p.grid, p.localWaypoints);
        if (stopRequested())
            break;
        const double t = aloneRouteTimeS(surveyPart(p.localWaypoints), a.cfg, home, landing);
        if (soonest.offer(t))
            chosen = i;
    }
    if (stopRequested())
        return makeError(ErrorCode::Cancelled, "planning cancelled");
    AircraftPlan p = std::move(best[chosen]);
    p.anglesTried = tried;
    mopt.turnLowerBound = true;
    p.metrics = plan::computeMetrics(p.grid, p.path, mopt);
    return p;
}

Result<AircraftPlan> sweepRegion(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                                 const Aircraft& a, const PlannerOptions& options, const std::optional<geo::Vec2>& home,
                                 const std::optional<geo::Vec2>& landing) {
    plan::SweepOptions so;
    so.trackSpacingM = a.fp.acrossM;
    so.photoSpacingM = a.fp.alongM;
    so.realAcrossM = a.fp.real.longSideM;
    so.realAlongM = a.fp.real.shortSideM;
    so.safetyMarginM = options.safetyMarginM;
    so.keepInside = options.keepInsideArea;
    so.time = a.model;
    so.home = home;
    so.landing = landing;
    if (options.gridAngleDeg)
        so.anglesDeg = {*options.gridAngleDeg};
    const bool plane = fleet::fliesAsPlane(a.cfg.kind);
    const double radiusM = plane ? fleet::minTurnRadiusM(a.cfg.plane, a.cfg.cruiseSpeedMps) : 0.0;
    // A plane's lanes end further from the zones (planeLaneRoomM); the sweep's transitions, which a
    // plane does not fly (its turns replace them), need not keep inside.
    if (plane) {
        so.safetyMarginM += planeLaneRoomM(radiusM, a.fp.real.shortSideM);
        so.keepInside = false;
    }
    reportProgress(0.0, "lanes");
    auto sp = plan::planSweep(region, noFly, so);
    if (stopRequested())
        return makeError(ErrorCode::Cancelled, "planning cancelled");
    if (!sp)
        return makeError(sp.error().code, a.who + ": " + sp.error().message);
    if (plane) {
        AircraftPlan p = planeLanesPlan(*sp, noFly, a.cfg, radiusM, a.fp.acrossM, options, home, landing);
        routeMetrics(p, a.model);
        return p;
    }
    AircraftPlan p;
    p.gridAngleDeg = sp->stats.angleDeg;
    p.anglesTried = sp->stats.directionsPlanned;
    for (std::size_t i = 0; i < sp->lanes.size(); ++i) {
        const plan::Lane& lane = sp->lanes[i];
        for (const auto& ph : lane.photos)
            p.localWaypoints.push_back({ph, lane.headingDeg, route::WaypointKind::Photo, -1});
        if (i + 1 < sp->lanes.size()) {
            const auto& link = sp->links[i];
            for (std::size_t k = 0; k < link.size(); ++k) {
                const geo::Vec2 next = k + 1 < link.size() ? link[k + 1] : sp->lanes[i + 1].photos.front();
                p.localWaypoints.push_back({link[k], legHeading(link[k], next), route::WaypointKind::Transit, -1});
            }
        }
    }
    route::dropNearDuplicates(p.localWaypoints);
    p.warnings = sp->warnings;
    routeMetrics(p, a.model);
    return p;
}

Result<AircraftPlan> lawnmowerRegion(const geo::MultiPolygon& region, const Aircraft& a,
                                     const PlannerOptions& options, const std::optional<geo::Vec2>& home) {
    plan::LawnmowerOptions lo;
    lo.trackSpacingM = a.fp.acrossM;
    lo.photoSpacingM = a.fp.alongM;
    lo.time = a.model;
    lo.home = home;
    lo.angleDeg = options.gridAngleDeg;
    lo.footprintAcrossM = a.fp.real.longSideM;
    lo.footprintAlongM = a.fp.real.shortSideM;
    auto lp = plan::planLawnmower(region, lo);
    if (!lp)
        return makeError(lp.error().code, a.who + ": " + lp.error().message);
    AircraftPlan p;
    p.gridAngleDeg = lp->angleDeg;
    p.anglesTried = lp->anglesTried;
    for (const auto& t : lp->transects) {
        if (t.photos.empty())
            continue;
        const geo::Vec2 d = t.stripEnd - t.stripStart;
        const geo::Vec2 u = d.norm() > 0 ? geo::Vec2(d.normalized()) : geo::Vec2(0, 1);
        // The Survey flies each transect on from its turnaround before the entry to the one after the exit.
        if (lo.turnaroundM > 0)
            p.localWaypoints.push_back({t.stripStart - lo.turnaroundM * u, t.headingDeg, route::WaypointKind::Turn, -1});
        for (const auto& ph : t.photos)
            p.localWaypoints.push_back({ph, t.headingDeg, route::WaypointKind::Photo, -1});
        if (lo.turnaroundM > 0)
            p.localWaypoints.push_back({t.stripEnd + lo.turnaroundM * u, t.headingDeg, route::WaypointKind::Turn, -1});
    }
    route::dropNearDuplicates(p.localWaypoints);
    routeMetrics(p, a.model);
    return p;
}

// The time of one flight over `survey` as the mission will fly it: made safe (detours round the margins)
// and from home and back by the safe transit; aloneRouteTimeS when any of that fails (the plan's own
// stages then report why).
double flownTimeS(const std::vector<route::LocalWaypoint>& survey, const AircraftConfig& cfg,
                  const std::optional<geo::Vec2>& home, const std::optional<geo::Vec2>& landing,
                  const route::SafePathFinder& finder) {
    auto safe = route::enforceNoFly(survey, finder);
    if (!safe)
        return aloneRouteTimeS(survey, cfg, home, landing);
    if (!home)
        return aloneRouteTimeS(*safe, cfg, home, landing);
    auto flown = route::withTransit(*safe, *home, finder, landing);
    if (!flown)
        return aloneRouteTimeS(*safe, cfg, home, landing);
    return aloneRouteTimeS(*flown, cfg, home, landing);
}

std::string minutes(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f min", s / 60.0);
    return buf;
}

Result<AircraftPlan> planOne(const geo::MultiPolygon& region,
                             const std::vector<geo::Polygon>& noFly, const Aircraft& a,
                             PlannerKind kind, const PlannerOptions& options,
                             const std::optional<geo::Vec2>& home,
                             const std::optional<geo::Vec2>& landing,
                             const route::LaneSpacingFn& laneSpacing, GridCache* grids = nullptr) {
    Result<AircraftPlan> p = makeError(ErrorCode::Internal, "no planner");
    switch (kind) {
    case PlannerKind::Sweep:
        p = sweepRegion(region, noFly, a, options, home, landing);
        break;
    case PlannerKind::Lawnmower:
        p = lawnmowerRegion(region, a, options, home);
        break;
    default:
        p = gridRegion(region, noFly, a, kind, options, home, landing, grids);
        break;
    }
    if (stopRequested())
        return makeError(ErrorCode::Cancelled, "planning cancelled");
    if (p && laneSpacing) {
        // Each lane's photos as far apart as its own ground allows (the planner spaced them for the
        // lowest height above ground over the whole region).
        route::LaneSpacingReport rep;
        p->localWaypoints = route::spaceLanes(p->localWaypoints, a.fp.alongM, laneSpacing, &rep);
        p->terrain.lanesRespaced = rep.respaced;
        p->terrain.photosSavedPerLane = rep.photosBefore - rep.photosAfter;
        if (rep.respaced > 0 && (kind == PlannerKind::Sweep || kind == PlannerKind::Lawnmower))
            routeMetrics(*p, a.model);
    }
    if (p)
        finish(*p, a, kind);
    return p;
}

} // namespace

void routeMetrics(AircraftPlan& p, const plan::FlightTimeModel& model) {
    std::vector<geo::Vec2> pts;
    pts.reserve(p.localWaypoints.size());
    for (const auto& w : p.localWaypoints)
        pts.push_back(w.pos);
    const plan::FlightTime t = plan::flightTime(pts, model);
    p.metrics.pathLengthM = t.lengthM;
    p.metrics.distanceM = t.lengthM;
    p.metrics.turns = t.turns;
    p.metrics.turnAngleDeg = t.turnAngleDeg;
    p.metrics.estimatedTimeS = t.totalS;
    p.metrics.occurrences = static_cast<int>(pts.size());
}

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

Result<AircraftPlan> planRegion(const geo::MultiPolygon& region,
                                const std::vector<geo::Polygon>& noFly,
                                const AircraftConfig& aircraft, const PlannerOptions& options,
                                const std::optional<geo::Vec2>& home,
                                const std::optional<geo::Vec2>& landing,
                                const route::LaneSpacingFn& laneSpacing) {
    if (options.doubleGrid) // two passes, each planned here without it
        return planDoubleGrid(region, noFly, aircraft, options, home, landing, laneSpacing);
    const auto t0 = std::chrono::steady_clock::now();
    auto a = prepare(aircraft);
    if (!a)
        return a.error();
    Result<AircraftPlan> out = makeError(ErrorCode::Internal, "no planner");
    const bool plane = fleet::fliesAsPlane(aircraft.kind);
    if (auto e = planeRoutingError(aircraft, options.planner, a->who); !e.empty())
        return makeError(ErrorCode::InvalidInput, e);
    if (options.planner != PlannerKind::Auto) {
        out = planOne(region, noFly, *a, options.planner, options, home, landing, laneSpacing);
    } else {
        // The candidates, each planned in full and compared on the route the aircraft would fly: its
        // survey made safe (the detours a grid planner's jumps need) and the safe ways from home and back.
        const route::SafePathFinder finder(route::NoFlyField(noFly, options.safetyMarginM));
        std::string note;
        auto soonest = plan::soonestTime(); // on a tie the planner listed first wins
        GridCache grids;
        std::optional<Error> firstError;
        constexpr PlannerKind kCandidates[] = {PlannerKind::Sweep, PlannerKind::Stride,
                                               PlannerKind::Raster};
        for (std::size_t i = 0; i < std::size(kCandidates); ++i) {
            const PlannerKind k = kCandidates[i];
            if (plane && !servesPlanes(plannerKindInfo(k)))
                continue; // its route turns on the spot
            if (stopRequested())
                return makeError(ErrorCode::Cancelled, "planning cancelled");
            const char* id = plannerKindInfo(k).id;
            // Each planner moves the progress through its own third ("stride: grid").
            auto p = [&] {
                const double parts = static_cast<double>(std::size(kCandidates));
                JobScope part(static_cast<double>(i) / parts, static_cast<double>(i + 1) / parts,
                              std::string(id) + ": ");
                return planOne(region, noFly, *a, k, options, home, landing, laneSpacing, &grids);
            }();
            if (!p) {
                if (!firstError)
                    firstError = p.error();
                note += std::string(note.empty() ? "" : ", ") + id + " failed";
                continue;
            }
            const double t = flownTimeS(surveyPart(p->localWaypoints), aircraft, home, landing, finder);
            note += std::string(note.empty() ? "" : ", ") + id + " " + minutes(t);
            if (soonest.offer(t))
                out = std::move(p);
        }
        if (!out)
            return firstError ? *firstError : out.error();
        out->plannerChoice =
            plane ? std::string(plannerKindInfo(out->planner).id) + " (" + note +
                        "; the only planner here that plans for a plane: stride and raster turn "
                        "on the spot)"
                  : std::string(plannerKindInfo(out->planner).id) + " flies soonest (" + note +
                        ", home to home in one flight)";
    }
    if (stopRequested())
        return makeError(ErrorCode::Cancelled, "planning cancelled");
    if (!out)
        return out;
    out->metrics.planningMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

std::vector<route::Waypoint> routeWaypoints(const std::vector<route::LocalWaypoint>& w, const geo::LocalFrame& frame,
                                            double altitudeM) {
    constexpr std::size_t kBlock = 1 << 16;
    std::vector<route::Waypoint> out;
    out.reserve(w.size());
    geo::Ring block;
    for (std::size_t i = 0; i < w.size(); i += kBlock) {
        if (stopRequested())
            break;
        const std::size_t end = std::min(w.size(), i + kBlock);
        block.clear();
        for (std::size_t k = i; k < end; ++k)
            block.push_back(w[k].pos);
        const geo::GeoRing geo = frame.toGeo(block);
        for (std::size_t k = i; k < end; ++k)
            out.push_back({geo[k - i], altitudeM, w[k].headingDeg, w[k].kind});
    }
    return out;
}

std::vector<route::LocalWaypoint> surveyPart(const std::vector<route::LocalWaypoint>& w) {
    const auto isPhoto = [](const route::LocalWaypoint& x) { return x.kind == route::WaypointKind::Photo; };
    const auto first = std::find_if(w.begin(), w.end(), isPhoto);
    if (first == w.end())
        return {};
    const auto last = std::find_if(w.rbegin(), w.rend(), isPhoto).base();
    return {first, last};
}

double aloneRouteTimeS(const std::vector<route::LocalWaypoint>& survey, const AircraftConfig& a,
                       const std::optional<geo::Vec2>& home, const std::optional<geo::Vec2>& landing) {
    std::vector<geo::Vec2> pts;
    pts.reserve(survey.size() + 2);
    if (home)
        pts.push_back(*home);
    for (const auto& w : survey)
        pts.push_back(w.pos);
    if (home)
        pts.push_back(landing ? *landing : *home);
    return route::flightTimeS(pts, flightModel(a));
}

} // namespace pf::mission
