// Where the sweep may not go and what it cannot see: pockets of free space enclosed by merged margins
// (no safe way enters them), a point inside a polygon to tell which pocket it lies in, and the report
// of the ground no footprint reaches from anywhere the aircraft may fly. Internal to the sweep planner.
#pragma once

#include "core/geo/types.h"
#include "core/plan/sweep_planner.h"

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
void reportUnseenGround(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                        const geo::MultiPolygon& grown, const geo::MultiPolygon& freeSpace, const Pockets& pockets,
                        int anchor, double realAcross, double realAlong, SweepPlan& plan);

} // namespace pf::plan::sweep_detail
