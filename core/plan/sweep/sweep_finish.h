// Finishing a searched sweep: the flight in its order (or the construction's, should it fly
// sooner), its lanes with their photos and photographed turns, photos thinned, spot photos for the
// ground left unseen, and the ground no photo can see reported. Internal to the sweep planner.
#pragma once

#include "core/plan/sweep/sweep_planner.h"
#include "core/plan/sweep/sweep_prepare.h"
#include "core/plan/sweep/sweep_state.h"

namespace pf::plan::sweep_detail {

// The finished plan of fp, starting from `base` (the statistics of the directions; no lanes yet).
// Uses fp's router, which caches the ways it works out.
SweepPlan finishPlan(const PreparedGround& g, const SweepPlan& base, FullPlan& fp);

} // namespace pf::plan::sweep_detail
