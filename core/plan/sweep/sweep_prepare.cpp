#include "core/plan/sweep/sweep_prepare.h"

#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <unordered_map>

namespace pf::plan::sweep_detail {

namespace {

// The coarse graphs: corners of the grown zones only, every pair of nodes joined ahead of time.
geo::VisibilityGraphOptions coarseOptions(const SweepOptions& opt,
                                          geo::MultiPolygon keepInside = {}) {
    geo::VisibilityGraphOptions vgo;
    vgo.quadrantSegments = opt.quadrantSegments;
    vgo.coarseCorners = true;
    vgo.allPairs = true;
    vgo.keepInside = std::move(keepInside);
    return vgo;
}

// The detailed graphs: every corner, no all-pairs table (they serve the few transitions the coarse
// ones miss).
geo::VisibilityGraphOptions detailedOptions(const SweepOptions& opt,
                                            geo::MultiPolygon keepInside = {}) {
    geo::VisibilityGraphOptions vgo = coarseOptions(opt, std::move(keepInside));
    vgo.coarseCorners = false;
    vgo.allPairs = false;
    return vgo;
}

// The pocket flown: the home's; without a home, the pocket holding the most free space (the lowest
// id among equals).
int anchorPocket(const Pockets& pockets, const std::optional<geo::Vec2>& home,
                 const geo::MultiPolygon& freeSpace) {
    int anchor = -1;
    if (home)
        return pockets.of(*home);
    std::unordered_map<int, double> areaOf;
    for (const auto& f : freeSpace)
        areaOf[pockets.of(interiorPoint(f))] += geo::area(f);
    double best = -1;
    for (const auto& [id, a] : areaOf)
        if (a > best || (a == best && id < anchor)) {
            best = a;
            anchor = id;
        }
    return anchor;
}

SweepLaneParams laneParams(const SweepOptions& opt, double grownMarginM, double realAcross,
                           double realAlong) {
    SweepLaneParams lp;
    lp.trackSpacingM = opt.trackSpacingM;
    lp.photoSpacingM = opt.photoSpacingM;
    lp.grownMarginM = grownMarginM;
    lp.flyOutsideArea = !opt.keepInside;
    lp.marginRunCapM = 2.0 * std::max(realAlong, opt.photoSpacingM) + 2.0 * grownMarginM;
    lp.neighbourReachM = std::max(0.0, 0.5 * (realAcross - opt.trackSpacingM));
    lp.reachAlongM = 0.5 * realAlong;
    return lp;
}

} // namespace

PreparedGround::PreparedGround(const geo::MultiPolygon& region_,
                               const std::vector<geo::Polygon>& noFly_, const SweepOptions& opt_)
    : region(region_), noFly(noFly_), opt(opt_), spacingM(opt.trackSpacingM),
      photoSpacingM(opt.photoSpacingM),
      realAcrossM(opt.realAcrossM > 0 ? opt.realAcrossM : spacingM),
      realAlongM(opt.realAlongM > 0 ? opt.realAlongM : photoSpacingM),
      field(noFly, opt.safetyMarginM), freeGraph(field, coarseOptions(opt)),
      grownOnce(std::make_shared<const geo::MultiPolygon>(freeGraph.inflatedZones())),
      keepInside(opt.keepInside ? region : geo::buffer(region, 0.5 * opt.trackSpacingM - 0.05, 2)),
      keepGraph(field, coarseOptions(opt, keepInside), grownOnce), coarseFree(freeGraph),
      detailedFree(field, detailedOptions(opt), grownOnce), coarseKeep(keepGraph),
      detailedKeep(field, detailedOptions(opt, keepInside), grownOnce),
      routeGraphs{RouteGraph{&coarseKeep, false}, RouteGraph{&detailedKeep, false},
                  RouteGraph{&coarseFree, true}, RouteGraph{&detailedFree, true}},
      freeSpace(grown().empty() ? region : geo::difference(region, grown())),
      ground(region, noFly, grown()),
      toSee(noFly.empty() ? region
                          : geo::difference(region, geo::MultiPolygon(noFly.begin(), noFly.end()))),
      home(opt.home), landing(opt.landing ? opt.landing : opt.home), pockets(grown()),
      anchor(anchorPocket(pockets, home, freeSpace)),
      lanes(laneParams(opt, freeGraph.inflatedMarginM(), realAcrossM, realAlongM)),
      uTurnS(2.0 * turnCostS(90.0, opt.time) + spacingM / opt.time.speedMps) {}

} // namespace pf::plan::sweep_detail
