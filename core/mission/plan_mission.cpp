#include "core/mission/plan_mission.h"

#include "core/job_scope.h"
#include "core/mission/build_plan.h"
#include "core/mission/corridor.h"
#include "core/mission/fleet_plan.h"
#include "core/mission/memory_estimate.h"
#include "core/mission/oblique.h"
#include "core/mission/plan_corridor.h"
#include "core/mission/plan_geojson.h"
#include "core/mission/plan_region.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/route_check.h"
#include "core/mission/simplify_input.h"
#include "core/mission/terrain_stage.h"
#include "core/mission/validation.h"
#include "core/sensor/camera.h"

#include <future>
#include <new>
#include <string>
#include <vector>

namespace pf::mission {

namespace {

using namespace detail;

// planMission for one planner kind (never Auto).
Result<MissionPlan> planMissionWith(const Mission& m) {
    if (m.aircraft.empty())
        return makeError(ErrorCode::InvalidInput, "the mission has no aircraft: add one to plan a flight");
    auto geom = localGeometry(m);
    if (!geom)
        return geom.error();
    const geo::LocalFrame& frame = geom->frame;

    // Per aircraft: footprint (for the split) and home.
    std::vector<fleet::Capability> caps;
    std::vector<std::optional<geo::Vec2>> homes;
    for (const auto& a : m.aircraft) {
        auto alt = resolvedAltitude(a);
        if (!alt)
            return makeError(alt.error().code, aircraftLabel(a) + ": " + alt.error().message);
        auto eff = sensor::effectiveFootprint(a.camera, *alt, a.overlap);
        if (!eff)
            return makeError(eff.error().code, aircraftLabel(a) + ": " + eff.error().message);
        caps.push_back({a.name, *eff, flightModel(a)});
        const std::optional<geo::LonLat> h = a.home ? a.home : m.home;
        homes.push_back(h ? std::optional<geo::Vec2>(frame.toLocal(*h)) : std::nullopt);
    }
    std::optional<geo::Vec2> landing;
    if (m.landing)
        landing = frame.toLocal(*m.landing);

    // 1. Each aircraft's region: the whole area alone, else a time-balanced split (fleet_plan.h).
    if (m.aircraft.size() == 1)
        return buildPlan(m, m.options, *geom, {geo::MultiPolygon{geom->area}}, homes, landing,
                         true);
    return planFleet(FleetInput{m, *geom, std::move(caps), std::move(homes), landing});
}

} // namespace

// The automatic choice is made per aircraft, over its own region, by planRegion: sweep, stride and
// raster each plan it and the one flown soonest home to home is kept (its reason in
// AircraftPlan::plannerChoice). With several aircraft the split is searched with stride's times
// (see planMissionWith), so each aircraft flies no longer than stride would make it fly there; small
// missions are also planned with stride, sweep and raster alone (planMissionChecked), the soonest
// makespan kept.
namespace {

Result<MissionPlan> planMissionChecked(const Mission& m, Progress* progress);

// Missions up to this many photos (estimatePlanMemory) are also planned with one planner throughout
// under the automatic choice (see planMissionChecked): the demo needs about 300; planning it so takes
// about 2 s more there (sweep alone is the slowest to plan, its split searched on its own times).
constexpr double kWholeMissionRecheckPhotos = 2000.0;

// A planner that does not keep out of the no-fly zones (the lawnmower, the yardstick) says which
// zones its routes cross: they are flown straight over.
void warnOfZonesCrossed(const Mission& m, MissionPlan& plan) {
    const PlannerKindInfo& info = plannerKindInfo(m.options.planner);
    if (info.avoidsNoFly || m.noFlyZones.empty())
        return;
    const std::vector<std::string> zones = zonesEntered(m, plan);
    if (zones.empty())
        return;
    std::string names;
    for (std::size_t i = 0; i < zones.size(); ++i)
        names += (i == 0 ? "" : i + 1 == zones.size() ? " and " : ", ") + zones[i];
    plan.warnings.push_back(
        std::string("the ") + info.id + " planner flies straight over no-fly zone" +
        (zones.size() == 1 ? " " : "s ") + names +
        ": it ignores no-fly zones by design, as the yardstick the other planners are "
        "compared with; plan this mission with another planner (auto keeps out of them)");
}

} // namespace

Result<MissionPlan> planMission(const Mission& given, Progress* progress) {
    for (const auto& a : given.aircraft)
        if (auto e = cameraTiltError(given, a, detail::aircraftLabel(a)); !e.empty())
            return makeError(ErrorCode::InvalidInput, e);
    // A traced boundary of many thousand vertices is planned simplified (simplify_input.h), and the
    // plan says so. Every camera is pointed as the mission says (oblique.h): the footprints
    // planned, balanced and checked are those of the photos taken.
    const InputSimplification simple = given.options.cameraTiltDeg == 0.0
                                           ? simplifyInput(given) // no copy made to point nothing
                                           : simplifyInput(withPointedCameras(given));
    if (!simple.error.empty())
        return makeError(ErrorCode::TooLarge, simple.error);
    const Mission& m = simple.mission;
    // The estimate refuses what cannot fit before anything large is allocated; should it be wrong,
    // running out of memory is still a refusal with advice, not an internal error.
    try {
        auto plan = planMissionChecked(m, progress);
        if (plan && !simple.note.empty())
            plan->warnings.insert(plan->warnings.begin(), simple.note);
        return plan;
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
    if (plansCorridorLanes(m)) // lanes along the corridor: no planner to choose
        return planCorridorMission(m);
    Mission one = m;
    std::string why;
    // The automatic choice holds two plans of a region at once (the soonest so far and the next);
    // where only one fits, stride alone plans it, and the choice says why.
    if (m.options.planner == PlannerKind::Auto && !checkPlanMemory(m, budget, 2).ok()) {
        one.options.planner = PlannerKind::Stride;
        why = "stride alone: comparing planners would need more memory than this machine has (" +
              metres(2.0 * estimatePlanMemory(m).bytes / 1e9, 1) + " GB)";
    }
    // With several aircraft the split is searched on stride's times and then rebalanced on the chosen
    // planners' times, so the mission planned with one planner throughout (its split searched on its
    // own times) can finish sooner: on 44 two- and three-aircraft missions (the sample areas and 16
    // generated ones) stride alone finished sooner than the per-aircraft choice on 4, by up to 0.4
    // min. On missions small enough that planning them again costs seconds, stride, sweep and raster
    // alone are planned too and the soonest makespan is kept (never one that covers less or breaches
    // a margin more), so the automatic choice never flies longer than a planner it chose from. On a
    // larger mission the choice says that it compared per aircraft only.
    // The three single-planner plans are independent of the automatic one (each builds its own
    // geometry and frame; the core keeps no shared mutable state), so they run on their own threads
    // beside it where the memory allows: the choice is the same as planned one after the other, in
    // less wall time on two cores (the demo: 1.2 s of CPU in 0.76 s).
    const bool recheck = m.options.planner == PlannerKind::Auto && why.empty() && m.aircraft.size() > 1;
    const double photos = recheck ? estimatePlanMemory(m).photos : 0.0;
    const bool recheckFits = recheck && photos <= kWholeMissionRecheckPhotos && checkPlanMemory(m, budget, 2).ok();
    constexpr PlannerKind kAlone[] = {PlannerKind::Stride, PlannerKind::Sweep, PlannerKind::Raster};
    const auto planAlone = [&m](PlannerKind k) {
        Mission alone = m;
        alone.options.planner = k;
        return planMissionWith(alone);
    };
    std::vector<std::future<Result<MissionPlan>>> aloneRuns;
    if (recheckFits && checkPlanMemory(m, budget, 2 + std::size(kAlone)).ok()) {
        Progress* progress = JobScope::current();
        for (PlannerKind k : kAlone)
            aloneRuns.push_back(std::async(std::launch::async, [progress, k, &planAlone] {
                JobScope quiet(progress, JobScope::CancelOnly{});
                return planAlone(k);
            }));
    }
    auto plan = planMissionWith(one);
    // Every thread started is joined here, whatever the outcome (a cancelled job stops them too).
    std::vector<Result<MissionPlan>> alonePlans;
    for (auto& f : aloneRuns)
        alonePlans.push_back(f.get());
    if (stopRequested())
        return cancelledError(); // whatever a loop broken off left behind is dropped
    if (plan)
        warnOfZonesCrossed(m, *plan);
    if (!plan || m.options.planner != PlannerKind::Auto)
        return plan;
    std::string choice = why;
    if (choice.empty())
        for (const auto& a : plan->aircraft)
            choice += std::string(choice.empty() ? "" : "; ") + (plan->aircraft.size() > 1 ? a.aircraft + ": " : "") +
                      (a.plannerChoice.empty() ? plannerKindInfo(a.planner).id : a.plannerChoice);
    if (recheck && !recheckFits) {
        choice += " (compared per aircraft only: with about " + metres(photos) +
                  " photos, planning the whole mission with each planner as well would take too long)";
    } else if (recheckFits) {
        const std::string perAircraft = choice;
        const double perAircraftS = plan->makespanS;
        for (std::size_t i = 0; i < std::size(kAlone); ++i) {
            const PlannerKind k = kAlone[i];
            auto other = alonePlans.empty() ? planAlone(k) : std::move(alonePlans[i]);
            if (stopRequested())
                return cancelledError();
            if (!other || !(other->makespanS < plan->makespanS - 0.5) ||
                other->noFlyViolations > plan->noFlyViolations || other->coverageRatio < plan->coverageRatio - 1e-4)
                continue;
            choice = std::string(plannerKindInfo(k).id) + " for every aircraft: planned alone it finishes sooner (" +
                     metres(other->makespanS / 60.0, 1) + " min against " + metres(perAircraftS / 60.0, 1) +
                     " min with each aircraft's own choice: " + perAircraft + ")";
            plan = std::move(other);
        }
    }
    plan->plannerChoice = choice;
    return plan;
}

} // namespace


} // namespace pf::mission
