#include "core/plan/sweep/sweep_planner.h"

#include "core/job_scope.h"

#include "core/geo/no_fly_field.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/visibility_graph.h"
#include "core/plan/coverage_check.h"
#include "core/plan/lanes/photo_thinning.h"
#include "core/plan/lawnmower_planner.h"
#include "core/plan/sweep/cell_order.h"
#include "core/plan/sweep/decomposition.h"
#include "core/plan/sweep/lane_trim.h"
#include "core/plan/sweep/sweep_estimate.h"
#include "core/plan/sweep/sweep_input.h"
#include "core/plan/sweep/sweep_lanes.h"
#include "core/plan/sweep/sweep_reach.h"
#include "core/plan/sweep/sweep_routing.h"
#include "core/plan/sweep/sweep_state.h"
#include "core/plan/sweep/sweep_turns.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <memory>
#include <unordered_map>

namespace pf::plan {

using geo::Vec2;

namespace {

using namespace sweep_detail;

constexpr double kInf = std::numeric_limits<double>::infinity();
// Lane ends the lane-level search considers joining, per end: the nearest this many.
constexpr int kNeighbours = 10;
// Lanes flown no longer than this many trigger distances are checked for being redundant.
constexpr double kShortLanePhotos = 4.0;
// A direction's lanes on shared lines are planned in full when their quick estimate is at most this
// many times that of its own lanes.
constexpr double kSharedLinesEstimateRatio = 1.1;
constexpr std::size_t kSharedLinesMaxLanes = 600;
// Phases of the shared lines compared by the quick estimate (see the variants).
constexpr int kSharedLinePhases = 4;
// What a lane of the placed shared lines costs for placeSharedLines, in U-turns (each lane a line
// becomes has two ends and a link to another).
constexpr double kPlacedRunCost = 3.0;
// How many more shared-line variants are finished when the fastest one leaves ground unseen.
constexpr int kSharedRetries = 3;
// The most pixels of the coverage check in the search for the Survey's direction.
constexpr double kSurveyCheckPixels = 1.0e5;

std::string fmt(double v, int decimals = 1) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

} // namespace

Result<SweepPlan> planSweep(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                            const SweepOptions& opt) {
    if (auto ok = checkSweepInput(region, opt); !ok)
        return ok.error();
    const double s = opt.trackSpacingM, ph = opt.photoSpacingM;
    const double realAcross = opt.realAcrossM > 0 ? opt.realAcrossM : s;
    const double realAlong = opt.realAlongM > 0 ? opt.realAlongM : ph;

    SweepPlan plan;
    // --- the free space and the ways through it
    geo::NoFlyField field(noFly, opt.safetyMarginM);
    geo::VisibilityGraphOptions vgo;
    vgo.quadrantSegments = opt.quadrantSegments;
    vgo.coarseCorners = true;
    vgo.allPairs = true;
    const geo::VisibilityGraph freeGraph(field, vgo);
    const auto grownOnce = std::make_shared<const geo::MultiPolygon>(freeGraph.inflatedZones());
    // Transitions stay over the area with keep-inside; without, within half a track spacing of it
    // (as no waypoint of any plan may stray further), unless no such way exists.
    vgo.keepInside = opt.keepInside ? region : geo::buffer(region, 0.5 * opt.trackSpacingM - 0.05, 2);
    std::unique_ptr<geo::VisibilityGraph> keepGraph = std::make_unique<geo::VisibilityGraph>(field, vgo, grownOnce);
    const geo::VisibilityGraph& graph = *keepGraph;
    // The detailed graphs serve the few transitions the coarse ones miss: no all-pairs table for them.
    geo::VisibilityGraphOptions detailed = vgo;
    detailed.coarseCorners = false;
    detailed.allPairs = false;
    const LazyGraph coarseFree(freeGraph), detailedFree(field, [&] {
        auto o = detailed;
        o.keepInside.clear();
        return o;
    }(), grownOnce);
    std::unique_ptr<LazyGraph> coarseKeep, detailedKeep;
    std::vector<RouteGraph> routeGraphs;
    if (keepGraph) {
        coarseKeep = std::make_unique<LazyGraph>(*keepGraph);
        detailedKeep = std::make_unique<LazyGraph>(field, detailed, grownOnce);
        routeGraphs.push_back(RouteGraph{coarseKeep.get(), false});
        routeGraphs.push_back(RouteGraph{detailedKeep.get(), false});
    }
    routeGraphs.push_back(RouteGraph{&coarseFree, true});
    routeGraphs.push_back(RouteGraph{&detailedFree, true});
    plan.stats.graphNodes = static_cast<int>(graph.nodeCount());
    plan.stats.graphEdges = static_cast<int>(graph.edgeCount());
    const geo::MultiPolygon& grown = freeGraph.inflatedZones();
    const geo::MultiPolygon freeSpace = grown.empty() ? region : geo::difference(region, grown);
    const SweepGround ground(region, noFly, grown);
    // The ground the photos must see: the region less the zones.
    const geo::MultiPolygon toSee =
        noFly.empty() ? region : geo::difference(region, geo::MultiPolygon(noFly.begin(), noFly.end()));

    const std::optional<Vec2> home = opt.home;
    const std::optional<Vec2> landing = opt.landing ? opt.landing : opt.home;
    for (const auto* p : {&home, &landing})
        if (*p && !field.pointIsSafe(**p))
            return makeError(ErrorCode::NoPath, std::string(p == &home ? "The home point" : "The landing point") +
                                                    " (" + fmt((*p)->x()) + ", " + fmt((*p)->y()) +
                                                    ") m lies within the " + fmt(opt.safetyMarginM) +
                                                    " m safety margin of a no-fly zone.");

    // --- reachability: free pieces inside a pocket of the grown zones are reached only from there
    const Pockets pockets(grown);
    int anchor = -1;
    {
        if (home) {
            anchor = pockets.of(*home);
        } else {
            std::unordered_map<int, double> areaOf;
            for (const auto& f : freeSpace)
                areaOf[pockets.of(interiorPoint(f))] += geo::area(f);
            double best = -1;
            for (const auto& [id, a] : areaOf)
                if (a > best || (a == best && id < anchor)) {
                    best = a;
                    anchor = id;
                }
        }
    }

    // --- candidate directions
    std::vector<double> angles = candidateDirections(region, noFly, opt);
    // The directions a Survey would fly over the region (plan::planLawnmower, zones ignored, every
    // degree and every edge direction searched): the fastest, and the fastest whose photos see the
    // area as the reference Survey keeps to (a degree off an edge flies a hair shorter and leaves
    // corners, which the sweep's spot photos take). Their lanes suit the region's outline, and the
    // quick estimate below, which sees cells rather than the flow of lanes round the zones, often
    // ranks them too low: on the eval's 60 generated areas the best direction of about half the areas
    // was one of them, outside the three best estimated on a third. Both are planned in full besides
    // the best estimated ones. The coverage check rasterises the area in pixels of a fifth of the
    // footprint's short side (the corners it looks for are footprint-sized), at most about 10^5.
    std::optional<double> surveyAngle;
    std::vector<double> alwaysPlanned; // the Survey's directions, as angles of the candidates
    auto keepAngle = [&](double deg) {
        for (double a : angles)
            if (sameDirection(a, deg)) {
                alwaysPlanned.push_back(a);
                return a;
            }
        angles.push_back(deg);
        alwaysPlanned.push_back(deg);
        return deg;
    };
    if (opt.anglesDeg.empty() && opt.surveyDirection) {
        LawnmowerOptions lo;
        lo.trackSpacingM = s;
        lo.photoSpacingM = ph;
        lo.time = opt.time;
        lo.home = opt.home;
        if (auto lm = planLawnmower(region, lo); lm.ok())
            keepAngle(lm->angleDeg);
        lo.footprintAcrossM = realAcross;
        lo.footprintAlongM = realAlong;
        lo.searchCoverageResolutionM =
            std::max(0.2 * std::min(realAcross, realAlong), std::sqrt(geo::area(region) / kSurveyCheckPixels));
        if (auto lm = planLawnmower(region, lo); lm.ok()) {
            surveyAngle = keepAngle(lm->angleDeg);
            plan.stats.surveyAngleDeg = *surveyAngle;
        }
    }

    // --- quick estimate per direction: decomposition, lane heights, turns, cell changes
    SweepLaneParams lp;
    lp.trackSpacingM = s;
    lp.photoSpacingM = ph;
    lp.grownMarginM = freeGraph.inflatedMarginM();
    lp.flyOutsideArea = !opt.keepInside;
    lp.marginRunCapM = 2.0 * std::max(realAlong, ph) + 2.0 * freeGraph.inflatedMarginM();
    lp.neighbourReachM = std::max(0.0, 0.5 * (realAcross - s));
    lp.reachAlongM = 0.5 * realAlong;
    const double uTurnS = 2.0 * turnCostS(90.0, opt.time) + s / opt.time.speedMps;
    // Lane heights of a variant and its quick estimate: lanes, turns, cell changes.
    auto estimate = [&](DirectionPlan& dp) {
        SweepLaneParams vp = lp;
        vp.sharedLines = dp.sharedLines;
        dp.heights = allLaneHeights(dp.d(), dp.merged(), vp, ground, &dp.pinned);
        return quickEstimateS(dp.d(), dp.merged(), dp.heights, ph, opt.time, s);
    };
    std::vector<DirectionPlan> dirs;
    geo::MultiPolygon shrunk;
    for (double a : angles) {
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "planning the sweep: cancelled");
        DirectionPlan dp;
        dp.angleDeg = a;
        auto dec = decompose(freeSpace, SweepFrame{a * M_PI / 180.0});
        if (!dec.ok()) // a degenerate order of vertices: a hair's rotation resolves it
            dec = decompose(freeSpace, SweepFrame{a * M_PI / 180.0 + 1e-7});
        if (!dec.ok()) { // rings touching at a point: 5 mm less free space parts them
            if (shrunk.empty())
                shrunk = geo::buffer(freeSpace, -0.005, 2);
            dec = decompose(shrunk, SweepFrame{a * M_PI / 180.0});
        }
        if (!dec.ok())
            continue;
        auto decomposition = std::make_shared<const Decomposition>(std::move(*dec));
        auto merged = std::make_shared<std::vector<MergedCell>>();
        if (opt.mergeCells) {
            *merged = mergeCells(*decomposition);
        } else {
            for (std::size_t i = 0; i < decomposition->cells.size(); ++i)
                merged->push_back(MergedCell{{static_cast<int>(i)}});
        }
        dp.dec = decomposition;
        dp.mc = merged;
        dp.estimateS = estimate(dp);
        dirs.push_back(std::move(dp));
    }
    plan.stats.directionsEstimated = static_cast<int>(dirs.size());
    if (dirs.empty())
        return makeError(ErrorCode::InvalidGeometry,
                         "The area could not be decomposed in any sweep direction: its outline may touch or cross itself.");
    std::vector<std::size_t> rank(dirs.size());
    for (std::size_t i = 0; i < rank.size(); ++i)
        rank[i] = i;
    std::stable_sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t b) { return dirs[a].estimateS < dirs[b].estimateS; });

    // --- full plans for the best directions
    const double regionArea = geo::area(region);
    const double wedgeDepth = std::max(0.0, 0.5 * s - std::max(0.0, 0.5 * (realAcross - s)));
    auto safeOutside = [&](const Vec2& a, const Vec2& b) { return field.segmentIsSafe(a, b); };
    // The fastest plan of each kind of lanes: a cell's own spacing, and lines shared by all cells
    // (kept apart because the search's time does not see what the shared lines leave beside the
    // zones for spot photos; both are finished and the faster flight kept).
    std::unique_ptr<FullPlan> best, bestShared;
    std::vector<std::unique_ptr<FullPlan>> otherOwn, otherShared;
    const double allowed = 0.001 * regionArea; // ground a direction may leave to the wedges (see worse)
    const int planned = std::min<int>(opt.plannedDirections, static_cast<int>(rank.size()));
    // Each planned direction also with its lanes on shared lines (SweepLaneParams::latticeY0) laid from
    // the free space's lowest edge, planned in full for the best direction, for the others only when
    // the quick estimate (which does not see the trim) puts it near the direction's own lanes, and
    // not on large areas (many lanes), where the zones are few for the lanes and the time would
    // double; the fastest plan is kept.
    std::deque<DirectionPlan> variants;
    std::vector<const DirectionPlan*> toPlan;
    std::vector<std::size_t> planRank(rank.begin(), rank.begin() + planned);
    for (std::size_t r = static_cast<std::size_t>(planned); r < rank.size(); ++r)
        if (std::find(alwaysPlanned.begin(), alwaysPlanned.end(), dirs[rank[r]].angleDeg) != alwaysPlanned.end())
            planRank.push_back(rank[r]);
    plan.stats.surveyDirectionPlanned = false;
    for (std::size_t r : planRank)
        plan.stats.surveyDirectionPlanned = plan.stats.surveyDirectionPlanned || (surveyAngle && dirs[r].angleDeg == *surveyAngle);
    for (std::size_t r = 0; r < planRank.size(); ++r) {
        const DirectionPlan& base = dirs[planRank[r]];
        toPlan.push_back(&base);
        if (!opt.sharedLines || base.d().cells.empty())
            continue;
        double ymin = kInf, ymax = -kInf;
        for (const auto& c : base.d().cells) {
            ymin = std::min(ymin, c.ylo);
            ymax = std::max(ymax, c.yhi);
        }
        DirectionPlan v;
        v.angleDeg = base.angleDeg;
        v.dec = base.dec;
        v.mc = base.mc;
        const double y0 = ymin + 0.5 * s - 0.02;
        v.sharedLines = latticeLines(y0, s, ymin, ymax);
        v.estimateS = estimate(v);
        std::size_t laneCount = 0;
        for (const auto& hs : v.heights)
            laneCount += hs.size();
        if (laneCount > kSharedLinesMaxLanes || (r > 0 && v.estimateS > kSharedLinesEstimateRatio * base.estimateS))
            continue;
        variants.push_back(std::move(v));
        toPlan.push_back(&variants.back());
        // The lines' phase decides which of them a zone cuts (a zone 20 m across with its margins cuts
        // one line or two): besides the lines laid from the lowest edge, the best of kSharedLinePhases - 1
        // shifts by a fraction of half a spacing (the lowest line stays within half a spacing of the
        // edge) by the quick estimate is planned too. On the eval's 60 generated areas this took the
        // mean flight time from 1.335x to 1.317x the lawnmower's, photos outside the zones from 1.061x
        // to 1.053x, for a third more planning time.
        std::optional<DirectionPlan> shifted;
        for (int k = 1; k < kSharedLinePhases; ++k) {
            DirectionPlan w;
            w.angleDeg = base.angleDeg;
            w.dec = base.dec;
            w.mc = base.mc;
            w.sharedLines = latticeLines(y0 - 0.5 * s * k / kSharedLinePhases, s, ymin, ymax);
            w.estimateS = estimate(w);
            if (!shifted || w.estimateS < shifted->estimateS)
                shifted = std::move(w);
        }
        if (shifted) {
            variants.push_back(std::move(*shifted));
            toPlan.push_back(&variants.back());
        }
        if (opt.placedLines) {
            DirectionPlan w;
            w.angleDeg = base.angleDeg;
            w.dec = base.dec;
            w.mc = base.mc;
            w.sharedLines = placeSharedLines(base.d(), s, [&](double lengthM, int runs) {
                return lengthM / opt.time.speedMps + kPlacedRunCost * runs * uTurnS;
            });
            if (!w.sharedLines.empty()) {
                w.estimateS = estimate(w);
                variants.push_back(std::move(w));
                toPlan.push_back(&variants.back());
            }
        }
    }
    for (const DirectionPlan* planning : toPlan) {
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "planning the sweep: cancelled");
        const DirectionPlan& dp = *planning;
        auto fp = std::make_unique<FullPlan>();
        fp->angleDeg = dp.angleDeg;
        fp->dir = &dp;
        fp->router = std::make_unique<Router>(opt.time, routeGraphs);
        Router& router = *fp->router;
        const Vec2 u = dp.d().frame.toWorld(Vec2(1, 0));
        std::vector<std::vector<CellLane>> laneSets(dp.merged().size());
        for (std::size_t mi = 0; mi < dp.merged().size(); ++mi)
            laneSets[mi] = cellLanes(dp.d(), dp.merged()[mi], dp.heights[mi], lp, ground, safeOutside);
        dropCoveredLanes(dp.d(), laneSets, dp.pinned, lp, ground, realAcross, realAlong, kShortLanePhotos * ph);
        // Cells in a pocket no safe path reaches are not flown (a merged cell lies in one piece of the
        // free space, so its middle lane tells): their lanes see nothing.
        std::vector<char> reachableCell(laneSets.size(), 0);
        for (std::size_t mi = 0; mi < laneSets.size(); ++mi)
            if (!laneSets[mi].empty()) {
                const auto& ml = laneSets[mi][laneSets[mi].size() / 2];
                reachableCell[mi] = pockets.of(0.5 * (ml.flyA + ml.flyB)) == anchor ? 1 : 0;
            }
        if (opt.trimLanes)
            trimCoveredLanes(dp.d(), laneSets, lp, ground, 1.0, &reachableCell);
        for (std::size_t mi = 0; mi < dp.merged().size(); ++mi) {
            PlannedCell pc;
            pc.merged = static_cast<int>(mi);
            pc.lanes = std::move(laneSets[mi]);
            if (pc.lanes.empty())
                continue;
            pc.reachable = reachableCell[mi] != 0;
            pc.firstPoint = static_cast<int>(router.size());
            for (const auto& l : pc.lanes) {
                router.add(EndPoint{l.span.first, u});
                router.add(EndPoint{l.span.last, -u});
                pc.laneTimeS += (l.span.last - l.span.first).norm() / opt.time.speedMps;
            }
            if (pc.reachable)
                for (std::size_t j = 0; j + 1 < pc.lanes.size(); ++j) {
                    pc.right.push_back(router.route(pc.pt(j, true), pc.pt(j + 1, true)));
                    pc.left.push_back(router.route(pc.pt(j, false), pc.pt(j + 1, false)));
                }
            fp->cells.push_back(std::move(pc));
        }
        if (home)
            fp->homePt = router.add(EndPoint{*home, Vec2(0, 0)});
        if (landing)
            fp->landingPt = router.add(EndPoint{*landing, Vec2(0, 0)});
        // The order problem over the reachable cells: two ways each (first lane's direction).
        for (std::size_t ci = 0; ci < fp->cells.size(); ++ci) {
            if (stopRequested())
                return makeError(ErrorCode::Cancelled, "planning the sweep: cancelled");
            const auto& pc = fp->cells[ci];
            if (!pc.reachable)
                continue;
            const std::size_t n = pc.lanes.size();
            OrderCell oc;
            for (int parity = 0; parity < (n > 1 ? 2 : 1); ++parity) {
                OrderWay w;
                w.a = pc.pt(0, !leftToRight(0, parity));
                w.b = pc.pt(n - 1, leftToRight(n - 1, parity));
                w.costS = pc.laneTimeS;
                for (std::size_t j = 0; j + 1 < n; ++j)
                    w.costS += (leftToRight(j, parity) ? pc.right[j] : pc.left[j]).timeS;
                oc.ways.push_back(w);
            }
            fp->problem.cells.push_back(oc);
            fp->orderCellOf.push_back(static_cast<int>(ci));
        }
        // The sweep's own order: cells by where they begin across the lanes, then along them.
        {
            std::vector<int> order(fp->orderCellOf.size());
            for (std::size_t k = 0; k < order.size(); ++k)
                order[k] = static_cast<int>(k);
            auto key = [&](int k) {
                const auto& pc = fp->cells[static_cast<std::size_t>(fp->orderCellOf[static_cast<std::size_t>(k)])];
                const auto& l = pc.lanes.front();
                return std::make_pair(l.y, dp.d().frame.toFrame(l.flyA).x());
            };
            std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
            fp->problem.sweepOrder = order;
        }
        fp->problem.link = [&router](int a, int b) { return router.timeS(a, b); };
        fp->problem.lowerBound = [&router](int a, int b) { return router.lowerBound(a, b); };
        if (home) {
            const int h = fp->homePt;
            fp->problem.start = [&router, h](int v) { return router.timeS(h, v); };
        }
        if (landing) {
            const int l = fp->landingPt;
            fp->problem.finish = [&router, l](int v) { return router.timeS(v, l); };
        }
        OrderOptions oo;
        oo.improve = opt.improveOrder;
        oo.maxRounds = opt.maxOrderRounds;
        fp->order = orderCells(fp->problem, oo);
        // The lane-level problem: every lane on its own, so that the search can also fly a few lanes
        // of one cell between two of another (round a zone, say), where cell by cell cannot.
        fp->laneBase.assign(fp->cells.size(), -1);
        for (std::size_t ci = 0; ci < fp->cells.size(); ++ci) {
            if (stopRequested())
                return makeError(ErrorCode::Cancelled, "planning the sweep: cancelled");
            const auto& pc = fp->cells[ci];
            if (!pc.reachable)
                continue;
            fp->laneBase[ci] = static_cast<int>(fp->laneRef.size());
            for (std::size_t j = 0; j < pc.lanes.size(); ++j) {
                fp->laneRef.emplace_back(static_cast<int>(ci), static_cast<int>(j));
                OrderCell oc;
                const auto& l = pc.lanes[j];
                oc.ways.push_back(OrderWay{pc.pt(j, false), pc.pt(j, true), (l.span.last - l.span.first).norm() / opt.time.speedMps});
                fp->laneProblem.cells.push_back(oc);
            }
        }
        auto toLanes = [&](const std::vector<OrderStep>& cellSteps) {
            std::vector<OrderStep> out;
            for (const auto& st : cellSteps) {
                const int ci = fp->orderCellOf[static_cast<std::size_t>(st.cell)];
                const auto& pc = fp->cells[static_cast<std::size_t>(ci)];
                const std::size_t n = pc.lanes.size();
                for (std::size_t k = 0; k < n; ++k) {
                    const std::size_t j = st.reversed ? n - 1 - k : k;
                    const bool ltr = leftToRight(j, st.way) != st.reversed;
                    out.push_back(OrderStep{fp->laneBase[static_cast<std::size_t>(ci)] + static_cast<int>(j), 0, !ltr});
                }
            }
            return out;
        };
        // The construction alone: the sequence the search above started from.
        fp->constructed = toLanes(fp->order.constructed);
        fp->laneProblem.link = fp->problem.link;
        fp->laneProblem.lowerBound = fp->problem.lowerBound;
        fp->laneProblem.start = fp->problem.start;
        fp->laneProblem.finish = fp->problem.finish;
        fp->steps = toLanes(fp->order.steps);
        if (opt.improveOrder && !fp->steps.empty()) {
            // Neighbour lists: the nearest end points of other lanes, found on a grid of lane spacings.
            std::vector<int> pts;
            for (const auto& [ci, j] : fp->laneRef) {
                pts.push_back(fp->cells[static_cast<std::size_t>(ci)].pt(static_cast<std::size_t>(j), false));
                pts.push_back(fp->cells[static_cast<std::size_t>(ci)].pt(static_cast<std::size_t>(j), true));
            }
            fp->near = nearestEndPoints(router, pts, kNeighbours, s);
            const auto& nearRef = fp->near;
            fp->laneProblem.near = [&nearRef](int p) -> const std::vector<int>& { return nearRef[static_cast<std::size_t>(p)]; };
            OrderOptions lo;
            lo.maxRounds = opt.maxOrderRounds;
            lo.focusAboveS = 1.2 * uTurnS;
            OrderResult lr = improveOrder(fp->laneProblem, fp->steps, lo);
            // A second start: the lanes row by row across the area, as a Survey flies its lines, each
            // row's pieces one after the other round the zones between them (the search then moves
            // pieces where a cell of their own pays).
            const auto rows = !opt.rowStart ? std::vector<OrderStep>{} : rowOrders(fp->laneProblem, fp->laneRef, fp->cells, dp.d().frame, s);
            if (!rows.empty()) {
                OrderResult rr = improveOrder(fp->laneProblem, rows, lo);
                if (rr.costS < lr.costS) {
                    lr = std::move(rr);
                    fp->rowStart = true;
                }
            }
            fp->steps = lr.steps;
            fp->timeS = lr.costS;
            fp->laneMoves = lr.moves;
        } else {
            fp->timeS = orderCost(fp->laneProblem, fp->steps);
        }
        // Wedges of ground beyond a lane's end that its own line cannot fly over (a margin there, or
        // the area's edge with keep-inside): about half lie on a turn to the neighbour lane, which
        // photographs them; the rest is missed. A direction may not buy time with coverage.
        for (const auto& pc : fp->cells)
            if (pc.reachable)
                for (const auto& l : pc.lanes)
                    for (double w : {l.wedgeLeftBelow, l.wedgeLeftAbove, l.wedgeRightBelow, l.wedgeRightAbove})
                        fp->missedM2 += 0.25 * std::max(0.0, w - 0.5 * realAlong) * wedgeDepth;
        auto worse = [&](const FullPlan& a, const FullPlan& b) {
            const bool aMiss = a.missedM2 > allowed, bMiss = b.missedM2 > allowed;
            if (aMiss != bMiss)
                return aMiss;
            return aMiss ? a.missedM2 > b.missedM2 + allowed || (a.missedM2 >= b.missedM2 - allowed && a.timeS > b.timeS)
                         : a.timeS > b.timeS;
        };
        // Shared lines leave the ground beside a zone's edge to spot photos (their wedges are counted
        // as missed): among them the search's time decides, the finished flights then weigh the spots.
        // The others are kept: finished too while one could still fly sooner (finishFastest).
        if (!dp.sharedLines.empty()) {
            if (bestShared && bestShared->timeS > fp->timeS)
                std::swap(bestShared, fp);
            if (!bestShared)
                bestShared = std::move(fp);
            else
                otherShared.push_back(std::move(fp));
        } else {
            if (best && worse(*best, *fp))
                std::swap(best, fp);
            if (!best)
                best = std::move(fp);
            else
                otherOwn.push_back(std::move(fp));
        }
    }
    plan.stats.directionsPlanned = static_cast<int>(planRank.size());
    const SweepPlan base = plan;

    // --- a finished plan (flight order, photographed turns, thinned photos, spot photos) of a candidate
    auto finish = [&](FullPlan& fp) {
        SweepPlan plan = base;
        Router& router = *fp.router;
        const DirectionPlan& dp = *fp.dir;
        plan.stats.angleDeg = fp.angleDeg;
        plan.stats.cellsBeforeMerge = static_cast<int>(dp.d().cells.size());
        plan.stats.cellsAfterMerge = static_cast<int>(dp.merged().size());
        plan.stats.orderRounds = fp.order.rounds;
        plan.stats.orderMoves = fp.order.moves + fp.laneMoves;
        plan.stats.linkEvaluations = fp.order.linkEvaluations;
        plan.stats.rowStart = fp.rowStart;
        plan.stats.sharedLines = !dp.sharedLines.empty();
        for (const auto& m : dp.merged()) {
            geo::Polygon poly;
            for (const auto& p : mergedRing(dp.d(), m))
                poly.outer.push_back(dp.d().frame.toWorld(p));
            plan.cells.push_back(std::move(poly));
        }

        // Every point flown for a lane-level sequence, with the links.
        struct Flown {
            std::vector<std::pair<const CellLane*, bool>> lanes; // lane, flown left to right
            std::vector<std::pair<int, int>> refs;               // (planned cell, lane) of each
            std::vector<std::vector<Vec2>> links;
            std::vector<Vec2> homeLink, landingLink;
            int leaving = 0;
            bool broken = false;
        };
        auto fly = [&](const std::vector<OrderStep>& steps) {
            Flown f;
            int lastPt = fp.homePt;
            for (const auto& st : steps) {
                const auto& [ci, j] = fp.laneRef[static_cast<std::size_t>(st.cell)];
                const PlannedCell& pc = fp.cells[static_cast<std::size_t>(ci)];
                const int entry = st.entry(fp.laneProblem);
                if (lastPt >= 0) {
                    Route r = router.route(lastPt, entry);
                    f.broken = f.broken || !r.ok;
                    f.leaving += r.leavesArea && !f.lanes.empty() ? 1 : 0; // the way from home may well
                    if (f.lanes.empty())
                        f.homeLink = std::move(r.mid);
                    else
                        f.links.push_back(std::move(r.mid));
                }
                f.lanes.emplace_back(&pc.lanes[static_cast<std::size_t>(j)], !st.reversed);
                f.refs.emplace_back(ci, j);
                lastPt = st.exit(fp.laneProblem);
            }
            if (fp.landingPt >= 0 && !steps.empty()) {
                Route r = router.route(lastPt, fp.landingPt);
                f.broken = f.broken || !r.ok;
                f.landingLink = std::move(r.mid);
            }
            return f;
        };
        auto flownTime = [&](const Flown& f) {
            FlightTimeAccumulator acc(opt.time);
            if (home)
                acc.add(*home);
            for (const auto& p : f.homeLink)
                acc.add(p);
            for (std::size_t i = 0; i < f.lanes.size(); ++i) {
                const auto& [l, ltr] = f.lanes[i];
                acc.add(ltr ? l->span.first : l->span.last);
                acc.add(ltr ? l->span.last : l->span.first);
                if (i < f.links.size())
                    for (const auto& p : f.links[i])
                        acc.add(p);
            }
            for (const auto& p : f.landingLink)
                acc.add(p);
            if (landing)
                acc.add(*landing);
            return acc.result();
        };
        Flown flown = fly(fp.steps);
        FlightTime time = flownTime(flown);
        {
            // The search works on the same model; keep the construction should it ever fly faster.
            Flown constructed = fly(fp.constructed);
            const FlightTime ct = flownTime(constructed);
            plan.stats.constructedTimeS = ct.totalS;
            if (ct.totalS < time.totalS) {
                flown = std::move(constructed);
                time = ct;
            }
        }
        plan.stats.transitionsLeavingArea = flown.leaving;
        plan.time = time;
        plan.homeLink = flown.homeLink;
        plan.landingLink = flown.landingLink;
        plan.links = std::move(flown.links);
        plan.stats.laneSegments = static_cast<int>(flown.lanes.size());
        plan.lanes.reserve(flown.lanes.size());
        const Vec2 u = dp.d().frame.toWorld(Vec2(1, 0));
        const double reach = 0.5 * realAlong;
        std::vector<std::vector<Vec2>> links;
        for (std::size_t i = 0; i < flown.lanes.size(); ++i) {
            const auto& [l, ltr] = flown.lanes[i];
            Lane lane = makeLane(l->stripA, l->stripB, ph, l->flyA, l->flyB);
            if (!ltr) {
                std::reverse(lane.photos.begin(), lane.photos.end());
                std::swap(lane.stripStart, lane.stripEnd);
                lane.headingDeg = std::fmod(lane.headingDeg + 180.0, 360.0);
            }
            plan.lanes.push_back(std::move(lane));
            plan.laneCells.push_back(fp.cells[static_cast<std::size_t>(flown.refs[i].first)].merged);
            if (i + 1 >= flown.lanes.size())
                break;
            std::vector<Vec2> link = std::move(plan.links[i]);
            // A straight turn to the neighbour lane of the same cell that runs along the boundary past
            // the end photos' reach, through ground only that turn flies over: photos on it.
            const auto& [nl, nltr] = flown.lanes[i + 1];
            const bool neighbours = flown.refs[i].first == flown.refs[i + 1].first &&
                                    std::abs(flown.refs[i].second - flown.refs[i + 1].second) == 1 && ltr != nltr;
            if (neighbours && link.empty()) {
                if (auto side = photographedTurn(*l, ltr, *nl, nltr, u, reach, ph)) {
                    links.push_back({});
                    plan.lanes.push_back(std::move(*side));
                    plan.laneCells.push_back(-1);
                }
            }
            links.push_back(std::move(link));
        }
        plan.links = std::move(links);
        if (opt.thinPhotos) {
            PhotoThinningOptions to;
            to.trackSpacingM = s;
            to.photoSpacingM = ph;
            to.realAcrossM = realAcross;
            to.realAlongM = realAlong;
            plan.stats.photosLeftOut = thinLanePhotos(plan.lanes, {}, to, [&ground](const Vec2& p) {
                return ground.insideArea(p) && !ground.inZone(p);
            });
        }
        if (opt.spotPhotos && !plan.lanes.empty()) {
            SpotPhotoOptions so;
            so.realAcrossM = realAcross;
            so.realAlongM = realAlong;
            so.headingDeg = std::fmod(450.0 - fp.angleDeg, 360.0);
            addSpotPhotos(plan, toSee, noFly, field, grown, ground, opt.keepInside ? region : vgo.keepInside, pockets,
                          anchor, router, so, opt.time, home, landing);
        }
        if (flown.broken)
            plan.warnings.push_back("Some transitions of the sweep found no safe way and fly straight: check the plan.");
        if (flown.leaving > 0 && opt.keepInside)
            plan.warnings.push_back(std::to_string(flown.leaving) +
                                    " transitions leave the area: no way over it keeps the safety margin.");

        // --- ground no photo can see: pockets and ground between zones whose margins merge
        reportUnseenGround(toSee, noFly, grown, freeSpace, pockets, anchor, realAcross, realAlong, plan);
        return plan;
    };
    // The fastest finished flight of one kind of lanes: the search's best, then the others in order of
    // their search's time while that is below the fastest finished so far (a finished flight is never
    // faster than its search's time: the photographed turns and spot photos only add). What finishing
    // adds differs a lot between directions (on a generated area with 19 zones: 1033 s searched, 1308 s
    // finished at 60 degrees; 1036 s and 1207 s at 57.9): the search's time alone picked the slower.
    // An own-lanes plan that leaves more ground to the wedges than allowed is not taken over one that
    // does not.
    auto finishFastest = [&](FullPlan& first, std::vector<std::unique_ptr<FullPlan>>& others, bool ownLanes,
                             double beatS = kInf) {
        SweepPlan fastest = finish(first);
        std::stable_sort(others.begin(), others.end(), [](const auto& a, const auto& b) { return a->timeS < b->timeS; });
        for (auto& o : others) {
            if (o->timeS >= std::min(fastest.time.totalS, beatS) || stopRequested())
                break;
            if (ownLanes && o->missedM2 > allowed && o->missedM2 > first.missedM2)
                continue;
            SweepPlan p = finish(*o);
            if (p.time.totalS < fastest.time.totalS)
                fastest = std::move(p);
        }
        return fastest;
    };
    if (!best || !bestShared)
        return best ? finishFastest(*best, otherOwn, true) : finishFastest(*bestShared, otherShared, false);
    // Shared lines leave some ground to the spot photos: kept only when the flight is faster and the
    // real footprints see as much as with the cells' own lanes (within 0.05 % of the area). A finished
    // flight is never faster than its search's time (the spot photos only add), so the second kind
    // is finished only when it could still win.
    CoverageCheckOptions co;
    co.resolutionM = 0.05 * std::min(realAcross, realAlong);
    co.maxPatches = 0;
    auto unseen = [&](const SweepPlan& sp) {
        std::vector<PhotoFootprint> fps;
        for (const auto& l : sp.lanes)
            for (const auto& p : l.photos)
                fps.push_back(PhotoFootprint{p, l.headingDeg, realAcross, realAlong});
        auto r = checkCoverage(toSee, fps, co);
        return r ? r->uncoveredAreaM2 : kInf;
    };
    const double tolerance = 0.0005 * regionArea;
    // The fastest shared lines left more ground unseen than the cells' own lanes: the next shared
    // variants by the search's time (the lines of another phase or placement leave other wedges)
    // while they could still fly sooner, the first that sees as much taken; else the own lanes.
    auto otherSharedSeeing = [&](SweepPlan& own, double ownUnseen) {
        std::stable_sort(otherShared.begin(), otherShared.end(),
                         [](const auto& a, const auto& b) { return a->timeS < b->timeS; });
        int tried = 0;
        for (auto& o : otherShared) {
            if (o->timeS >= own.time.totalS || tried++ >= kSharedRetries || stopRequested())
                break;
            SweepPlan p = finish(*o);
            if (p.time.totalS < own.time.totalS && unseen(p) <= ownUnseen + tolerance)
                return p;
        }
        return std::move(own);
    };
    auto cancelled = [] { return makeError(ErrorCode::Cancelled, "planning the sweep: cancelled"); };
    if (best->timeS <= bestShared->timeS) {
        SweepPlan own = finishFastest(*best, otherOwn, true);
        if (bestShared->timeS >= own.time.totalS)
            return own;
        if (stopRequested())
            return cancelled();
        SweepPlan shared = finishFastest(*bestShared, otherShared, false, own.time.totalS);
        return shared.time.totalS < own.time.totalS && unseen(shared) <= unseen(own) + tolerance
                   ? shared
                   : otherSharedSeeing(own, unseen(own));
    }
    SweepPlan shared = finishFastest(*bestShared, otherShared, false);
    const double sharedUnseen = unseen(shared);
    // What no footprint can reach stays unseen by any plan: seeing all else but 0.1 % of the area
    // (the cells' own lanes leave up to about that too), shared lines need no comparison when the
    // cells' own lanes cannot fly faster.
    const bool sharedSeesAll = sharedUnseen <= shared.stats.unreachableAreaM2 + 2.0 * tolerance;
    if (best->timeS >= shared.time.totalS && sharedSeesAll)
        return shared;
    if (stopRequested())
        return cancelled();
    SweepPlan own = finishFastest(*best, otherOwn, true, sharedSeesAll ? shared.time.totalS : kInf);
    if (shared.time.totalS >= own.time.totalS)
        return own;
    const double ownUnseen = unseen(own);
    return sharedUnseen <= ownUnseen + tolerance ? shared : otherSharedSeeing(own, ownUnseen);
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
