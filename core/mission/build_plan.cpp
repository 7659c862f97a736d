#include "core/mission/build_plan.h"

#include "core/fleet/aircraft.h"
#include "core/fleet/altitude.h"
#include "core/fleet/photo_dedup.h"
#include "core/geo/polygon_ops.h"
#include "core/job_scope.h"
#include "core/mission/double_grid.h"
#include "core/mission/oblique.h"
#include "core/mission/plan_messages.h"
#include "core/mission/plan_region.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/terrain_stage.h"
#include "core/plan/coverage_check.h"
#include "core/plan/planner.h"
#include "core/route/photo_waypoints.h"
#include "core/route/safety.h"
#include "core/route/sorties.h"
#include "core/route/transit.h"
#include "core/sensor/footprint.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <string>

namespace pf::mission::detail {

namespace {

// planRegion for aircraft k, moving the progress through its own part of [0, 0.6], its name before
// the stage (with several aircraft).
Result<AircraftPlan> planAircraftRegion(const Mission& m, const PlannerOptions& opt,
                                        const LocalGeometry& geom,
                                        const std::vector<geo::MultiPolygon>& regions,
                                        const std::vector<std::optional<geo::Vec2>>& homes,
                                        const std::optional<geo::Vec2>& landing, std::size_t k) {
    const std::size_t n = m.aircraft.size();
    const std::string who = n == 1
                                ? std::string()
                                : (m.aircraft[k].name.empty() ? "aircraft " + std::to_string(k + 1)
                                                              : m.aircraft[k].name) +
                                      ": ";
    JobScope part(0.6 * static_cast<double>(k) / static_cast<double>(n),
                  0.6 * static_cast<double>(k + 1) / static_cast<double>(n), who);
    return planRegion(regions[k], geom.noFly, m.aircraft[k], opt, homes[k], landing,
                      laneSpacing(m, k));
}

// Every aircraft's region planned, each but the first on a thread of its own beside this one. The
// regions are planned independently (the core keeps no shared mutable state, and planRegion leaves
// the frame's transformation alone), so the plans are those made one after the other, in about 1/n
// of the wall time on as many cores: a fleet plan plans its regions once per split tried and once
// more for the split chosen. Every thread started is joined before this returns, whatever the
// outcome; a cancelled job stops each of them.
std::vector<Result<AircraftPlan>> planRegions(const Mission& m, const PlannerOptions& opt,
                                              const LocalGeometry& geom,
                                              const std::vector<geo::MultiPolygon>& regions,
                                              const std::vector<std::optional<geo::Vec2>>& homes,
                                              const std::optional<geo::Vec2>& landing,
                                              const RegionPlanner& planner) {
    std::vector<Result<AircraftPlan>> out;
    if (planner) { // a planner of the caller's (a corridor's stretches): one after the other
        for (std::size_t k = 0; k < m.aircraft.size(); ++k)
            out.push_back(planner(k, regions[k]));
        return out;
    }
    const JobScope::Share job = JobScope::share();
    std::vector<std::future<Result<AircraftPlan>>> others;
    for (std::size_t k = 1; k < m.aircraft.size(); ++k)
        others.push_back(std::async(std::launch::async, [&, k] {
            JobScope scope(job);
            return planAircraftRegion(m, opt, geom, regions, homes, landing, k);
        }));
    // Should this throw (out of memory), the futures' destructors still wait for their threads.
    out.push_back(planAircraftRegion(m, opt, geom, regions, homes, landing, 0));
    for (auto& f : others)
        out.push_back(f.get());
    return out;
}

// Step 2: every aircraft's region planned, each plan keeping its home, its region and its survey
// part (and, when asked, the time it would fly alone).
Status planEachAircraft(MissionPlan& plan, const Mission& m, const PlannerOptions& opt,
                        const LocalGeometry& geom, const std::vector<geo::MultiPolygon>& regions,
                        const std::vector<std::optional<geo::Vec2>>& homes,
                        const std::optional<geo::Vec2>& landing, std::vector<double>* aloneTimes,
                        const RegionPlanner& planner) {
    const std::size_t n = m.aircraft.size();
    for (std::size_t k = 0; k < n; ++k)
        if (regions[k].empty())
            return makeError(ErrorCode::InvalidInput,
                             aircraftLabel(m.aircraft[k]) +
                                 ": got no part of the area (too many aircraft for it)");
    std::vector<Result<AircraftPlan>> planned =
        planRegions(m, opt, geom, regions, homes, landing, planner);
    for (std::size_t k = 0; k < n; ++k) {
        if (stopRequested())
            return cancelledError();
        Result<AircraftPlan>& ap = planned[k];
        if (!ap)
            return ap.error();
        if (homes[k])
            ap->route.home = geom.frame.toGeo(*homes[k]);
        ap->subarea = regions[k];
        ap->surveyWaypoints = surveyPart(ap->localWaypoints);
        if (aloneTimes)
            aloneTimes->push_back(
                aloneRouteTimeS(ap->surveyWaypoints, m.aircraft[k], homes[k], landing));
        plan.aircraft.push_back(std::move(*ap));
    }
    return {};
}

// Step 3 (several aircraft): the photos of ground another aircraft already takes dropped.
Status dropSharedPhotos(MissionPlan& plan, const PlannerOptions& opt) {
    std::vector<fleet::AircraftPhotos> photos;
    for (const auto& a : plan.aircraft)
        photos.push_back({a.surveyWaypoints, a.footprint.acrossM, a.footprint.alongM,
                          a.footprint.real.longSideM, a.footprint.real.shortSideM});
    auto saved =
        opt.doubleGrid ? dropDuplicatePhotosPerPass(photos) : fleet::dropDuplicatePhotos(photos);
    if (!saved)
        return saved.error();
    for (std::size_t k = 0; k < plan.aircraft.size(); ++k) {
        plan.aircraft[k].surveyWaypoints = std::move(photos[k].waypoints);
        plan.aircraft[k].photosSaved = saved->photosSaved[k];
        // Where dropped photos leave only turn and transit points between two photos, fly straight.
        if (saved->photosSaved[k] > 0)
            route::straightenTransits(plan.aircraft[k].grid, plan.aircraft[k].surveyWaypoints);
    }
    plan.photosSaved = saved->totalSaved;
    return {};
}

// What step 4 flies every aircraft over: the frame, the area, its ground outside the zones, and
// the finders of safe legs.
struct FlightGround {
    FlightGround(const LocalGeometry& geom, const PlannerOptions& opt)
        : frame(geom.frame), area{geom.area},
          admissible(geom.noFly.empty() ? area : geo::difference(geom.area, geom.noFly)),
          safeFinder(route::NoFlyField(geom.noFly, opt.safetyMarginM)) {}

    const geo::LocalFrame& frame;
    const geo::MultiPolygon area;
    const geo::MultiPolygon admissible;
    const route::SafePathFinder safeFinder;
    // The lawnmower flies what a ground station's Survey flies: straight over the zones, from and
    // back to home too. Nothing makes it safe; the route check reports every crossing.
    const route::SafePathFinder straightFinder;
};

// What the checks after step 4 need of every flight: its path and its photos.
struct FlownPhotos {
    std::vector<std::vector<geo::Vec2>> paths;
    std::vector<plan::PhotoFootprint> footprints;
    std::vector<int> passes; // parallel: a double grid's pass of each photo
};

// The aircraft's flown route as it is being made: its waypoints, and its path (home, every
// waypoint, landing) for the flight time and the margin check.
struct Flight {
    std::vector<route::LocalWaypoint> waypoints;
    std::vector<geo::Vec2> path;
};

// Step 4's safety: the survey (a copy of the aircraft's) pulled inside the area (multirotors),
// oblique photos moved back to where the aircraft takes them (oblique.h), kept out of the no-fly
// zones and rid of near duplicates; the aircraft's survey and its safety figures updated.
Status makeSurveySafe(MissionPlan& plan, AircraftPlan& ap, const AircraftConfig& cfg,
                      const PlannerOptions& opt, const FlightGround& ground,
                      const route::SafePathFinder& finder, bool yardstick, const std::string& who,
                      std::vector<route::LocalWaypoint>& survey) {
    route::SafetyReport rep;
    const double ahead = ap.footprint.real.aheadM;
    // A plane's turns cannot be pulled inside (its plan says so): only a multirotor's route is.
    // Oblique photos' centres are kept `ahead` further inside, so that the aircraft is inside.
    if (opt.keepInsideArea && !yardstick && !fleet::fliesAsPlane(cfg.kind)) {
        const route::PhotoSides sides{ap.footprint.acrossM, ap.footprint.alongM,
                                      ap.footprint.real.longSideM, ap.footprint.real.shortSideM};
        auto inside = route::keepInsideArea(survey, ground.area, ground.admissible, sides,
                                            opt.insideMarginM + ahead, finder, &rep);
        if (!inside)
            return makeError(inside.error().code, who + ": " + inside.error().message);
        survey = std::move(*inside);
    }
    if (const int out = moveToAircraft(survey, ahead, yardstick ? nullptr : &finder))
        rep.warnings.push_back(
            std::to_string(out) +
            " oblique photo(s) just past a no-fly zone, looking away from it, cannot be taken from "
            "straight behind their ground (the zone or its margin is in the way): taken from the "
            "nearest point outside the margin (the coverage check counts them as taken)");
    if (!yardstick) {
        auto safe = route::enforceNoFly(survey, finder, &rep);
        if (!safe)
            return makeError(safe.error().code, who + ": " + safe.error().message);
        survey = std::move(*safe);
    }
    // After the no-fly stage nothing repairs a leg: a waypoint is dropped only where the leg that
    // replaces it keeps the margin; an oblique photo's lead-in is added only where it keeps it.
    route::dropNearDuplicates(survey, yardstick ? nullptr : &finder.field());
    if (ahead > 0.0)
        leadOntoLanes(survey, yardstick ? nullptr : &finder.field());
    for (const auto& w : rep.warnings)
        plan.warnings.push_back(who + ": " + w);
    ap.detours = rep.detours;
    ap.waypointsMoved = rep.waypointsMoved;
    ap.keptInside = rep.keptInside;
    ap.surveyWaypoints = survey;
    return {};
}

// One flight landing elsewhere: out from home, back to the landing point.
Status flyToLanding(AircraftPlan& ap, const std::vector<route::LocalWaypoint>& survey,
                    const geo::Vec2& home, const geo::Vec2& landing,
                    const route::SafePathFinder& finder, const route::FlightModel& model,
                    const std::string& who, Flight& flight) {
    auto t = route::withTransit(survey, home, finder, landing);
    if (!t)
        return makeError(t.error().code, who + ": " + t.error().message);
    std::vector<geo::Vec2> poly{home};
    for (const auto& w : *t)
        poly.push_back(w.pos);
    poly.push_back(landing);
    SortieSummary s;
    s.firstWaypoint = 0;
    s.lastWaypoint = static_cast<int>(t->size()) - 1;
    s.lengthM = polylineLength(poly);
    s.timeS = route::flightTimeS(poly, model);
    flight.waypoints = std::move(*t);
    ap.sorties.push_back(s);
    return {};
}

// The sorties flown one after the other through home, with a note when it takes several batteries.
void joinSorties(MissionPlan& plan, AircraftPlan& ap, const route::SortiePlan& sp,
                 const geo::Vec2& home, const std::string& who, Flight& flight) {
    std::vector<route::LocalWaypoint>& flown = flight.waypoints;
    for (const auto& s : sp.sorties) {
        // Between two sorties the route flies through home (where the battery is changed): a
        // straight leg from one sortie's last waypoint to the next one's first is never flown, and
        // may cross a zone, yet the whole route (its check, the map, the one file for the
        // aircraft) would join them.
        if (!flown.empty())
            flown.push_back({home, route::headingDeg(home, s.waypoints.front().pos),
                             route::WaypointKind::Transit, -1});
        SortieSummary sum;
        sum.firstWaypoint = static_cast<int>(flown.size());
        flown.insert(flown.end(), s.waypoints.begin(), s.waypoints.end());
        sum.lastWaypoint = static_cast<int>(flown.size()) - 1;
        sum.lengthM = s.lengthM;
        sum.timeS = s.timeS;
        ap.sorties.push_back(sum);
    }
    if (sp.sorties.size() > 1)
        plan.notes.push_back(who + ": the flight needs " + std::to_string(sp.sorties.size()) +
                             " batteries (sorties returning home), " +
                             metres(sp.totalTimeS / 60.0, 1) + " min in all for " +
                             metres(sp.budgetS / 60.0, 1) + " min per battery");
}

// The flight from home: cut into sorties that fit the battery (or one flight to the landing
// point), its path through home between sorties.
Status flyFromHome(MissionPlan& plan, AircraftPlan& ap, const AircraftConfig& cfg,
                   const PlannerOptions& opt, const std::vector<route::LocalWaypoint>& survey,
                   const geo::Vec2& home, const std::optional<geo::Vec2>& landing,
                   const route::SafePathFinder& finder, const route::FlightModel& model,
                   const std::string& who, Flight& flight) {
    if (stopRequested())
        return cancelledError();
    auto sp = route::splitIntoSorties(survey, home, finder, model,
                                      route::SortieOptions{cfg.enduranceMin, opt.batteryReserve},
                                      cfg.name);
    if (!sp)
        return makeError(sp.error().code, who + ": " + sp.error().message);
    if (sp->sorties.size() == 1 && landing && (*landing - home).norm() > 1e-6) {
        if (auto s = flyToLanding(ap, survey, home, *landing, finder, model, who, flight); !s)
            return s;
    } else {
        joinSorties(plan, ap, *sp, home, who, flight);
    }
    // Every sortie starts and ends at home: the legs between sorties are flown through it.
    flight.path.push_back(home);
    for (std::size_t si = 0; si < ap.sorties.size(); ++si) {
        for (int i = ap.sorties[si].firstWaypoint; i <= ap.sorties[si].lastWaypoint; ++i)
            flight.path.push_back(flight.waypoints[static_cast<std::size_t>(i)].pos);
        if (si + 1 < ap.sorties.size())
            flight.path.push_back(home);
    }
    flight.path.push_back(ap.sorties.size() == 1 && landing ? *landing : home);
    return {};
}

// No home: the survey alone, one flight; no transit to check.
void flyWithoutHome(MissionPlan& plan, AircraftPlan& ap,
                    const std::vector<route::LocalWaypoint>& survey,
                    const route::FlightModel& model, const std::string& who, Flight& flight) {
    flight.waypoints = survey;
    for (const auto& w : flight.waypoints)
        flight.path.push_back(w.pos);
    SortieSummary s;
    s.lastWaypoint = static_cast<int>(flight.waypoints.size()) - 1;
    s.lengthM = polylineLength(flight.path);
    s.timeS = route::flightTimeS(flight.path, model);
    ap.sorties.push_back(s);
    plan.warnings.push_back(who + ": no home point, so no transit and no endurance check");
}

// One route per sortie, beside the whole route.
void cutSortieRoutes(AircraftPlan& ap) {
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
}

// The flight made the aircraft's route: its times, distance and photos per sortie, its waypoints
// on the map, its photos and path kept for the checks.
Status recordFlight(AircraftPlan& ap, const geo::LocalFrame& frame, const route::FlightModel& model,
                    Flight& flight, FlownPhotos& flown) {
    const std::vector<route::LocalWaypoint>& wps = flight.waypoints;
    ap.localWaypoints = wps;
    ap.timeS = 0.0;
    ap.flightDistanceM = 0.0;
    for (auto& s : ap.sorties) {
        ap.timeS += s.timeS;
        ap.flightDistanceM += s.lengthM;
        for (int i = s.firstWaypoint; i <= s.lastWaypoint; ++i)
            s.photos += wps[static_cast<std::size_t>(i)].kind == route::WaypointKind::Photo;
    }
    ap.route.waypoints = routeWaypoints(wps, frame, ap.altitudeM);
    if (stopRequested())
        return cancelledError();
    for (const auto& w : wps)
        if (w.kind == route::WaypointKind::Photo) {
            flown.footprints.push_back(
                sensor::photoTakenFrom(w.pos, w.headingDeg, ap.footprint.real));
            flown.passes.push_back(w.pass);
        }
    cutSortieRoutes(ap);
    ap.metrics.photos = static_cast<int>(std::count_if(wps.begin(), wps.end(), [](const auto& w) {
        return w.kind == route::WaypointKind::Photo;
    }));
    ap.flight = plan::flightTime(flight.path, model);
    flown.paths.push_back(std::move(flight.path));
    return {};
}

// Step 4 for aircraft k: its survey made safe, flown from home in sorties (or alone), recorded.
Status finishFlight(MissionPlan& plan, std::size_t k, const Mission& m, const PlannerOptions& opt,
                    const FlightGround& ground, const std::vector<std::optional<geo::Vec2>>& homes,
                    const std::optional<geo::Vec2>& landing, bool check, FlownPhotos& flown) {
    const std::size_t n = m.aircraft.size();
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
    const route::SafePathFinder& finder = yardstick ? ground.straightFinder : ground.safeFinder;
    std::vector<route::LocalWaypoint> survey = ap.surveyWaypoints;
    if (auto s = makeSurveySafe(plan, ap, cfg, opt, ground, finder, yardstick, who, survey); !s)
        return s;

    const route::FlightModel model = flightModel(cfg);
    Flight flight;
    if (const auto& home = homes[k]) {
        if (auto s =
                flyFromHome(plan, ap, cfg, opt, survey, *home, landing, finder, model, who, flight);
            !s)
            return s;
    } else {
        flyWithoutHome(plan, ap, survey, model, who, flight);
    }
    return recordFlight(ap, ground.frame, model, flight, flown);
}

// Step 5 (several aircraft): altitude separation between aircraft in the air together.
void separateAltitudes(MissionPlan& plan, const Mission& m, const PlannerOptions& opt,
                       const std::vector<std::optional<geo::Vec2>>& homes) {
    std::vector<fleet::AltitudeSlot> slots;
    for (std::size_t k = 0; k < m.aircraft.size(); ++k)
        slots.push_back({m.aircraft[k].name, plan.aircraft[k].altitudeM, m.aircraft[k].maxAltitudeM,
                         0.0, plan.aircraft[k].timeS});
    const fleet::AltitudeCheck alt = fleet::checkAltitudeSeparation(slots, opt.altitudeSeparationM);
    plan.altitudeConflicts = static_cast<int>(alt.conflicts.size());
    addAltitudeMessages(plan, alt, slots, opt.altitudeSeparationM, homes);
}

// Step 6's figures on the plan: the real footprints of every photo of every aircraft laid over
// the admissible ground, the unseen patches, the pockets no path leads into, the margin breaches.
Status checkPlan(MissionPlan& plan, const Mission& m, const PlannerOptions& opt,
                 const LocalGeometry& geom, const geo::MultiPolygon& admissible,
                 const FlownPhotos& flown, const std::vector<geo::Ring>& terrainOutlines) {
    reportProgress(0.85, "coverage check");
    JobScope stage(0.85, 1.0);
    const auto* outlines = m.terrain.prepared ? &terrainOutlines : nullptr;
    // A double grid's passes are checked one by one: every point must be seen twice.
    auto cov = opt.doubleGrid ? checkPassCoverage(admissible, flown.footprints, flown.passes,
                                                  outlines, plan.passCoverage)
                              : plan::checkCoverage(admissible, flown.footprints, {}, outlines);
    if (stopRequested())
        return cancelledError();
    if (!cov)
        return makeError(cov.error().code, "checking the coverage: " + cov.error().message);
    plan.coverageRatio = cov->coveredFraction;
    plan.uncoveredAreaM2 = cov->uncoveredAreaM2;
    plan.uncoveredPatchCount = cov->patchCount;
    for (const auto& p : cov->patches)
        plan.uncovered.push_back({p.shape, p.areaM2});
    attributeUncovered(plan, geom.noFly);
    if (cov->coveredFraction < kCoverageTarget)
        plan.warnings.push_back(std::string(opt.doubleGrid ? "one pass of the double grid: " : "") +
                                uncoveredMessage(plan));
    geo::MultiPolygon pockets;
    for (const auto& a : plan.aircraft)
        pockets.insert(pockets.end(), a.grid.pockets().begin(), a.grid.pockets().end());
    if (!pockets.empty())
        plan.warnings.push_back(pocketWarning(geo::unite(pockets)));
    plan.noFlyViolations =
        plan::countNoFlyViolations(flown.paths, geom.noFly, opt.safetyMarginM).total();
    if (plan.noFlyViolations > 0)
        plan.warnings.push_back(
            std::to_string(plan.noFlyViolations) +
            " waypoint(s) or leg(s) come closer to a no-fly zone than the safety margin");
    return {};
}

// The totals over the n aircraft, the makespan and the ideal time, and a double grid's choices.
void sumTotals(MissionPlan& plan, const PlannerOptions& opt, std::size_t n) {
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
    if (opt.doubleGrid) // say so whatever the planner: its passes
        for (const auto& a : plan.aircraft)
            plan.plannerChoice += (plan.plannerChoice.empty() ? "" : "; ") +
                                  (n > 1 ? a.aircraft + ": " : "") + a.plannerChoice;
}

// A warning for the legs that join parts of an aircraft's area no grid move connects.
void warnJumps(MissionPlan& plan) {
    if (plan.totals.jumps <= 0)
        return;
    int detours = 0;
    for (const auto& a : plan.aircraft)
        detours += a.detours;
    plan.warnings.push_back(
        std::to_string(plan.totals.jumps) +
        " leg(s) join parts of an aircraft's area that no grid move connects (a no-fly "
        "zone or its margin separates them): they are flown straight where that is safe, "
        "else around the margins (" +
        std::to_string(detours) + " detour(s) in all)");
}

} // namespace

Result<MissionPlan> buildPlan(const Mission& m, const PlannerOptions& opt,
                              const LocalGeometry& geom,
                              const std::vector<geo::MultiPolygon>& regions,
                              const std::vector<std::optional<geo::Vec2>>& homes,
                              const std::optional<geo::Vec2>& landing, bool check,
                              std::vector<double>* aloneTimes, const RegionPlanner& planner) {
    const std::size_t n = m.aircraft.size();
    MissionPlan plan;
    plan.frame = geom.frame;

    // 2. Each aircraft over its region.
    if (auto s = planEachAircraft(plan, m, opt, geom, regions, homes, landing, aloneTimes, planner);
        !s)
        return s.error();

    // 3. No second photo of ground another aircraft already takes.
    if (n > 1)
        if (auto s = dropSharedPhotos(plan, opt); !s)
            return s.error();

    // 4. Safety, transit and sorties.
    const FlightGround ground(geom, opt);
    FlownPhotos flown;
    for (std::size_t k = 0; k < n; ++k)
        if (auto s = finishFlight(plan, k, m, opt, ground, homes, landing, check, flown); !s)
            return s.error();

    // 4b. Terrain following (terrain_stage.h): altitudes above the ground, legs checked,
    // waypoints inserted where the ground rises, times with the climbs, each photo's footprint on
    // the terrain.
    std::vector<geo::Ring> terrainOutlines;
    if (m.terrain.prepared)
        if (auto t = applyTerrain(plan, m, geom.frame, homes, landing, flown.footprints,
                                  terrainOutlines);
            !t)
            return t.error();

    // 5. Altitude separation between aircraft in the air together.
    if (n > 1)
        separateAltitudes(plan, m, opt, homes);

    // 6. The independent check: real footprints of every photo of every aircraft, margin breaches.
    if (stopRequested())
        return cancelledError();
    if (check)
        if (auto s = checkPlan(plan, m, opt, geom, ground.admissible, flown, terrainOutlines); !s)
            return s.error();

    sumTotals(plan, opt, n);
    warnJumps(plan);
    return plan;
}

} // namespace pf::mission::detail
