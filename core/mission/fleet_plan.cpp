// The fleet's plan: the estimates' grid angle, the split search (starts, correction rounds) and the
// plan of the best split.
#include "core/mission/fleet_plan.h"

#include "core/fleet/aircraft.h"
#include "core/fleet/area_split.h"
#include "core/fleet/subarea_polygons.h"
#include "core/geo/polygon_ops.h"
#include "core/job_scope.h"
#include "core/mission/build_plan.h"
#include "core/mission/plan_region.h"
#include "core/mission/terrain_stage.h"
#include "core/sensor/camera.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <string>
#include <tuple>
#include <utility>

namespace pf::mission::detail {

namespace {

// Raw time estimates of the fleet split, remembered by aircraft and the sorted cells of the split's
// base grid. The memo holds one base grid's cells: a different grid (never expected within one
// planFleet, whose area, zones, fleet and split options are fixed) empties it first. The split
// estimates two or three subareas at once (one thread each): the memo is locked while it is read or
// written, never while an estimate runs.
class EstimateMemo {
public:
    template <class Estimate>
    Result<double> rawS(std::size_t aircraft, const std::vector<int>& cells, const grid::Grid& base,
                        Estimate&& estimate) {
        const std::tuple<int, int, double, double, double, double> grid{
            base.cols(),     base.rows(),       base.cellSize(),
            base.angleDeg(), base.origin().x(), base.origin().y()};
        auto key = std::make_pair(aircraft, cells);
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            if (grid != m_grid) {
                m_known.clear();
                m_grid = grid;
            }
            if (auto it = m_known.find(key); it != m_known.end())
                return it->second;
        }
        Result<double> t = estimate();
        if (t) {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_known.emplace(std::move(key), *t);
        }
        return t;
    }

private:
    std::mutex m_mutex;
    std::tuple<int, int, double, double, double, double> m_grid{};
    std::map<std::pair<std::size_t, std::vector<int>>, double> m_known;
};

// Every split tried, with the makespan of its plan at the fixed angle and whether that makespan is
// within kBalanceTarget of the ideal.
struct Candidate {
    bool balanced = false;
    double makespanS = 0.0;
    std::vector<geo::MultiPolygon> regions;
};

// Up to two starts of up to three rounds each (searchSplits).
constexpr int kStarts = 2;
constexpr int kRounds = 3;
// The parts of the job's progress: the estimates' grid angle, the split search, then the plan of
// the split chosen. Each round of the search has an equal slot; within it the split's estimates
// move the progress towards kSplitPart of the slot (the number they take is not known beforehand:
// half way at kHalfwayEstimates), the round's plan the rest.
constexpr double kAngleEnd = 0.05;
constexpr double kSearchEnd = 0.70;
constexpr double kSplitPart = 0.6;
constexpr double kHalfwayEstimates = 20.0;
const std::string kSharing = "sharing the area: ";

double slotStart(int start, int round) {
    return kAngleEnd +
           (kSearchEnd - kAngleEnd) * (start * kRounds + round) / double(kStarts * kRounds);
}
double slotEnd(int start, int round) {
    return slotStart(start, round + 1);
}

// The job's Progress without its reports: the stages nested in an estimate or a round plan would
// otherwise report their own names and fractions over the search's.
struct Quiet {
    JobScope scope{JobScope::current(), JobScope::CancelOnly{}};
};

// The estimates' planner for aircraft `k`: a plane's estimates use the sweep, the planner that plans
// for planes (stride turns on the spot), when the mission leaves the choice to the planner.
PlannerOptions estimateFor(const FleetInput& in, std::size_t k, PlannerOptions o) {
    if (in.mission.options.planner == PlannerKind::Auto &&
        fleet::fliesAsPlane(in.mission.aircraft[k].kind))
        o.planner = PlannerKind::Sweep;
    return o;
}

// The split estimates times at one fixed angle (a full angle search per estimate would cost 37
// times as much): the mission's, or the best for the aircraft with the coarsest grid (the cheapest
// search) over the whole area.
Result<double> estimateAngle(const FleetInput& in, const PlannerOptions& estimateOpt) {
    const Mission& m = in.mission;
    if (m.options.gridAngleDeg)
        return *m.options.gridAngleDeg;
    reportProgress(0.0, kSharing + "grid angle of the estimates");
    std::size_t coarsest = 0;
    for (std::size_t k = 1; k < in.caps.size(); ++k)
        if (sensor::cellSizeFor(in.caps[k].footprint) >
            sensor::cellSizeFor(in.caps[coarsest].footprint))
            coarsest = k;
    Quiet quiet;
    auto whole = planRegion(geo::MultiPolygon{in.geom.area}, in.geom.noFly, m.aircraft[coarsest],
                            estimateFor(in, coarsest, estimateOpt), in.homes[coarsest],
                            in.landing);
    if (!whole)
        return whole.error();
    return whole->gridAngleDeg;
}

// The splits tried, each planned to the end at the fixed angle (`fixedPlan`, without the coverage
// check). `fixed` is the estimates' planner at that angle.
//
// The estimate of a subarea is the time of the route the aircraft would fly alone over it
// (aloneRouteTimeS). The planner's own cell-path time misses where the photos sit (the route runs
// through photo waypoints, not cell centres) and was off by up to 7 % on large footprints; the
// route leaves only what needs the neighbours (photos another aircraft already takes) and the
// no-fly detours to the correction factors below. An aircraft whose subarea lies far from its home
// gets less of the area.
//
// Up to two starts: the aircraft in the mission's order, then, if no round of it came within the
// balancer's tolerance, reversed. The partition seeds the aircraft one after the other from the far
// end of the free cells, so the order decides which aircraft gets which end of the area and the
// shapes of the subareas; the flight time depends on those shapes (turns, pieces, photos a
// neighbour already takes) far more than on their sizes, so two splits balanced on the estimate can
// differ by 10 % in makespan. The second start is skipped when the first is balanced, to keep the
// planning time near that of one split. Every split planned is a candidate.
//
// The estimate misses what comes after the per-aircraft plan: photos dropped because a neighbour
// with a larger footprint already sees them, detours, the safe transit. So each round splits, plans
// to the end, measures each aircraft's final time against its estimate, and the next round splits
// again with each estimate scaled by that factor.
Result<std::vector<Candidate>> searchSplits(const FleetInput& in, const PlannerOptions& fixed,
                                            const PlannerOptions& fixedPlan) {
    const Mission& m = in.mission;
    const LocalGeometry& geom = in.geom;
    const std::size_t n = m.aircraft.size();
    const auto rawEstimate = [&](std::size_t k, const geo::MultiPolygon& sub) -> Result<double> {
        Quiet quiet;
        auto ap = planRegion(sub, geom.noFly, m.aircraft[k], estimateFor(in, k, fixed), in.homes[k],
                             in.landing,
                             laneSpacing(m, k));
        if (!ap)
            return ap.error();
        return aloneRouteTimeS(surveyPart(ap->localWaypoints), m.aircraft[k], in.homes[k],
                               in.landing);
    };
    fleet::AreaSplitOptions so;
    so.gridAngleDeg = *fixed.gridAngleDeg;
    so.safetyMarginM = m.options.safetyMarginM;
    // Tighter than the balancer's default (5 %): the stages after the estimate add their own
    // spread, and the target is the final makespan within 10 % of the ideal.
    so.balance.tolerance = 0.03;
    const auto ratio = [](const MissionPlan& p) {
        return p.idealS > 0 ? p.makespanS / p.idealS : 1.0;
    };
    std::vector<Candidate> candidates;
    // The raw estimates already made, by aircraft and subarea cells: every round and both starts
    // split the same base grid, and the balance search comes back to the same subareas (on the demo
    // 40 % of the estimates asked for; each also costs a polygon union).
    EstimateMemo memo;
    std::vector<std::vector<std::size_t>> orders(1);
    for (std::size_t k = 0; k < n; ++k)
        orders[0].push_back(k);
    orders.emplace_back(orders[0].rbegin(), orders[0].rend());
    bool reachedTolerance = false;
    for (int start = 0; start < kStarts && !reachedTolerance; ++start) {
        const auto& order = orders[static_cast<std::size_t>(start)];
        std::vector<fleet::Capability> ordered;
        for (std::size_t k : order)
            ordered.push_back(in.caps[k]);
        std::vector<double> factor(n, 1.0);
        for (int round = 0; round < kRounds; ++round) {
            const double lo = slotStart(start, round), hi = slotEnd(start, round);
            // Called from several threads at once (each in this job's scope).
            std::atomic<int> estimates{0};
            const fleet::CellsTimeEstimator estimate =
                [&](int i, const std::vector<int>& cells,
                    const grid::Grid& base) -> Result<double> {
                if (stopRequested())
                    return cancelledError(); // the split stops at its next estimate
                const double done = estimates++;
                reportProgress(lo + (hi - lo) * kSplitPart * done / (done + kHalfwayEstimates),
                               kSharing + "estimating flight times");
                const std::size_t k = order[static_cast<std::size_t>(i)];
                auto t = memo.rawS(k, cells, base, [&] {
                    return rawEstimate(k, fleet::cellsPolygon(base, cells, base.admissible()));
                });
                if (!t)
                    return t;
                return *t * factor[k];
            };
            if (stopRequested())
                return cancelledError();
            auto split = fleet::splitArea(geom.area, geom.noFly, ordered, so, estimate);
            if (!split)
                return makeError(split.error().code,
                                 "sharing the area between the aircraft: " + split.error().message);
            std::vector<geo::MultiPolygon> regions(n);
            for (std::size_t i = 0; i < n; ++i)
                regions[order[i]] = std::move(split->subareas[i]);
            reportProgress(lo + (hi - lo) * kSplitPart,
                           kSharing + "planning split " + std::to_string(candidates.size() + 1));
            std::vector<double> alone; // the estimate of each subarea, as the plan made it
            Result<MissionPlan> p = [&] {
                Quiet quiet;
                return buildPlan(m, fixedPlan, geom, regions, in.homes, in.landing, false, &alone);
            }();
            if (!p)
                return p.error();
            // With the automatic choice the estimate is stride's, the plan another planner's: the
            // factor is taken against the estimate itself.
            if (m.options.planner == PlannerKind::Auto)
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
    return candidates;
}

// The candidates were planned at the estimate's fixed angle (a full angle search per candidate
// would cost up to 37 times as much) and without the coverage check. They are ranked: those within
// kBalanceTarget of the ideal first (a plan that leaves the other aircraft idle while one flies on
// is not what a shared area asks for, even if its makespan is a little shorter), then by makespan.
// The first is planned once more with the mission's options (which may search the angle per
// subarea; if that makes the makespan longer, the fixed angle is kept) and checked. Should a leg
// breach a no-fly margin, or its photos miss the coverage target where another split could see the
// ground missed, the next one is tried; if none passes, the first is returned with its warnings.
Result<MissionPlan> planBest(const FleetInput& in, std::vector<Candidate> candidates,
                             const PlannerOptions& fixedPlan) {
    const Mission& m = in.mission;
    const PlannerOptions& opt = m.options;
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) {
                         return a.balanced != b.balanced ? a.balanced : a.makespanS < b.makespanS;
                     });
    // Gaps a split leaves lie where one aircraft's photos end and the next one's begin: within the
    // longest footprint of the shared boundary.
    double reachM = 0.0;
    for (const auto& c : in.caps)
        reachM = std::max(reachM, c.footprint.real.longSideM);
    std::optional<MissionPlan> first;
    for (const Candidate& c : candidates) {
        if (stopRequested())
            return cancelledError();
        auto chosen = buildPlan(m, opt, in.geom, c.regions, in.homes, in.landing, true);
        if (!chosen)
            return chosen.error();
        if (!opt.gridAngleDeg && chosen->makespanS > c.makespanS) {
            chosen = buildPlan(m, fixedPlan, in.geom, c.regions, in.homes, in.landing, true);
            if (!chosen)
                return chosen.error();
        }
        if (chosen->coverageRatio >= kCoverageTarget && chosen->noFlyViolations == 0)
            return chosen;
        const bool worthAnother =
            chosen->noFlyViolations > 0 ||
            otherSplitCouldReachTarget(*chosen, c.regions, reachM, kCoverageTarget);
        if (!first)
            first = std::move(*chosen);
        if (!worthAnother)
            break;
    }
    return std::move(*first);
}

} // namespace

bool otherSplitCouldReachTarget(const MissionPlan& plan,
                                const std::vector<geo::MultiPolygon>& regions, double reachM,
                                double target) {
    if (plan.coverageRatio >= target)
        return true;
    if (plan.coverageRatio <= 0.0 || plan.uncoveredAreaM2 <= 0.0)
        return true; // nothing known of what is missed
    const double admissibleM2 = plan.uncoveredAreaM2 / (1.0 - plan.coverageRatio);
    // The ground within reachM of two subareas: along their shared boundaries.
    std::vector<geo::MultiPolygon> grown;
    for (const auto& r : regions)
        grown.push_back(geo::buffer(r, reachM, 2));
    std::vector<geo::MultiPolygon> band;
    for (std::size_t i = 0; i < grown.size(); ++i)
        for (std::size_t j = i + 1; j < grown.size(); ++j)
            for (const auto& piece : grown[j])
                if (auto both = geo::intersection(grown[i], piece); !both.empty())
                    band.push_back(std::move(both));
    // The part of a patch within reach of a shared boundary (a zone's margin ring across which the
    // boundary runs counts only where it passes).
    const auto nearShared = [&](const UncoveredArea& patch) {
        double m2 = 0.0;
        for (const auto& part : band)
            for (const auto& p : patch.shape)
                m2 += geo::area(geo::intersection(part, p));
        return std::min(m2, patch.areaM2);
    };
    double listedM2 = 0.0, splitsM2 = 0.0;
    for (const auto& u : plan.uncovered) {
        listedM2 += u.areaM2;
        splitsM2 += nearShared(u);
    }
    splitsM2 += std::max(0.0, plan.uncoveredAreaM2 - listedM2);
    const double anySplitM2 = plan.uncoveredAreaM2 - splitsM2;
    return 1.0 - anySplitM2 / admissibleM2 >= target;
}

Result<MissionPlan> planFleet(const FleetInput& in) {
    const PlannerOptions& opt = in.mission.options;
    // With the automatic choice, the split is searched with stride's times (the split needs
    // hundreds of estimates; three planners each would triple them; stride's split gave the demo a
    // shorter makespan than raster's, 7.0 against 7.0 min for 0.59 against 0.82 s) and each
    // aircraft's region is then planned with the soonest of sweep, stride and raster (planRegion):
    // no aircraft flies longer than stride would make it fly there.
    PlannerOptions estimateOpt = opt;
    if (opt.planner == PlannerKind::Auto)
        estimateOpt.planner = PlannerKind::Stride;
    Result<double> angle = [&] {
        JobScope part(0.0, kAngleEnd);
        return estimateAngle(in, estimateOpt);
    }();
    if (!angle)
        return angle.error();
    PlannerOptions fixed = estimateOpt;
    fixed.gridAngleDeg = *angle;
    // The plans the split's rounds make and measure (the mission's planner at the fixed angle):
    // with the automatic choice each aircraft's region is planned with its soonest planner, and the
    // correction factors carry that back into the split.
    PlannerOptions fixedPlan = opt;
    fixedPlan.gridAngleDeg = *angle;
    auto candidates = searchSplits(in, fixed, fixedPlan);
    if (!candidates)
        return candidates.error();
    JobScope part(kSearchEnd, 1.0);
    return planBest(in, std::move(*candidates), fixedPlan);
}

} // namespace pf::mission::detail
