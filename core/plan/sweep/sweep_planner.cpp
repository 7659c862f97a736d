#include "core/plan/sweep/sweep_planner.h"

#include "core/job_scope.h"

#include "core/plan/sweep/sweep_choice.h"
#include "core/plan/sweep/sweep_directions.h"
#include "core/plan/sweep/sweep_input.h"
#include "core/plan/sweep/sweep_prepare.h"
#include "core/plan/sweep/sweep_search.h"

#include <deque>
#include <memory>

namespace pf::plan {

using geo::Vec2;

// The stages: the ground prepared once (free space, ways, pockets); the candidate directions with
// the Survey's; a quick estimate of each; the best planned in full, each with its variants on
// shared lines, by an order search; the fastest of each kind of lanes finished and the one flown
// chosen.
Result<SweepPlan> planSweep(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                            const SweepOptions& opt) {
    using namespace sweep_detail;
    if (auto ok = checkSweepInput(region, opt); !ok)
        return ok.error();
    const PreparedGround g(region, noFly, opt);
    if (auto ok = checkSweepEnds(g.field, g.home, g.landing, opt.safetyMarginM); !ok)
        return ok.error();
    SweepPlan plan;
    plan.stats.graphNodes = static_cast<int>(g.keepGraph.nodeCount());
    plan.stats.graphEdges = static_cast<int>(g.keepGraph.edgeCount());

    const SweepDirections candidates = sweepDirections(g);
    if (candidates.surveyAngle)
        plan.stats.surveyAngleDeg = *candidates.surveyAngle;
    auto dirs = estimateDirections(g, candidates.anglesDeg);
    if (!dirs.ok())
        return dirs.error();
    plan.stats.directionsEstimated = static_cast<int>(dirs->size());

    const std::vector<std::size_t> planRank =
        directionsToPlan(*dirs, candidates, opt.plannedDirections);
    plan.stats.surveyDirectionPlanned = false;
    for (std::size_t r : planRank)
        plan.stats.surveyDirectionPlanned =
            plan.stats.surveyDirectionPlanned ||
            (candidates.surveyAngle && (*dirs)[r].angleDeg == *candidates.surveyAngle);
    std::deque<DirectionPlan> variants;
    const std::vector<const DirectionPlan*> toPlan = laneVariants(g, *dirs, planRank, variants);

    SweepChoice choice(g);
    for (const DirectionPlan* dp : toPlan) {
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "planning the sweep: cancelled");
        auto searched = searchDirection(g, *dp);
        if (!searched.ok())
            return searched.error();
        choice.add(std::move(*searched));
    }
    plan.stats.directionsPlanned = static_cast<int>(planRank.size());
    return choice.choose(plan);
}

std::vector<geo::Vec2> sweepFlightPath(const SweepPlan& plan, const std::optional<geo::Vec2>& home,
                                       const std::optional<geo::Vec2>& landing, bool laneEndsOnly) {
    std::vector<Vec2> out;
    if (home)
        out.push_back(*home);
    if (!plan.lanes.empty())
        out.insert(out.end(), plan.homeLink.begin(), plan.homeLink.end());
    for (std::size_t i = 0; i < plan.lanes.size(); ++i) {
        const auto& ph = plan.lanes[i].photos;
        if (laneEndsOnly && ph.size() > 2) {
            out.push_back(ph.front());
            out.push_back(ph.back());
        } else {
            out.insert(out.end(), ph.begin(), ph.end());
        }
        if (i < plan.links.size() && i + 1 < plan.lanes.size())
            out.insert(out.end(), plan.links[i].begin(), plan.links[i].end());
    }
    if (!plan.lanes.empty())
        out.insert(out.end(), plan.landingLink.begin(), plan.landingLink.end());
    const std::optional<Vec2> land = landing ? landing : home;
    if (land)
        out.push_back(*land);
    return out;
}

} // namespace pf::plan
