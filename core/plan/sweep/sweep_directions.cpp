#include "core/plan/sweep/sweep_directions.h"

#include "core/job_scope.h"

#include "core/geo/polygon_ops.h"
#include "core/plan/lawnmower_planner.h"
#include "core/plan/sweep/decomposition.h"
#include "core/plan/sweep/sweep_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace pf::plan::sweep_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A direction's lanes on shared lines are planned in full when their quick estimate is at most this
// many times that of its own lanes.
constexpr double kSharedLinesEstimateRatio = 1.1;
constexpr std::size_t kSharedLinesMaxLanes = 600;
// Phases of the shared lines compared by the quick estimate (see laneVariants).
constexpr int kSharedLinePhases = 4;
// What a lane of the placed shared lines costs for placeSharedLines, in U-turns (each lane a line
// becomes has two ends and a link to another).
constexpr double kPlacedRunCost = 3.0;
// The most pixels of the coverage check in the search for the Survey's direction.
constexpr double kSurveyCheckPixels = 1.0e5;

// The decomposition of the free space in one direction; none when no small change resolves a
// degenerate input. `shrunk`: the free space 5 mm smaller, made when first needed.
std::optional<Decomposition> decomposeDirection(const geo::MultiPolygon& freeSpace, double angleDeg,
                                                geo::MultiPolygon& shrunk) {
    auto dec = decompose(freeSpace, SweepFrame{angleDeg * M_PI / 180.0});
    if (!dec.ok()) // a degenerate order of vertices: a hair's rotation resolves it
        dec = decompose(freeSpace, SweepFrame{angleDeg * M_PI / 180.0 + 1e-7});
    if (!dec.ok()) { // rings touching at a point: 5 mm less free space parts them
        if (shrunk.empty())
            shrunk = geo::buffer(freeSpace, -0.005, 2);
        dec = decompose(shrunk, SweepFrame{angleDeg * M_PI / 180.0});
    }
    if (!dec.ok())
        return std::nullopt;
    return std::move(*dec);
}

// A variant of a direction: its decomposition and cells, on other lines.
DirectionPlan variantOf(const DirectionPlan& base, std::vector<double> sharedLines) {
    DirectionPlan v;
    v.angleDeg = base.angleDeg;
    v.dec = base.dec;
    v.mc = base.mc;
    v.sharedLines = std::move(sharedLines);
    return v;
}

std::size_t laneCount(const DirectionPlan& dp) {
    std::size_t n = 0;
    for (const auto& hs : dp.heights)
        n += hs.size();
    return n;
}

} // namespace

SweepDirections sweepDirections(const PreparedGround& g) {
    const SweepOptions& opt = g.opt;
    SweepDirections sd;
    sd.anglesDeg = candidateDirections(g.region, g.noFly, opt);
    if (!opt.anglesDeg.empty() || !opt.surveyDirection)
        return sd;
    // The directions a Survey would fly over the region (plan::planLawnmower, zones ignored, every
    // degree and every edge direction searched): the fastest, and the fastest whose photos see the
    // area as the reference Survey keeps to (a degree off an edge flies a hair shorter and leaves
    // corners, which the sweep's spot photos take). Their lanes suit the region's outline, and the
    // quick estimate, which sees cells rather than the flow of lanes round the zones, often ranks
    // them too low: on the eval's 60 generated areas the best direction of about half the areas was
    // one of them, outside the three best estimated on a third. Both are planned in full besides
    // the best estimated ones. The coverage check rasterises the area in pixels of a fifth of the
    // footprint's short side (the corners it looks for are footprint-sized), at most about 10^5.
    auto keepAngle = [&](double deg) {
        for (double a : sd.anglesDeg)
            if (sameDirection(a, deg)) {
                sd.alwaysPlanned.push_back(a);
                return a;
            }
        sd.anglesDeg.push_back(deg);
        sd.alwaysPlanned.push_back(deg);
        return deg;
    };
    LawnmowerOptions lo;
    lo.trackSpacingM = g.spacingM;
    lo.photoSpacingM = g.photoSpacingM;
    lo.time = opt.time;
    lo.home = opt.home;
    if (auto lm = planLawnmower(g.region, lo); lm.ok())
        keepAngle(lm->angleDeg);
    lo.footprintAcrossM = g.realAcrossM;
    lo.footprintAlongM = g.realAlongM;
    lo.searchCoverageResolutionM = std::max(0.2 * std::min(g.realAcrossM, g.realAlongM),
                                            std::sqrt(geo::area(g.region) / kSurveyCheckPixels));
    if (auto lm = planLawnmower(g.region, lo); lm.ok())
        sd.surveyAngle = keepAngle(lm->angleDeg);
    return sd;
}

double estimateLanes(const PreparedGround& g, DirectionPlan& dp) {
    SweepLaneParams vp = g.lanes;
    vp.sharedLines = dp.sharedLines;
    dp.heights = allLaneHeights(dp.d(), dp.merged(), vp, g.ground, &dp.pinned);
    return quickEstimateS(dp.d(), dp.merged(), dp.heights, g.photoSpacingM, g.opt.time, g.spacingM);
}

Result<std::vector<DirectionPlan>> estimateDirections(const PreparedGround& g,
                                                      const std::vector<double>& anglesDeg) {
    std::vector<DirectionPlan> dirs;
    geo::MultiPolygon shrunk;
    for (double a : anglesDeg) {
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "planning the sweep: cancelled");
        auto dec = decomposeDirection(g.freeSpace, a, shrunk);
        if (!dec)
            continue;
        DirectionPlan dp;
        dp.angleDeg = a;
        auto decomposition = std::make_shared<const Decomposition>(std::move(*dec));
        auto merged = std::make_shared<std::vector<MergedCell>>();
        if (g.opt.mergeCells) {
            *merged = mergeCells(*decomposition);
        } else {
            for (std::size_t i = 0; i < decomposition->cells.size(); ++i)
                merged->push_back(MergedCell{{static_cast<int>(i)}});
        }
        dp.dec = decomposition;
        dp.mc = merged;
        dp.estimateS = estimateLanes(g, dp);
        dirs.push_back(std::move(dp));
    }
    if (dirs.empty())
        return makeError(ErrorCode::InvalidGeometry,
                         "The area could not be decomposed in any sweep direction: its "
                         "outline may touch or cross itself.");
    return dirs;
}

std::vector<std::size_t> directionsToPlan(const std::vector<DirectionPlan>& dirs,
                                          const SweepDirections& sd, int planned) {
    std::vector<std::size_t> rank(dirs.size());
    for (std::size_t i = 0; i < rank.size(); ++i)
        rank[i] = i;
    std::stable_sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t b) {
        return dirs[a].estimateS < dirs[b].estimateS;
    });
    planned = std::min<int>(planned, static_cast<int>(rank.size()));
    std::vector<std::size_t> planRank(rank.begin(), rank.begin() + planned);
    for (std::size_t r = static_cast<std::size_t>(planned); r < rank.size(); ++r)
        if (std::find(sd.alwaysPlanned.begin(), sd.alwaysPlanned.end(), dirs[rank[r]].angleDeg) !=
            sd.alwaysPlanned.end())
            planRank.push_back(rank[r]);
    return planRank;
}

std::vector<const DirectionPlan*> laneVariants(const PreparedGround& g,
                                               const std::vector<DirectionPlan>& dirs,
                                               const std::vector<std::size_t>& planRank,
                                               std::deque<DirectionPlan>& variants) {
    const double s = g.spacingM;
    std::vector<const DirectionPlan*> toPlan;
    // Each planned direction also with its lanes on shared lines (SweepLaneParams::latticeY0) laid
    // from the free space's lowest edge, planned in full for the best direction, for the others
    // only when the quick estimate (which does not see the trim) puts it near the direction's own
    // lanes, and not on large areas (many lanes), where the zones are few for the lanes and the
    // time would double; the fastest plan is kept.
    for (std::size_t r = 0; r < planRank.size(); ++r) {
        const DirectionPlan& base = dirs[planRank[r]];
        toPlan.push_back(&base);
        if (!g.opt.sharedLines || base.d().cells.empty())
            continue;
        double ymin = kInf, ymax = -kInf;
        for (const auto& c : base.d().cells) {
            ymin = std::min(ymin, c.ylo);
            ymax = std::max(ymax, c.yhi);
        }
        const double y0 = ymin + 0.5 * s - 0.02;
        DirectionPlan v = variantOf(base, latticeLines(y0, s, ymin, ymax));
        v.estimateS = estimateLanes(g, v);
        if (laneCount(v) > kSharedLinesMaxLanes ||
            (r > 0 && v.estimateS > kSharedLinesEstimateRatio * base.estimateS))
            continue;
        variants.push_back(std::move(v));
        toPlan.push_back(&variants.back());
        // The lines' phase decides which of them a zone cuts (a zone 20 m across with its margins
        // cuts one line or two): besides the lines laid from the lowest edge, the best of
        // kSharedLinePhases - 1 shifts by a fraction of half a spacing (the lowest line stays
        // within half a spacing of the edge) by the quick estimate is planned too. On the eval's 60
        // generated areas this took the mean flight time from 1.335x to 1.317x the lawnmower's,
        // photos outside the zones from 1.061x to 1.053x, for a third more planning time.
        std::optional<DirectionPlan> shifted;
        for (int k = 1; k < kSharedLinePhases; ++k) {
            DirectionPlan w =
                variantOf(base, latticeLines(y0 - 0.5 * s * k / kSharedLinePhases, s, ymin, ymax));
            w.estimateS = estimateLanes(g, w);
            if (!shifted || w.estimateS < shifted->estimateS)
                shifted = std::move(w);
        }
        if (shifted) {
            variants.push_back(std::move(*shifted));
            toPlan.push_back(&variants.back());
        }
        if (g.opt.placedLines) {
            DirectionPlan w = variantOf(
                base, placeSharedLines(base.d(), s, [&](double lengthM, int runs) {
                    return lengthM / g.opt.time.speedMps + kPlacedRunCost * runs * g.uTurnS;
                }));
            if (!w.sharedLines.empty()) {
                w.estimateS = estimateLanes(g, w);
                variants.push_back(std::move(w));
                toPlan.push_back(&variants.back());
            }
        }
    }
    return toPlan;
}

} // namespace pf::plan::sweep_detail
