#include "core/mission/plan_mission.h"

#include "core/fleet/altitude.h"
#include "core/fleet/area_split.h"
#include "core/fleet/photo_dedup.h"
#include "core/geo/polygon_ops.h"
#include "core/grid/grid.h"
#include "core/sensor/camera.h"
#include "core/mission/plan_region.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/terrain_stage.h"
#include "core/mission/validation.h"
#include "core/plan/coverage_check.h"
#include "core/plan/planner.h"
#include "core/route/photo_waypoints.h"
#include "core/route/safety.h"
#include "core/route/sorties.h"
#include "core/route/transit.h"

#include <cpl_json.h>

#include <algorithm>
#include <future>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace pf::mission {

namespace {

// The covered fraction of the admissible area below which a plan gets a warning.
constexpr double kCoverageTarget = 0.995;
// The makespan / ideal (total time / aircraft) a shared plan aims to stay within.
constexpr double kBalanceTarget = 1.10;

} // namespace

namespace {

std::string aircraftLabel(const AircraftConfig& a) {
    return a.name.empty() ? std::string("the aircraft") : "aircraft \"" + a.name + "\"";
}

double polylineLength(const std::vector<geo::Vec2>& p) {
    double s = 0.0;
    for (std::size_t i = 1; i < p.size(); ++i)
        s += (p[i] - p[i - 1]).norm();
    return s;
}

std::string metres(double v, int decimals = 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// Steps 2 to 6 of planMission for given regions (one per aircraft), planned with `opt`. Without
// `check`, step 6 (the coverage raster and the margin breaches) is left out: the candidates of the
// split are compared on their times alone, and only the plan returned is checked.
Result<MissionPlan> buildPlan(const Mission& m, const PlannerOptions& opt, const LocalGeometry& geom,
                              const std::vector<geo::MultiPolygon>& regions,
                              const std::vector<std::optional<geo::Vec2>>& homes,
                              const std::optional<geo::Vec2>& landing, bool check,
                              std::vector<double>* aloneTimes = nullptr);

} // namespace

namespace {

// planMission for one planner kind (never Auto).
Result<MissionPlan> planMissionWith(const Mission& m) {
    if (m.aircraft.empty())
        return makeError(ErrorCode::InvalidInput, "the mission has no aircraft: add one to plan a flight");
    auto geom = localGeometry(m);
    if (!geom)
        return geom.error();
    const geo::LocalFrame& frame = geom->frame;
    const std::size_t n = m.aircraft.size();
    const PlannerOptions& opt = m.options;

    // Per aircraft: footprint (for the split) and home.
    std::vector<fleet::Capability> caps;
    std::vector<sensor::EffectiveFootprint> footprints;
    std::vector<std::optional<geo::Vec2>> homes;
    for (const auto& a : m.aircraft) {
        auto alt = resolvedAltitude(a);
        if (!alt)
            return makeError(alt.error().code, aircraftLabel(a) + ": " + alt.error().message);
        auto eff = sensor::effectiveFootprint(a.camera, *alt, a.overlap);
        if (!eff)
            return makeError(eff.error().code, aircraftLabel(a) + ": " + eff.error().message);
        footprints.push_back(*eff);
        caps.push_back({a.name, *eff, flightModel(a)});
        const std::optional<geo::LonLat> h = a.home ? a.home : m.home;
        homes.push_back(h ? std::optional<geo::Vec2>(frame.toLocal(*h)) : std::nullopt);
    }
    std::optional<geo::Vec2> landing;
    if (m.landing)
        landing = frame.toLocal(*m.landing);

    // 1. Each aircraft's region: the whole area alone, else a time-balanced split.
    if (n == 1) {
        auto one = buildPlan(m, opt, *geom, {geo::MultiPolygon{geom->area}}, homes, landing, true);
        return one;
    }
    // The split estimates times at one fixed angle (a full angle search per estimate would cost 37
    // times as much): the mission's, or the best for the aircraft with the coarsest grid (the cheapest
    // search) over the whole area.
    double estimateAngle = 0.0;
    if (opt.gridAngleDeg) {
        estimateAngle = *opt.gridAngleDeg;
    } else {
        std::size_t coarsest = 0;
        for (std::size_t k = 1; k < n; ++k)
            if (sensor::cellSizeFor(footprints[k]) > sensor::cellSizeFor(footprints[coarsest]))
                coarsest = k;
        auto whole = planRegion(geo::MultiPolygon{geom->area}, geom->noFly, m.aircraft[coarsest], opt, frame,
                                homes[coarsest], landing);
        if (!whole)
            return whole.error();
        estimateAngle = whole->gridAngleDeg;
    }
    PlannerOptions fixed = opt;
    fixed.gridAngleDeg = estimateAngle;
    // The time of the route the aircraft would fly alone over `sub` (aloneRouteTimeS). The planner's
    // own cell-path time misses where the photos sit (the route runs through photo waypoints, not
    // cell centres) and was off by up to 7 % on large footprints; the route leaves only what needs
    // the neighbours (photos another aircraft already takes) and the no-fly detours to the correction
    // factors below. An aircraft whose subarea lies far from its home gets less of the area.
    const auto rawEstimate = [&](std::size_t k, const geo::MultiPolygon& sub) -> Result<double> {
        auto ap = planRegion(sub, geom->noFly, m.aircraft[k], fixed, frame, homes[k], landing);
        if (!ap)
            return ap.error();
        return aloneRouteTimeS(surveyPart(ap->localWaypoints), m.aircraft[k], homes[k], landing);
    };
    fleet::AreaSplitOptions so;
    so.gridAngleDeg = estimateAngle;
    so.safetyMarginM = opt.safetyMarginM;
    // Tighter than the balancer's default (5 %): the stages after the estimate add their own spread,
    // and the target is the final makespan within 10 % of the ideal.
    so.balance.tolerance = 0.03;
    // Every split tried, with the makespan of its plan at the fixed angle and whether that makespan
    // is within kBalanceTarget of the ideal.
    struct Candidate {
        bool balanced = false;
        double makespanS = 0.0;
        std::vector<geo::MultiPolygon> regions;
    };
    std::vector<Candidate> candidates;
    const auto ratio = [](const MissionPlan& p) { return p.idealS > 0 ? p.makespanS / p.idealS : 1.0; };
    // Up to two starts: the aircraft in the mission's order, then, if no round of it came within the
    // balancer's tolerance, reversed. The partition seeds the aircraft one after the other from the
    // far end of the free cells, so the order decides which aircraft gets which end of the area and
    // the shapes of the subareas; the flight time depends on those shapes (turns, pieces, photos a
    // neighbour already takes) far more than on their sizes, so two splits balanced on the estimate
    // can differ by 10 % in makespan. The second start is skipped when the first is balanced, to keep
    // the planning time near that of one split. Every split planned is a candidate (below).
    std::vector<std::vector<std::size_t>> orders(1);
    for (std::size_t k = 0; k < n; ++k)
        orders[0].push_back(k);
    orders.emplace_back(orders[0].rbegin(), orders[0].rend());
    bool reachedTolerance = false;
    for (const auto& order : orders) {
        if (reachedTolerance)
            break;
        std::vector<fleet::Capability> ordered;
        for (std::size_t k : order)
            ordered.push_back(caps[k]);
        std::vector<double> factor(n, 1.0);
        // The estimate misses what comes after the per-aircraft plan: photos dropped because a
        // neighbour with a larger footprint already sees them, detours, the safe transit. So: split,
        // plan to the end, measure each aircraft's final time against its estimate, and split again
        // with each estimate scaled by that factor; a few rounds at most per start.
        constexpr int kRounds = 3;
        for (int round = 0; round < kRounds; ++round) {
            const fleet::RegionTimeEstimator estimate = [&](int i, const geo::MultiPolygon& sub) -> Result<double> {
                const std::size_t k = order[static_cast<std::size_t>(i)];
                auto t = rawEstimate(k, sub);
                if (!t)
                    return t;
                return *t * factor[k];
            };
            auto split = fleet::splitArea(geom->area, geom->noFly, ordered, so, estimate);
            if (!split)
                return makeError(split.error().code,
                                 "sharing the area between the aircraft: " + split.error().message);
            std::vector<geo::MultiPolygon> regions(n);
            for (std::size_t i = 0; i < n; ++i)
                regions[order[i]] = std::move(split->subareas[i]);
            std::vector<double> alone; // the estimate of each subarea, as the plan made it
            auto p = buildPlan(m, fixed, *geom, regions, homes, landing, false, &alone);
            if (!p)
                return p.error();
            // The factors of the plan just made.
            std::vector<double> next = factor;
            for (std::size_t k = 0; k < n; ++k)
                if (alone[k] > 0 && p->aircraft[k].timeS > 0)
                    next[k] = p->aircraft[k].timeS / alone[k];
            const bool balanced = ratio(*p) <= 1.0 + so.balance.tolerance;
            candidates.push_back({ratio(*p) <= kBalanceTarget, p->makespanS, std::move(regions)});
            reachedTolerance = reachedTolerance || balanced;
            if (balanced || next == factor)
                break;
            factor = std::move(next);
        }
    }
    // The candidates were planned at the estimate's fixed angle (a full angle search per candidate
    // would cost up to 37 times as much) and without the coverage check. They are ranked: those
    // within kBalanceTarget of the ideal first (a plan that leaves the other aircraft idle while one
    // flies on is not what a shared area asks for, even if its makespan is a little shorter), then
    // by makespan. The first is planned once more with the mission's options (which may search the
    // angle per subarea; if that makes the makespan longer, the fixed angle is kept) and checked.
    // Should its photos miss the coverage target or a leg breach a no-fly margin, the next one is
    // tried; if none passes, the first is returned with its warnings.
    std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return a.balanced != b.balanced ? a.balanced : a.makespanS < b.makespanS;
    });
    std::optional<MissionPlan> first;
    for (const Candidate& c : candidates) {
        auto chosen = buildPlan(m, opt, *geom, c.regions, homes, landing, true);
        if (!chosen)
            return chosen.error();
        if (!opt.gridAngleDeg && chosen->makespanS > c.makespanS) {
            chosen = buildPlan(m, fixed, *geom, c.regions, homes, landing, true);
            if (!chosen)
                return chosen.error();
        }
        if (chosen->coverageRatio >= kCoverageTarget && chosen->noFlyViolations == 0)
            return chosen;
        if (!first)
            first = std::move(*chosen);
    }
    return std::move(*first);
}

} // namespace

// The automatic choice plans the whole mission with each candidate planner and keeps the one that
// finishes soonest: so it is never slower than any planner it chose from, also with several
// aircraft, whose split depends on the planner's times. A plan that leaves more of the area unseen
// than the coverage target, or breaches a margin, loses to one that does not. The plans share
// nothing and run in parallel, unless the grids are large: then one after the other, so that the
// peak memory is that of the largest plan, not the sum of three.
Result<MissionPlan> planMission(const Mission& m) {
    if (needsTerrainStage(m)) // terrain following: the DEM read once, then planned over it (terrain_stage.h)
        return planOverTerrain(m, planMission);
    if (m.options.planner != PlannerKind::Auto)
        return planMissionWith(m);
    const PlannerKind kinds[] = {PlannerKind::Sweep, PlannerKind::Stride, PlannerKind::Raster};
    // The cells of the grid planners over the whole area (bounding box at the mission's angle).
    double cells = 0.0;
    if (auto geom = localGeometry(m)) {
        for (const auto& a : m.aircraft) {
            auto alt = resolvedAltitude(a);
            if (!alt)
                continue;
            if (auto eff = sensor::effectiveFootprint(a.camera, *alt, a.overlap))
                cells += grid::Grid::sizeFor(geo::MultiPolygon{geom->area}, sensor::cellSizeFor(*eff),
                                             m.options.gridAngleDeg.value_or(0.0))
                             .cells();
        }
    }
    constexpr double kParallelCells = 300'000.0; // about 100 MB of grid state per planner
    const bool parallel = cells <= kParallelCells;
    std::vector<std::future<Result<MissionPlan>>> runs;
    for (PlannerKind k : kinds) {
        Mission mk = m;
        mk.options.planner = k;
        runs.push_back(std::async(parallel ? std::launch::async : std::launch::deferred,
                                  [mk] { return planMissionWith(mk); }));
    }
    std::optional<MissionPlan> best;
    std::string note, errors;
    std::optional<ErrorCode> firstCode;
    auto sound = [](const MissionPlan& p) { return p.coverageRatio >= kCoverageTarget && p.noFlyViolations == 0; };
    for (std::size_t i = 0; i < runs.size(); ++i) {
        auto p = runs[i].get();
        const char* id = plannerKindInfo(kinds[i]).id;
        if (!p) {
            note += std::string(note.empty() ? "" : ", ") + id + " failed: " + p.error().message;
            errors += std::string(errors.empty() ? "" : "; ") + id + ": " + p.error().message;
            if (!firstCode)
                firstCode = p.error().code;
            continue;
        }
        note += std::string(note.empty() ? "" : ", ") + id + " " + metres(p->makespanS / 60.0, 1) + " min";
        if (!sound(*p))
            note += " (" + std::string(p->noFlyViolations > 0 ? "breaches a margin" : "misses the coverage target") + ")";
        const bool better = !best || (sound(*p) && !sound(*best)) ||
                            (sound(*p) == sound(*best) && p->makespanS < best->makespanS - 1e-9);
        if (better)
            best = std::move(*p);
    }
    if (!best)
        return makeError(*firstCode, "no planner could plan the mission: " + errors);
    best->plannerChoice = std::string(plannerKindInfo(best->aircraft.front().planner).id) +
                          " finishes soonest (" + note + ")";
    return std::move(*best);
}

namespace {

Result<MissionPlan> buildPlan(const Mission& m, const PlannerOptions& opt, const LocalGeometry& geomRef,
                              const std::vector<geo::MultiPolygon>& regions,
                              const std::vector<std::optional<geo::Vec2>>& homes,
                              const std::optional<geo::Vec2>& landing, bool check,
                              std::vector<double>* aloneTimes) {
    const LocalGeometry* geom = &geomRef;
    const geo::LocalFrame& frame = geom->frame;
    const std::size_t n = m.aircraft.size();
    MissionPlan plan;
    plan.frame = frame;

    // 2. Each aircraft over its region.
    for (std::size_t k = 0; k < n; ++k) {
        if (regions[k].empty())
            return makeError(ErrorCode::InvalidInput,
                             aircraftLabel(m.aircraft[k]) + ": got no part of the area (too many aircraft for it)");
        auto ap = planRegion(regions[k], geom->noFly, m.aircraft[k], opt, frame, homes[k], landing);
        if (!ap)
            return ap.error();
        ap->subarea = regions[k];
        ap->surveyWaypoints = surveyPart(ap->localWaypoints);
        if (aloneTimes)
            aloneTimes->push_back(aloneRouteTimeS(ap->surveyWaypoints, m.aircraft[k], homes[k], landing));
        plan.aircraft.push_back(std::move(*ap));
    }

    // 3. No second photo of ground another aircraft already takes.
    if (n > 1) {
        std::vector<fleet::AircraftPhotos> photos;
        for (const auto& a : plan.aircraft)
            photos.push_back({a.surveyWaypoints, a.footprint.acrossM, a.footprint.alongM, a.footprint.real.longSideM,
                              a.footprint.real.shortSideM});
        auto saved = fleet::dropDuplicatePhotos(photos);
        if (!saved)
            return saved.error();
        for (std::size_t k = 0; k < n; ++k) {
            plan.aircraft[k].surveyWaypoints = std::move(photos[k].waypoints);
            plan.aircraft[k].photosSaved = saved->photosSaved[k];
            // Where dropped photos leave only turn and transit points between two photos, fly straight.
            if (saved->photosSaved[k] > 0)
                route::straightenTransits(plan.aircraft[k].grid, plan.aircraft[k].surveyWaypoints);
        }
        plan.photosSaved = saved->totalSaved;
    }

    // 4. Safety, transit and sorties.
    const geo::MultiPolygon areaMp{geom->area};
    const geo::MultiPolygon admissible = geom->noFly.empty() ? areaMp : geo::difference(geom->area, geom->noFly);
    const route::SafePathFinder safeFinder(route::NoFlyField(geom->noFly, opt.safetyMarginM));
    // The lawnmower flies what a ground station's Survey flies: straight over the zones, from and back
    // to home too. Nothing makes it safe; the route check reports every crossing.
    const route::SafePathFinder straightFinder;
    std::vector<std::vector<geo::Vec2>> flownPaths;
    std::vector<plan::PhotoFootprint> photoFootprints;
    for (std::size_t k = 0; k < n; ++k) {
        AircraftPlan& ap = plan.aircraft[k];
        const AircraftConfig& cfg = m.aircraft[k];
        const std::string who = aircraftLabel(cfg);
        for (const auto& w : ap.warnings)
            plan.warnings.push_back(who + ": " + w);
        const bool yardstick = ap.planner == PlannerKind::Lawnmower;
        const route::SafePathFinder& finder = yardstick ? straightFinder : safeFinder;
        std::vector<route::LocalWaypoint> survey = ap.surveyWaypoints;
        route::SafetyReport rep;
        if (opt.keepInsideArea && !yardstick) {
            const route::PhotoSides sides{ap.footprint.acrossM, ap.footprint.alongM, ap.footprint.real.longSideM,
                                          ap.footprint.real.shortSideM};
            auto inside = route::keepInsideArea(survey, areaMp, admissible, sides, opt.insideMarginM, finder, &rep);
            if (!inside)
                return makeError(inside.error().code, who + ": " + inside.error().message);
            survey = std::move(*inside);
        }
        if (!yardstick) {
            auto safe = route::enforceNoFly(survey, finder, &rep);
            if (!safe)
                return makeError(safe.error().code, who + ": " + safe.error().message);
            survey = std::move(*safe);
        }
        route::dropNearDuplicates(survey);
        for (const auto& w : rep.warnings)
            plan.warnings.push_back(who + ": " + w);
        ap.detours = rep.detours;
        ap.waypointsMoved = rep.waypointsMoved;
        ap.keptInside = rep.keptInside;
        ap.surveyWaypoints = survey;

        const route::FlightModel model = flightModel(cfg);
        std::vector<route::LocalWaypoint> flown;
        std::vector<geo::Vec2> path; // home, every waypoint, landing
        const auto& home = homes[k];
        if (home) {
            auto sp = route::splitIntoSorties(survey, *home, finder, model,
                                              route::SortieOptions{cfg.enduranceMin, opt.batteryReserve}, cfg.name);
            if (!sp)
                return makeError(sp.error().code, who + ": " + sp.error().message);
            if (sp->sorties.size() == 1 && landing && (*landing - *home).norm() > 1e-6) {
                // One flight landing elsewhere: out from home, back to the landing point.
                auto t = route::withTransit(survey, *home, finder, landing);
                if (!t)
                    return makeError(t.error().code, who + ": " + t.error().message);
                std::vector<geo::Vec2> poly{*home};
                for (const auto& w : *t)
                    poly.push_back(w.pos);
                poly.push_back(*landing);
                SortieSummary s;
                s.firstWaypoint = 0;
                s.lastWaypoint = static_cast<int>(t->size()) - 1;
                s.lengthM = polylineLength(poly);
                s.timeS = route::flightTimeS(poly, model);
                flown = std::move(*t);
                ap.sorties.push_back(s);
            } else {
                for (const auto& s : sp->sorties) {
                    SortieSummary sum;
                    sum.firstWaypoint = static_cast<int>(flown.size());
                    flown.insert(flown.end(), s.waypoints.begin(), s.waypoints.end());
                    sum.lastWaypoint = static_cast<int>(flown.size()) - 1;
                    sum.lengthM = s.lengthM;
                    sum.timeS = s.timeS;
                    ap.sorties.push_back(sum);
                }
                if (sp->sorties.size() > 1)
                    plan.warnings.push_back(who + ": the flight needs " + std::to_string(sp->sorties.size()) +
                                            " batteries (sorties returning home), " + metres(sp->totalTimeS / 60.0, 1) +
                                            " min in all for " + metres(sp->budgetS / 60.0, 1) + " min per battery");
            }
            // Every sortie starts and ends at home: the legs between sorties are flown through it.
            path.push_back(*home);
            for (std::size_t si = 0; si < ap.sorties.size(); ++si) {
                for (int i = ap.sorties[si].firstWaypoint; i <= ap.sorties[si].lastWaypoint; ++i)
                    path.push_back(flown[static_cast<std::size_t>(i)].pos);
                if (si + 1 < ap.sorties.size())
                    path.push_back(*home);
            }
            path.push_back(ap.sorties.size() == 1 && landing ? *landing : *home);
        } else {
            // No home: the survey alone, one flight; no transit to check.
            flown = survey;
            for (const auto& w : flown)
                path.push_back(w.pos);
            SortieSummary s;
            s.lastWaypoint = static_cast<int>(flown.size()) - 1;
            s.lengthM = polylineLength(path);
            s.timeS = route::flightTimeS(path, model);
            ap.sorties.push_back(s);
            plan.warnings.push_back(who + ": no home point, so no transit and no endurance check");
        }
        ap.localWaypoints = flown;
        ap.timeS = 0.0;
        ap.flightDistanceM = 0.0;
        for (auto& s : ap.sorties) {
            ap.timeS += s.timeS;
            ap.flightDistanceM += s.lengthM;
            for (int i = s.firstWaypoint; i <= s.lastWaypoint; ++i)
                s.photos += flown[static_cast<std::size_t>(i)].kind == route::WaypointKind::Photo;
        }
        ap.route.waypoints.clear();
        for (const auto& w : flown) {
            ap.route.waypoints.push_back({frame.toGeo(w.pos), ap.altitudeM, w.headingDeg, w.kind});
            if (w.kind == route::WaypointKind::Photo)
                photoFootprints.push_back(
                    {w.pos, w.headingDeg, ap.footprint.real.longSideM, ap.footprint.real.shortSideM});
        }
        ap.sortieRoutes.clear();
        for (const auto& s : ap.sorties) {
            route::Route r = ap.route;
            r.waypoints.assign(ap.route.waypoints.begin() + s.firstWaypoint,
                               ap.route.waypoints.begin() + s.lastWaypoint + 1);
            ap.sortieRoutes.push_back(std::move(r));
        }
        ap.metrics.photos = static_cast<int>(std::count_if(flown.begin(), flown.end(), [](const auto& w) {
            return w.kind == route::WaypointKind::Photo;
        }));
        ap.flight = plan::flightTime(path, model);
        flownPaths.push_back(std::move(path));
    }

    // 4b. Terrain following (terrain_stage.h): altitudes above the ground, legs checked, waypoints
    // inserted where the ground rises, times with the climbs, each photo's footprint on the terrain.
    std::vector<geo::Ring> terrainOutlines;
    if (m.terrain.prepared)
        if (auto t = applyTerrain(plan, m, frame, homes, landing, photoFootprints, terrainOutlines); !t)
            return t.error();

    // 5. Altitude separation between aircraft in the air together.
    if (n > 1) {
        std::vector<fleet::AltitudeSlot> slots;
        for (std::size_t k = 0; k < n; ++k)
            slots.push_back({m.aircraft[k].name, plan.aircraft[k].altitudeM, m.aircraft[k].maxAltitudeM, 0.0,
                             plan.aircraft[k].timeS});
        const fleet::AltitudeCheck alt = fleet::checkAltitudeSeparation(slots, opt.altitudeSeparationM);
        plan.altitudeConflicts = static_cast<int>(alt.conflicts.size());
        for (const auto& w : alt.warnings)
            plan.warnings.push_back(w);
    }

    // 6. The independent check: real footprints of every photo of every aircraft, margin breaches.
    if (check) {
        auto cov = plan::checkCoverage(admissible, photoFootprints, {}, m.terrain.prepared ? &terrainOutlines : nullptr);
        if (!cov)
            return makeError(cov.error().code, "checking the coverage: " + cov.error().message);
        plan.coverageRatio = cov->coveredFraction;
        plan.uncoveredAreaM2 = cov->uncoveredAreaM2;
        for (const auto& p : cov->patches)
            plan.uncovered.push_back({p.shape, p.areaM2});
        if (cov->coveredFraction < kCoverageTarget)
            plan.warnings.push_back("the photos leave " + metres(cov->uncoveredAreaM2) + " m2 of the area (" +
                                    metres(100.0 * (1.0 - cov->coveredFraction), 1) + " %) unseen, in " +
                                    std::to_string(cov->patchCount) + " patch(es)");
        geo::MultiPolygon pockets;
        for (const auto& a : plan.aircraft)
            pockets.insert(pockets.end(), a.grid.pockets().begin(), a.grid.pockets().end());
        if (!pockets.empty())
            plan.warnings.push_back(pocketWarning(geo::unite(pockets)));
        plan.noFlyViolations = plan::countNoFlyViolations(flownPaths, geom->noFly, opt.safetyMarginM).total();
        if (plan.noFlyViolations > 0)
            plan.warnings.push_back(std::to_string(plan.noFlyViolations) +
                                    " waypoint(s) or leg(s) come closer to a no-fly zone than the safety margin");
    }

    PlanTotals& t = plan.totals;
    double sumTime = 0.0;
    for (const auto& a : plan.aircraft) {
        ++t.aircraft;
        t.cells += a.metrics.cells;
        t.visitable += a.metrics.visitable;
        t.photos += a.metrics.photos;
        t.pathLengthM += a.metrics.pathLengthM;
        t.distanceM += a.metrics.distanceM;
        t.turns += a.metrics.turns;
        t.flightTurns += a.flight.turns;
        t.turnAngleDeg += a.metrics.turnAngleDeg;
        t.jumps += a.metrics.jumps;
        t.revisits += a.metrics.revisits;
        t.estimatedTimeS = std::max(t.estimatedTimeS, a.metrics.estimatedTimeS);
        t.planningMs += a.metrics.planningMs;
        plan.makespanS = std::max(plan.makespanS, a.timeS);
        sumTime += a.timeS;
    }
    plan.idealS = sumTime / static_cast<double>(n);
    if (t.jumps > 0) {
        int detours = 0;
        for (const auto& a : plan.aircraft)
            detours += a.detours;
        plan.warnings.push_back(std::to_string(t.jumps) +
                                " leg(s) join parts of an aircraft's area that no grid move connects (a no-fly "
                                "zone or its margin separates them): they are flown straight where that is safe, "
                                "else around the margins (" + std::to_string(detours) + " detour(s) in all)");
    }
    return plan;
}

} // namespace

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

CPLJSONArray ringCoords(const geo::Ring& r, const geo::LocalFrame& frame) {
    CPLJSONArray a;
    for (const auto& v : r)
        a.Add(position(frame.toGeo(v)));
    if (!r.empty())
        a.Add(position(frame.toGeo(r.front()))); // GeoJSON rings are closed
    return a;
}

// A local MultiPolygon as a WGS84 GeoJSON MultiPolygon geometry.
CPLJSONObject multiPolygonGeometry(const geo::MultiPolygon& mp, const geo::LocalFrame& frame) {
    CPLJSONObject g;
    g.Add("type", "MultiPolygon");
    CPLJSONArray polys;
    for (const auto& poly : mp) {
        CPLJSONArray rings;
        rings.Add(ringCoords(poly.outer, frame));
        for (const auto& h : poly.holes)
            rings.Add(ringCoords(h, frame));
        polys.Add(rings);
    }
    g.Add("coordinates", polys);
    return g;
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
        for (std::size_t i = 0; i < a.route.waypoints.size(); ++i) {
            coords.Add(position(a.route.waypoints[i].position));
            // Between two sorties the aircraft lands at home for a fresh battery.
            const bool sortieEnds = std::any_of(a.sorties.begin(), a.sorties.end() - (a.sorties.empty() ? 0 : 1),
                                                [&](const SortieSummary& s) { return s.lastWaypoint == static_cast<int>(i); });
            if (a.route.home && sortieEnds)
                coords.Add(position(*a.route.home));
        }
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
            if (w.groundM && a.route.homeElevationM) { // terrain following
                p.Add("ground_m", *w.groundM);
                p.Add("alt_amsl_m", *a.route.homeElevationM + w.altitudeM);
            }
            p.Add("kind", "photo");
            p.Add("heading_deg", w.headingDeg);
            p.Add("footprint_across_m", a.footprint.real.longSideM);
            p.Add("footprint_along_m", a.footprint.real.shortSideM);
            f.Add("properties", p);
            CPLJSONObject g;
            g.Add("type", "Point");
            g.Add("coordinates", position(w.position));
            f.Add("geometry", g);
            features.Add(f);
        }
    }
    if (plan.frame) {
        for (const auto& a : plan.aircraft) {
            if (a.subarea.empty())
                continue;
            CPLJSONObject f;
            f.Add("type", "Feature");
            CPLJSONObject p;
            p.Add("aircraft", a.aircraft);
            p.Add("kind", "subarea");
            f.Add("properties", p);
            f.Add("geometry", multiPolygonGeometry(a.subarea, *plan.frame));
            features.Add(f);
        }
        for (const auto& u : plan.uncovered) {
            CPLJSONObject f;
            f.Add("type", "Feature");
            CPLJSONObject p;
            p.Add("kind", "uncovered");
            p.Add("area_m2", u.areaM2);
            f.Add("properties", p);
            f.Add("geometry", multiPolygonGeometry(u.shape, *plan.frame));
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
    if (!plan.plannerChoice.empty())
        root.Add("planner_choice", plan.plannerChoice);
    CPLJSONArray list;
    for (const auto& a : plan.aircraft) {
        CPLJSONObject o;
        o.Add("name", a.aircraft);
        o.Add("planner", mission::plannerKindInfo(a.planner).id);
        if (!a.plannerChoice.empty())
            o.Add("planner_choice", a.plannerChoice);
        o.Add("altitude_m", a.altitudeM);
        o.Add("cell_size_m", a.cellSizeM);
        o.Add("grid_angle_deg", a.gridAngleDeg);
        o.Add("angles_tried", a.anglesTried);
        addMetrics(o, a.metrics);
        o.Add("time_s", a.timeS);
        o.Add("flight_distance_m", a.flightDistanceM);
        o.Add("flight_turns", a.flight.turns);
        o.Add("flight_turn_angle_deg", a.flight.turnAngleDeg);
        o.Add("sorties", static_cast<int>(a.sorties.size()));
        CPLJSONArray sorties;
        for (const auto& s : a.sorties) {
            CPLJSONObject so;
            so.Add("first_waypoint", s.firstWaypoint);
            so.Add("last_waypoint", s.lastWaypoint);
            so.Add("photos", s.photos);
            so.Add("length_m", s.lengthM);
            so.Add("time_s", s.timeS);
            sorties.Add(so);
        }
        o.Add("sortie_list", sorties);
        o.Add("photos_saved", a.photosSaved);
        o.Add("detours", a.detours);
        o.Add("waypoints_moved", a.waypointsMoved);
        o.Add("kept_inside", a.keptInside);
        o.Add("footprint_across_m", a.footprint.real.longSideM);
        o.Add("footprint_along_m", a.footprint.real.shortSideM);
        if (a.terrain.active) { // terrain following (terrain_stage.h)
            CPLJSONObject t;
            t.Add("height_above_ground_m", a.terrain.heightAboveGroundM);
            t.Add("planning_height_m", a.terrain.planningHeightM);
            t.Add("home_ground_m", a.terrain.homeGroundM);
            t.Add("lowest_clearance_m", a.terrain.lowestClearanceM);
            t.Add("waypoints_inserted", a.terrain.waypointsInserted);
            t.Add("gsd_cm", a.terrain.gsdCm);
            t.Add("coarsest_gsd_cm", a.terrain.coarsestGsdCm);
            o.Add("terrain", t);
        }
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
    total.Add("flight_turns", t.flightTurns);
    total.Add("turn_angle_deg", t.turnAngleDeg);
    total.Add("jumps", t.jumps);
    total.Add("revisits", t.revisits);
    total.Add("estimated_time_s", t.estimatedTimeS);
    total.Add("planning_ms", t.planningMs);
    total.Add("makespan_s", plan.makespanS);
    total.Add("ideal_s", plan.idealS);
    total.Add("makespan_ratio", plan.idealS > 0 ? plan.makespanS / plan.idealS : 1.0);
    total.Add("coverage_ratio", plan.coverageRatio);
    total.Add("uncovered_m2", plan.uncoveredAreaM2);
    total.Add("nofly_violations", plan.noFlyViolations);
    total.Add("photos_saved", plan.photosSaved);
    total.Add("altitude_conflicts", plan.altitudeConflicts);
    int sortieCount = 0;
    for (const auto& a : plan.aircraft)
        sortieCount += static_cast<int>(a.sorties.size());
    total.Add("sorties", sortieCount);
    root.Add("total", total);
    // Also at the top level, where the plan-wide checks are looked for first.
    root.Add("coverage_ratio", plan.coverageRatio);
    root.Add("nofly_violations", plan.noFlyViolations);
    root.Add("makespan_s", plan.makespanS);
    CPLJSONArray warnings;
    for (const auto& w : plan.warnings)
        warnings.Add(w);
    root.Add("warnings", warnings);
    return doc.SaveAsString();
}

} // namespace pf::mission
