#include "core/plan/sweep/sweep_search.h"

#include "core/job_scope.h"

#include "core/plan/sweep/lane_trim.h"

#include <algorithm>
#include <utility>

namespace pf::plan::sweep_detail {

namespace {

// Lane ends the lane-level search considers joining, per end: the nearest this many.
constexpr int kNeighbours = 10;
// Lanes flown no longer than this many trigger distances are checked for being redundant.
constexpr double kShortLanePhotos = 4.0;

Error cancelled() {
    return makeError(ErrorCode::Cancelled, "planning the sweep: cancelled");
}

// Calls fn(ci, cell) for each reachable planned cell in turn; Cancelled when asked to stop.
template <class Fn> Status forReachableCells(const FullPlan& fp, Fn fn) {
    for (std::size_t ci = 0; ci < fp.cells.size(); ++ci) {
        if (stopRequested())
            return cancelled();
        if (fp.cells[ci].reachable)
            fn(ci, fp.cells[ci]);
    }
    return {};
}

// The lanes of every merged cell, less those other lanes make redundant; per cell whether a safe
// path reaches it (cells in a pocket no safe path reaches are not flown: their lanes see nothing).
std::vector<std::vector<CellLane>> cellLaneSets(const PreparedGround& g, const DirectionPlan& dp,
                                                std::vector<char>& reachableCell) {
    auto safeOutside = [&](const geo::Vec2& a, const geo::Vec2& b) {
        return g.field.segmentIsSafe(a, b);
    };
    std::vector<std::vector<CellLane>> laneSets(dp.merged().size());
    for (std::size_t mi = 0; mi < dp.merged().size(); ++mi)
        laneSets[mi] =
            cellLanes(dp.d(), dp.merged()[mi], dp.heights[mi], g.lanes, g.ground, safeOutside);
    dropCoveredLanes(dp.d(), laneSets, dp.pinned, g.lanes, g.ground, g.realAcrossM, g.realAlongM,
                     kShortLanePhotos * g.photoSpacingM);
    // A merged cell lies in one piece of the free space, so its middle lane tells.
    reachableCell.assign(laneSets.size(), 0);
    for (std::size_t mi = 0; mi < laneSets.size(); ++mi)
        if (!laneSets[mi].empty()) {
            const auto& ml = laneSets[mi][laneSets[mi].size() / 2];
            reachableCell[mi] = g.pockets.of(0.5 * (ml.flyA + ml.flyB)) == g.anchor ? 1 : 0;
        }
    if (g.opt.trimLanes)
        trimCoveredLanes(dp.d(), laneSets, g.lanes, g.ground, 1.0, &reachableCell);
    return laneSets;
}

// The planned cells (those with lanes) with their lane ends on the router and, for the reachable
// ones, the ways between neighbour lanes; then home and landing on the router.
void planCells(const PreparedGround& g, const DirectionPlan& dp, FullPlan& fp) {
    Router& router = *fp.router;
    const geo::Vec2 u = dp.d().frame.toWorld(geo::Vec2(1, 0));
    std::vector<char> reachableCell;
    std::vector<std::vector<CellLane>> laneSets = cellLaneSets(g, dp, reachableCell);
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
            pc.laneTimeS += (l.span.last - l.span.first).norm() / g.opt.time.speedMps;
        }
        if (pc.reachable)
            for (std::size_t j = 0; j + 1 < pc.lanes.size(); ++j) {
                pc.right.push_back(router.route(pc.pt(j, true), pc.pt(j + 1, true)));
                pc.left.push_back(router.route(pc.pt(j, false), pc.pt(j + 1, false)));
            }
        fp.cells.push_back(std::move(pc));
    }
    if (g.home)
        fp.homePt = router.add(EndPoint{*g.home, geo::Vec2(0, 0)});
    if (g.landing)
        fp.landingPt = router.add(EndPoint{*g.landing, geo::Vec2(0, 0)});
}

// The order problem over the reachable cells, two ways each (the first lane's direction), with the
// sweep's own order: cells by where they begin across the lanes, then along them.
Status cellProblem(const DirectionPlan& dp, FullPlan& fp) {
    Status st = forReachableCells(fp, [&](std::size_t ci, const PlannedCell& pc) {
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
        fp.problem.cells.push_back(oc);
        fp.orderCellOf.push_back(static_cast<int>(ci));
    });
    if (!st)
        return st;
    std::vector<int> order(fp.orderCellOf.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        order[k] = static_cast<int>(k);
    auto key = [&](int k) {
        const auto& pc =
            fp.cells[static_cast<std::size_t>(fp.orderCellOf[static_cast<std::size_t>(k)])];
        const auto& l = pc.lanes.front();
        return std::make_pair(l.y, dp.d().frame.toFrame(l.flyA).x());
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
    fp.problem.sweepOrder = order;
    Router& router = *fp.router;
    fp.problem.link = [&router](int a, int b) { return router.timeS(a, b); };
    fp.problem.lowerBound = [&router](int a, int b) { return router.lowerBound(a, b); };
    if (fp.homePt >= 0) {
        const int h = fp.homePt;
        fp.problem.start = [&router, h](int v) { return router.timeS(h, v); };
    }
    if (fp.landingPt >= 0) {
        const int l = fp.landingPt;
        fp.problem.finish = [&router, l](int v) { return router.timeS(v, l); };
    }
    return {};
}

// The lane-level problem: every lane on its own, so that the search can also fly a few lanes of one
// cell between two of another (round a zone, say), where cell by cell cannot. Same links as the
// cells' problem.
Status laneProblem(const PreparedGround& g, FullPlan& fp) {
    fp.laneBase.assign(fp.cells.size(), -1);
    Status st = forReachableCells(fp, [&](std::size_t ci, const PlannedCell& pc) {
        fp.laneBase[ci] = static_cast<int>(fp.laneRef.size());
        for (std::size_t j = 0; j < pc.lanes.size(); ++j) {
            fp.laneRef.emplace_back(static_cast<int>(ci), static_cast<int>(j));
            OrderCell oc;
            const auto& l = pc.lanes[j];
            oc.ways.push_back(OrderWay{pc.pt(j, false), pc.pt(j, true),
                                       (l.span.last - l.span.first).norm() / g.opt.time.speedMps});
            fp.laneProblem.cells.push_back(oc);
        }
    });
    if (!st)
        return st;
    fp.laneProblem.link = fp.problem.link;
    fp.laneProblem.lowerBound = fp.problem.lowerBound;
    fp.laneProblem.start = fp.problem.start;
    fp.laneProblem.finish = fp.problem.finish;
    return {};
}

// A cell-level sequence as the lane-level sequence flying the same lanes the same way.
std::vector<OrderStep> toLanes(const FullPlan& fp, const std::vector<OrderStep>& cellSteps) {
    std::vector<OrderStep> out;
    for (const auto& st : cellSteps) {
        const int ci = fp.orderCellOf[static_cast<std::size_t>(st.cell)];
        const auto& pc = fp.cells[static_cast<std::size_t>(ci)];
        const std::size_t n = pc.lanes.size();
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t j = st.reversed ? n - 1 - k : k;
            const bool ltr = leftToRight(j, st.way) != st.reversed;
            out.push_back(OrderStep{fp.laneBase[static_cast<std::size_t>(ci)] + static_cast<int>(j),
                                    0, !ltr});
        }
    }
    return out;
}

// The lane-level local search from the cells' order and, when it flies sooner, from the lanes row
// by row across the area; fp.steps and fp.timeS become the better one's.
void improveLaneOrder(const PreparedGround& g, const DirectionPlan& dp, FullPlan& fp) {
    const SweepOptions& opt = g.opt;
    if (!opt.improveOrder || fp.steps.empty()) {
        fp.timeS = orderCost(fp.laneProblem, fp.steps);
        return;
    }
    // Neighbour lists: the nearest end points of other lanes, found on a grid of lane spacings.
    std::vector<int> pts;
    for (const auto& [ci, j] : fp.laneRef) {
        pts.push_back(
            fp.cells[static_cast<std::size_t>(ci)].pt(static_cast<std::size_t>(j), false));
        pts.push_back(fp.cells[static_cast<std::size_t>(ci)].pt(static_cast<std::size_t>(j), true));
    }
    fp.near = nearestEndPoints(*fp.router, pts, kNeighbours, g.spacingM);
    const auto& nearRef = fp.near;
    fp.laneProblem.near = [&nearRef](int p) -> const std::vector<int>& {
        return nearRef[static_cast<std::size_t>(p)];
    };
    OrderOptions lo;
    lo.maxRounds = opt.maxOrderRounds;
    lo.focusAboveS = 1.2 * g.uTurnS;
    OrderResult lr = improveOrder(fp.laneProblem, fp.steps, lo);
    // A second start: the lanes row by row across the area, as a Survey flies its lines, each row's
    // pieces one after the other round the zones between them (the search then moves pieces where a
    // cell of their own pays).
    const auto rows =
        !opt.rowStart ? std::vector<OrderStep>{}
                      : rowOrders(fp.laneProblem, fp.laneRef, fp.cells, dp.d().frame, g.spacingM);
    if (!rows.empty()) {
        OrderResult rr = improveOrder(fp.laneProblem, rows, lo);
        if (rr.costS < lr.costS) {
            lr = std::move(rr);
            fp.rowStart = true;
        }
    }
    fp.steps = lr.steps;
    fp.timeS = lr.costS;
    fp.laneMoves = lr.moves;
}

// Wedges of ground beyond a lane's end that its own line cannot fly over (a margin there, or the
// area's edge with keep-inside): about half lie on a turn to the neighbour lane, which photographs
// them; the rest is missed. A direction may not buy time with coverage.
double missedWedgesM2(const PreparedGround& g, const FullPlan& fp) {
    const double s = g.spacingM;
    const double wedgeDepth = std::max(0.0, 0.5 * s - std::max(0.0, 0.5 * (g.realAcrossM - s)));
    double missed = 0.0;
    for (const auto& pc : fp.cells)
        if (pc.reachable)
            for (const auto& l : pc.lanes)
                for (double w :
                     {l.wedgeLeftBelow, l.wedgeLeftAbove, l.wedgeRightBelow, l.wedgeRightAbove})
                    missed += 0.25 * std::max(0.0, w - 0.5 * g.realAlongM) * wedgeDepth;
    return missed;
}

} // namespace

Result<std::unique_ptr<FullPlan>> searchDirection(const PreparedGround& g,
                                                  const DirectionPlan& dp) {
    auto fp = std::make_unique<FullPlan>();
    fp->angleDeg = dp.angleDeg;
    fp->dir = &dp;
    fp->router = std::make_unique<Router>(g.opt.time, g.routeGraphs);
    planCells(g, dp, *fp);
    if (auto ok = cellProblem(dp, *fp); !ok)
        return ok.error();
    OrderOptions oo;
    oo.improve = g.opt.improveOrder;
    oo.maxRounds = g.opt.maxOrderRounds;
    fp->order = orderCells(fp->problem, oo);
    if (auto ok = laneProblem(g, *fp); !ok)
        return ok.error();
    // The construction alone: the sequence the search above started from.
    fp->constructed = toLanes(*fp, fp->order.constructed);
    fp->steps = toLanes(*fp, fp->order.steps);
    improveLaneOrder(g, dp, *fp);
    fp->missedM2 = missedWedgesM2(g, *fp);
    return fp;
}

} // namespace pf::plan::sweep_detail
