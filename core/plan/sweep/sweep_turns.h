// The sweep's photographed turns: the straight turn between two neighbour lanes of a cell that runs
// along the boundary past the end photos' reach, over ground only that turn flies over, carries
// photos of its own. Internal to the sweep planner.
#pragma once

#include "core/geo/types.h"
#include "core/plan/lanes/lane.h"
#include "core/plan/sweep/sweep_lanes.h"

#include <optional>

namespace pf::plan::sweep_detail {

// Lane l flown left to right when ltr, then its neighbour nl (nltr), joined by a straight turn; u:
// the lanes' direction (world), reach: how far a photo sees along the lane (half the real footprint
// along), ph: the trigger distance. The photos on the turn (a lane of its own along the turn, its
// heading the turn's), or nothing when the end photos see all the turn passes over.
std::optional<Lane> photographedTurn(const CellLane& l, bool ltr, const CellLane& nl, bool nltr, const geo::Vec2& u,
                                     double reach, double ph);

} // namespace pf::plan::sweep_detail
