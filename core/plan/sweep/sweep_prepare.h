// The sweep's prepared ground: the free space, the ways through it and the lane parameters that
// every direction the sweep tries shares, built once per plan. Internal to the sweep planner.
#pragma once

#include "core/geo/no_fly_field.h"
#include "core/geo/types.h"
#include "core/geo/visibility_graph.h"
#include "core/plan/sweep/sweep_lanes.h"
#include "core/plan/sweep/sweep_planner.h"
#include "core/plan/sweep/sweep_reach.h"
#include "core/plan/sweep/sweep_routing.h"
#include "core/result.h"

#include <memory>
#include <optional>
#include <vector>

namespace pf::plan::sweep_detail {

// Everything below refers to the region, the zones and the options it was built from, and to its
// own members (the lazy graphs to the field, the ground to the grown zones): it is built in place
// and neither copied nor moved.
struct PreparedGround {
    PreparedGround(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                   const SweepOptions& opt);
    PreparedGround(const PreparedGround&) = delete;
    PreparedGround& operator=(const PreparedGround&) = delete;

    // The zones grown by their margin (the free space's holes).
    const geo::MultiPolygon& grown() const { return freeGraph.inflatedZones(); }

    const geo::MultiPolygon& region;
    const std::vector<geo::Polygon>& noFly;
    const SweepOptions& opt;
    // Track spacing, trigger distance, and the real footprint (the spacings when not given).
    double spacingM, photoSpacingM, realAcrossM, realAlongM;

    // --- the ways: transitions over the area (keepInside), else over the free space
    geo::NoFlyField field;
    const geo::VisibilityGraph freeGraph;
    std::shared_ptr<const geo::MultiPolygon> grownOnce;
    // Where transitions stay: the area with keep-inside; without, within half a track spacing of it
    // (as no waypoint of any plan may stray further), unless no such way exists.
    geo::MultiPolygon keepInside;
    const geo::VisibilityGraph keepGraph;
    // The detailed graphs serve the few transitions the coarse ones miss (built when first asked).
    LazyGraph coarseFree, detailedFree, coarseKeep, detailedKeep;
    std::vector<RouteGraph> routeGraphs; // in the order a router tries them

    // --- the ground
    geo::MultiPolygon freeSpace; // the region less the grown zones
    SweepGround ground;
    geo::MultiPolygon toSee; // the ground the photos must see: the region less the zones
    std::optional<geo::Vec2> home, landing;

    // --- reachability: free pieces inside a pocket of the grown zones are reached only from there
    Pockets pockets;
    int anchor = -1; // the pocket flown: the home's, else the one holding the most free space

    // --- the lanes' parameters, and a U-turn's time (two 90° turns and a spacing flown)
    SweepLaneParams lanes;
    double uTurnS = 0.0;
};

} // namespace pf::plan::sweep_detail
