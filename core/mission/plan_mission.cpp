#include "core/mission/plan_mission.h"

#include "core/fleet/altitude.h"
#include "core/fleet/area_split.h"
#include "core/fleet/photo_dedup.h"
#include "core/geo/polygon_ops.h"
#include "core/job_scope.h"
#include "core/mission/memory_estimate.h"
#include "core/mission/plan_geojson.h"
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
#include <new>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace pf::mission {

namespace {

// The covered fraction of the admissible area below which a plan gets a warning.
constexpr double kCoverageTarget = 0.995;
// The makespan / ideal (total time / aircraft) a shared plan aims to stay within.
constexpr double kBalanceTarget = 1.10;

} // namespace

namespace {

Error cancelledError() { return makeError(ErrorCode::Cancelled, "planning cancelled"); }

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
    // With the automatic choice, the split is searched with stride's times (the split needs hundreds
    // of estimates; three planners each would triple them; stride's split gave the demo a shorter
    // makespan than raster's, 7.0 against 7.0 min for 0.59 against 0.82 s) and each aircraft's region
    // is then planned with the soonest of sweep, stride and raster (planRegion): no aircraft flies
    // longer than stride would make it fly there.
    PlannerOptions estimateOpt = opt;
    if (opt.planner == PlannerKind::Auto)
        estimateOpt.planner = PlannerKind::Stride;
    double estimateAngle = 0.0;
    if (opt.gridAngleDeg) {
        estimateAngle = *opt.gridAngleDeg;
    } else {
        std::size_t coarsest = 0;
        for (std::size_t k = 1; k < n; ++k)
            if (sensor::cellSizeFor(footprints[k]) > sensor::cellSizeFor(footprints[coarsest]))
                coarsest = k;
        auto whole = planRegion(geo::MultiPolygon{geom->area}, geom->noFly, m.aircraft[coarsest], estimateOpt, frame,
                                homes[coarsest], landing);
        if (!whole)
            return whole.error();
        estimateAngle = whole->gridAngleDeg;
    }
    PlannerOptions fixed = estimateOpt;
    fixed.gridAngleDeg = estimateAngle;
    // The plans the split's rounds make and measure (the mission's planner at the fixed angle): with
    // the automatic choice each aircraft's region is planned with its soonest planner, and the
    // correction factors below carry that back into the split.
    PlannerOptions fixedPlan = opt;
    fixedPlan.gridAngleDeg = estimateAngle;
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
                if (stopRequested())
                    return cancelledError(); // the split stops at its next estimate
                const std::size_t k = order[static_cast<std::size_t>(i)];
                auto t = rawEstimate(k, sub);
                if (!t)
                    return t;
                return *t * factor[k];
            };
            if (stopRequested())
                return cancelledError();
            auto split = fleet::splitArea(geom->area, geom->noFly, ordered, so, estimate);
            if (!split)
                return makeError(split.error().code,
                                 "sharing the area between the aircraft: " + split.error().message);
            std::vector<geo::MultiPolygon> regions(n);
            for (std::size_t i = 0; i < n; ++i)
                regions[order[i]] = std::move(split->subareas[i]);
            std::vector<double> alone; // the estimate of each subarea, as the plan made it
            auto p = buildPlan(m, fixedPlan, *geom, regions, homes, landing, false, &alone);
            if (!p)
                return p.error();
            // With the automatic choice the estimate is stride's, the plan another planner's: the
            // factor is taken against the estimate itself.
            if (opt.planner == PlannerKind::Auto)
                for (std::size_t k = 0; k < n; ++k) {
                    auto t = rawEstimate(k, regions[k]);
                    if (!t)
                        return t.error();
                    alone[k] = *t;
                }
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
        if (stopRequested())
            return cancelledError();
        auto chosen = buildPlan(m, opt, *geom, c.regions, homes, landing, true);
        if (!chosen)
            return chosen.error();
        if (!opt.gridAngleDeg && chosen->makespanS > c.makespanS) {
            chosen = buildPlan(m, fixedPlan, *geom, c.regions, homes, landing, true);
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

// The automatic choice is made per aircraft, over its own region, by planRegion: sweep, stride and
// raster each plan it and the one flown soonest home to home is kept (its reason in
// AircraftPlan::plannerChoice). With several aircraft the split is searched with stride's times
// (see planMissionWith), so each aircraft flies no longer than stride would make it fly there; the
// whole mission planned with each planner in turn was measured as well: on the demo the same
// makespan (7.0 min) for 3.4 times the planning time (2.0 s against 0.59 s CPU).
namespace {

Result<MissionPlan> planMissionChecked(const Mission& m, Progress* progress);

} // namespace

Result<MissionPlan> planMission(const Mission& m, Progress* progress) {
    // The estimate refuses what cannot fit before anything large is allocated; should it be wrong,
    // running out of memory is still a refusal with advice, not an internal error.
    try {
        return planMissionChecked(m, progress);
    } catch (const std::bad_alloc&) {
        const MemoryEstimate e = estimatePlanMemory(m);
        return makeError(ErrorCode::TooLarge,
                         "the plan ran out of memory (it needs about " + metres(e.bytes / 1e9, 1) + " GB for " +
                             metres(e.cells) + " grid cells and about " + metres(e.photos) +
                             " photos): fly higher, use a larger cell or split the area into parts");
    }
}

namespace {

Result<MissionPlan> planMissionChecked(const Mission& m, Progress* progress) {
    // Terrain following: the DEM read once, then planned over it (terrain_stage.h).
    if (needsTerrainStage(m))
        return planOverTerrain(m, [progress](const Mission& over) { return planMissionChecked(over, progress); });
    JobScope scope(progress);
    const std::size_t budget = memoryBudgetBytes();
    if (auto fits = checkPlanMemory(m, budget); !fits)
        return fits.error();
    Mission one = m;
    std::string why;
    // The automatic choice holds two plans of a region at once (the soonest so far and the next);
    // where only one fits, stride alone plans it, and the choice says why.
    if (m.options.planner == PlannerKind::Auto && !checkPlanMemory(m, budget, 2).ok()) {
        one.options.planner = PlannerKind::Stride;
        why = "stride alone: comparing planners would need more memory than this machine has (" +
              metres(2.0 * estimatePlanMemory(m).bytes / 1e9, 1) + " GB)";
    }
    auto plan = planMissionWith(one);
    if (stopRequested())
        return cancelledError(); // whatever a loop broken off left behind is dropped
    if (!plan || m.options.planner != PlannerKind::Auto)
        return plan;
    std::string choice = why;
    if (choice.empty())
        for (const auto& a : plan->aircraft)
            choice += std::string(choice.empty() ? "" : "; ") + (plan->aircraft.size() > 1 ? a.aircraft + ": " : "") +
                      (a.plannerChoice.empty() ? plannerKindInfo(a.planner).id : a.plannerChoice);
    plan->plannerChoice = choice;
    return plan;
}

} // namespace

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
        if (stopRequested())
            return cancelledError();
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
        if (stopRequested())
            return cancelledError();
        reportProgress(check ? 0.6 + 0.25 * static_cast<double>(k) / static_cast<double>(n) : 0.6,
                       "detours and sorties");
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
        // After the no-fly stage nothing repairs a leg: a waypoint is dropped only where the leg that
        // replaces it keeps the margin.
        route::dropNearDuplicates(survey, yardstick ? nullptr : &finder.field());
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
            if (stopRequested())
                return cancelledError();
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
                    // Between two sorties the route flies through home (where the battery is changed): a
                    // straight leg from one sortie's last waypoint to the next one's first is never
                    // flown, and may cross a zone, yet the whole route (its check, the map, the one file
                    // for the aircraft) would join them.
                    if (!flown.empty())
                        flown.push_back({*home, route::headingDeg(*home, s.waypoints.front().pos),
                                         route::WaypointKind::Transit, -1});
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
        ap.route.waypoints = routeWaypoints(flown, frame, ap.altitudeM);
        if (stopRequested())
            return cancelledError();
        for (const auto& w : flown)
            if (w.kind == route::WaypointKind::Photo)
                photoFootprints.push_back(
                    {w.pos, w.headingDeg, ap.footprint.real.longSideM, ap.footprint.real.shortSideM});
        ap.sortieRoutes.clear();
        // Only the sortie's own waypoints are copied: a copy of the whole route per sortie (then cut)
        // kept its full capacity, sorties x waypoints in all (3.3 GB for 158 sorties of 523,000).
        std::vector<route::Waypoint> all = std::move(ap.route.waypoints);
        ap.route.waypoints.clear();
        for (const auto& s : ap.sorties) {
            route::Route r = ap.route; // everything but the waypoints
            r.waypoints.assign(all.begin() + s.firstWaypoint, all.begin() + s.lastWaypoint + 1);
            ap.sortieRoutes.push_back(std::move(r));
        }
        ap.route.waypoints = std::move(all);
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
    if (stopRequested())
        return cancelledError();
    if (check) {
        reportProgress(0.85, "coverage check");
        JobScope stage(0.85, 1.0);
        auto cov = plan::checkCoverage(admissible, photoFootprints, {}, m.terrain.prepared ? &terrainOutlines : nullptr);
        if (stopRequested())
            return cancelledError();
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
    std::ostringstream out;
    writePlanGeoJson(plan, out);
    return out.str();
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
