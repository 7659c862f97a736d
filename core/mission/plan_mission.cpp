#include "core/mission/plan_mission.h"

#include "core/fleet/aircraft.h"
#include "core/fleet/altitude.h"
#include "core/fleet/area_split.h"
#include "core/fleet/photo_dedup.h"
#include "core/fleet/subarea_polygons.h"
#include "core/geo/polygon_ops.h"
#include "core/job_scope.h"
#include "core/mission/build_plan.h"
#include "core/mission/memory_estimate.h"
#include "core/mission/plan_geojson.h"
#include "core/mission/plan_region.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/route_check.h"
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
#include <future>
#include <map>
#include <tuple>
#include <sstream>

namespace pf::mission {

namespace {

using namespace detail;

// Raw time estimates of the fleet split, remembered by aircraft and the sorted cells of the split's
// base grid. The memo holds one base grid's cells: a different grid (never expected within one
// planMissionWith, whose area, zones, fleet and split options are fixed) empties it first.
class EstimateMemo {
public:
    template <class Estimate>
    Result<double> rawS(std::size_t aircraft, const std::vector<int>& cells, const grid::Grid& base, Estimate&& estimate) {
        const std::tuple<int, int, double, double, double, double> grid{base.cols(), base.rows(), base.cellSize(),
                                                                        base.angleDeg(), base.origin().x(), base.origin().y()};
        if (grid != m_grid) {
            m_known.clear();
            m_grid = grid;
        }
        auto key = std::make_pair(aircraft, cells);
        if (auto it = m_known.find(key); it != m_known.end())
            return it->second;
        Result<double> t = estimate();
        if (t)
            m_known.emplace(std::move(key), *t);
        return t;
    }

private:
    std::tuple<int, int, double, double, double, double> m_grid{};
    std::map<std::pair<std::size_t, std::vector<int>>, double> m_known;
};

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
    // A plane's estimates use the sweep, the planner that plans for planes (stride turns on the spot).
    const auto estimateFor = [&](std::size_t k, PlannerOptions o) {
        if (opt.planner == PlannerKind::Auto && fleet::fliesAsPlane(m.aircraft[k].kind))
            o.planner = PlannerKind::Sweep;
        return o;
    };
    double estimateAngle = 0.0;
    if (opt.gridAngleDeg) {
        estimateAngle = *opt.gridAngleDeg;
    } else {
        std::size_t coarsest = 0;
        for (std::size_t k = 1; k < n; ++k)
            if (sensor::cellSizeFor(footprints[k]) > sensor::cellSizeFor(footprints[coarsest]))
                coarsest = k;
        auto whole = planRegion(geo::MultiPolygon{geom->area}, geom->noFly, m.aircraft[coarsest],
                                estimateFor(coarsest, estimateOpt), frame,
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
        auto ap = planRegion(sub, geom->noFly, m.aircraft[k], estimateFor(k, fixed), frame, homes[k], landing,
                             laneSpacing(m, k));
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
    // The raw estimates already made, by aircraft and subarea cells: every round and both starts
    // split the same base grid, and the balance search comes back to the same subareas (on the demo
    // 40 % of the estimates asked for; each also costs a polygon union).
    EstimateMemo memo;
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
            const fleet::CellsTimeEstimator estimate = [&](int i, const std::vector<int>& cells,
                                                           const grid::Grid& base) -> Result<double> {
                if (stopRequested())
                    return cancelledError(); // the split stops at its next estimate
                const std::size_t k = order[static_cast<std::size_t>(i)];
                auto t = memo.rawS(k, cells, base, [&] { return rawEstimate(k, fleet::cellsPolygon(base, cells, base.admissible())); });
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
