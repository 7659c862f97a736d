#include "core/plan/sweep/sweep_finish.h"

#include "core/plan/lanes/photo_thinning.h"
#include "core/plan/sweep/sweep_reach.h"
#include "core/plan/sweep/sweep_turns.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace pf::plan::sweep_detail {

namespace {

using geo::Vec2;

// Every point flown for a lane-level sequence, with the links.
struct Flown {
    std::vector<std::pair<const CellLane*, bool>> lanes; // lane, flown left to right
    std::vector<std::pair<int, int>> refs;               // (planned cell, lane) of each
    std::vector<std::vector<Vec2>> links;
    std::vector<Vec2> homeLink, landingLink;
    int leaving = 0;
    bool broken = false;
};

// The statistics of the direction and order searched, and the merged cells' outlines.
void describeSearch(const FullPlan& fp, SweepPlan& plan) {
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
}

Flown fly(FullPlan& fp, const std::vector<OrderStep>& steps) {
    Router& router = *fp.router;
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
}

FlightTime flownTime(const PreparedGround& g, const Flown& f) {
    FlightTimeAccumulator acc(g.opt.time);
    if (g.home)
        acc.add(*g.home);
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
    if (g.landing)
        acc.add(*g.landing);
    return acc.result();
}

// The searched order flown; the construction instead should it ever fly faster (the search works on
// the same model).
Flown flySoonest(const PreparedGround& g, FullPlan& fp, SweepPlan& plan) {
    Flown flown = fly(fp, fp.steps);
    FlightTime time = flownTime(g, flown);
    Flown constructed = fly(fp, fp.constructed);
    const FlightTime ct = flownTime(g, constructed);
    plan.stats.constructedTimeS = ct.totalS;
    if (ct.totalS < time.totalS) {
        flown = std::move(constructed);
        time = ct;
    }
    plan.stats.transitionsLeavingArea = flown.leaving;
    plan.time = time;
    plan.homeLink = flown.homeLink;
    plan.landingLink = flown.landingLink;
    plan.stats.laneSegments = static_cast<int>(flown.lanes.size());
    return flown;
}

// The flown lanes with their photos, in flight order, each followed by its link to the next; a
// straight turn to the neighbour lane of the same cell that runs along the boundary past the end
// photos' reach, through ground only that turn flies over, becomes a lane of photos of its own.
void layLanes(const PreparedGround& g, const FullPlan& fp, Flown& flown, SweepPlan& plan) {
    plan.lanes.reserve(flown.lanes.size());
    const Vec2 u = fp.dir->d().frame.toWorld(Vec2(1, 0));
    const double reach = 0.5 * g.realAlongM;
    const double ph = g.photoSpacingM;
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
        std::vector<Vec2> link = std::move(flown.links[i]);
        const auto& [nl, nltr] = flown.lanes[i + 1];
        const bool neighbours = flown.refs[i].first == flown.refs[i + 1].first &&
                                std::abs(flown.refs[i].second - flown.refs[i + 1].second) == 1 &&
                                ltr != nltr;
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
}

// Photos other photos make redundant left out, single photos for the ground the lanes leave unseen.
void refinePhotos(const PreparedGround& g, const FullPlan& fp, SweepPlan& plan) {
    const SweepOptions& opt = g.opt;
    if (opt.thinPhotos) {
        PhotoThinningOptions to;
        to.trackSpacingM = g.spacingM;
        to.photoSpacingM = g.photoSpacingM;
        to.realAcrossM = g.realAcrossM;
        to.realAlongM = g.realAlongM;
        const SweepGround& ground = g.ground;
        plan.stats.photosLeftOut = thinLanePhotos(plan.lanes, {}, to, [&ground](const Vec2& p) {
            return ground.insideArea(p) && !ground.inZone(p);
        });
    }
    if (opt.spotPhotos && !plan.lanes.empty()) {
        SpotPhotoOptions so;
        so.realAcrossM = g.realAcrossM;
        so.realAlongM = g.realAlongM;
        so.headingDeg = std::fmod(450.0 - fp.angleDeg, 360.0);
        addSpotPhotos(plan, g.toSee, g.noFly, g.field, g.grown(), g.ground, g.keepInside, g.pockets,
                      g.anchor, *fp.router, so, opt.time, g.home, g.landing);
    }
}

} // namespace

SweepPlan finishPlan(const PreparedGround& g, const SweepPlan& base, FullPlan& fp) {
    SweepPlan plan = base;
    describeSearch(fp, plan);
    Flown flown = flySoonest(g, fp, plan);
    layLanes(g, fp, flown, plan);
    refinePhotos(g, fp, plan);
    if (flown.broken)
        plan.warnings.push_back(
            "Some transitions of the sweep found no safe way and fly straight: check the plan.");
    if (flown.leaving > 0 && g.opt.keepInside)
        plan.warnings.push_back(
            std::to_string(flown.leaving) +
            " transitions leave the area: no way over it keeps the safety margin.");
    // Ground no photo can see: pockets and ground between zones whose margins merge.
    reportUnseenGround(g.toSee, g.noFly, g.grown(), g.freeSpace, g.pockets, g.anchor, g.realAcrossM,
                       g.realAlongM, plan);
    return plan;
}

} // namespace pf::plan::sweep_detail
