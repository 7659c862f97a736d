// The sweep's search in one direction: the lanes of every cell, the order of the cells and then of
// the lanes by flight time, and the ground its lane ends leave unseen. Internal to the sweep
// planner.
#pragma once

#include "core/plan/sweep/sweep_prepare.h"
#include "core/plan/sweep/sweep_state.h"
#include "core/result.h"

#include <memory>

namespace pf::plan::sweep_detail {

// The searched plan of one direction's variant (its order's time in timeS, its missed wedges in
// missedM2); Cancelled when asked to stop. Refers to dp and to g's graphs.
Result<std::unique_ptr<FullPlan>> searchDirection(const PreparedGround& g, const DirectionPlan& dp);

} // namespace pf::plan::sweep_detail
