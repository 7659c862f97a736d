// The memory a plan will need, estimated before anything large is allocated, and the machine's budget.
#pragma once

#include "core/mission/mission.h"
#include "core/result.h"

#include <cstddef>

namespace pf::mission {

struct MemoryEstimate {
    double cells = 0.0;  // grid cells over the aircraft's area (bounding box at the mission's angle)
    double photos = 0.0; // photos the area needs (its area / the effective footprint)
    double bytes = 0.0;  // peak of the whole plan command for one planner
};

// The peak memory of planning `m` with one planner (not Auto), from the cells and photos of every
// aircraft over the whole area: 80 MB of base, 64 bytes per cell (grid, planner state, cell path)
// and 320 bytes per photo (its waypoints in local and WGS84 form, the sortie routes, the footprint
// for the coverage check, the route check). Measured on square sites with 30 zones at 5 m altitude
// (1.25 km: 254 MB, estimate 265 MB; 2.5 km: 801 MB, estimate 824 MB).
MemoryEstimate estimatePlanMemory(const Mission& m);

// What planning may use: 75 % of the physical memory, or of the address-space limit (ulimit -v)
// when that is lower.
std::size_t memoryBudgetBytes();

// TooLarge when `plans` plans at once (the automatic choice holds two: the best so far and the one
// being made) would need more than `budgetBytes`: the message says how much, for how many cells and
// photos, and what altitude or cell size would fit.
Status checkPlanMemory(const Mission& m, std::size_t budgetBytes, int plans = 1);

} // namespace pf::mission
