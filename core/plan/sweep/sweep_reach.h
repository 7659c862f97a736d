// Where the sweep may not go and what it cannot see: pockets of free space enclosed by merged margins
// (no safe way enters them), a point inside a polygon to tell which pocket it lies in, and the report
// of the ground no footprint reaches from anywhere the aircraft may fly, and the single photos that
// see what the lanes leave unseen. Internal to the sweep planner.
#pragma once

#include "core/geo/no_fly_field.h"
#include "core/geo/types.h"
#include "core/plan/lanes/spot_photos.h"
#include "core/plan/sweep/sweep_lanes.h"
#include "core/plan/sweep/sweep_planner.h"
#include "core/plan/sweep/sweep_routing.h"

#include <optional>

#include <vector>

namespace pf::plan::sweep_detail {

using geo::Vec2;

// A point inside the polygon: the middle of the widest interval of a horizontal line through it.
Vec2 interiorPoint(const geo::Polygon& poly);

// Pockets: the holes of the grown zones' union, free space that no way from outside enters.
class Pockets {
public:
    explicit Pockets(const geo::MultiPolygon& grown);
    // The innermost pocket holding p, -1 outside every pocket.
    int of(const Vec2& p) const;
    const geo::Polygon& hole(int i) const { return m_holes[static_cast<std::size_t>(i)]; }

private:
    std::vector<geo::Polygon> m_holes;
    std::vector<double> m_areas;
};

// The ground no photo can see: free pieces no safe path reaches from the anchor's piece (pockets),
// and ground between zones whose margins merge, farther from the reachable free space than half the
// footprint's short side reaches; what the plan's photos leave of it, by the independent coverage
// check, goes into plan.stats (unreachablePockets, unreachableAreaM2) and a warning. Convex zones each
// alone in its grown piece hide nothing, and then nothing is checked.
// `ground`: the region less the zones (what the photos must see).
void reportUnseenGround(const geo::MultiPolygon& ground, const std::vector<geo::Polygon>& noFly,
                        const geo::MultiPolygon& grown, const geo::MultiPolygon& freeSpace, const Pockets& pockets,
                        int anchor, double realAcross, double realAlong, SweepPlan& plan);

// Single photos for the ground the plan's lanes leave unseen (plan::chooseSpotPhotos over `ground`,
// the region less the zones), taken from safe places (outside sweepGround's grown zones) of the anchor's free space over `flyOver`, each flown where
// it adds least time on the router's ways (plan::placeSpotPhotos); the plan's time is counted again
// over the whole flight. plan.stats.spotPhotos says how many.
void addSpotPhotos(SweepPlan& plan, const geo::MultiPolygon& ground, const std::vector<geo::Polygon>& noFly,
                   const geo::NoFlyField& field, const geo::MultiPolygon& grown, const SweepGround& sweepGround,
                   const geo::MultiPolygon& flyOver, const Pockets& pockets, int anchor, Router& router, const SpotPhotoOptions& options,
                   const FlightTimeModel& time, const std::optional<Vec2>& home, const std::optional<Vec2>& landing);

} // namespace pf::plan::sweep_detail
