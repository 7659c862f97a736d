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
// (resident peak, estimate: 0.5 km 99 MB, 111 MB; 1.25 km 271 MB, 273 MB; 2.5 km 693 MB, 852 MB;
// 5 km 2.70 GB, 3.17 GB).
MemoryEstimate estimatePlanMemory(const Mission& m);

// The address space a plan whose resident peak is `residentBytes` reserves at its peak: growing
// vectors and freed blocks the allocator keeps mapped, the libraries and thread stacks. Measured
// 1.35 to 1.5 times the resident peak plus about 150 MB on the sites above (5 km: 3.64 GB for
// 2.70 GB resident, 4.16 GB for 2.77 GB before the route's waypoints were reserved exactly); an
// address-space limit (ulimit -v) fails an allocation at this figure, not at the resident one.
double addressSpaceBytes(double residentBytes);

// What planning may hold resident: 75 % of the physical memory, and no more than lets the address
// space (addressSpaceBytes) stay within 95 % of the limit ulimit -v sets, when there is one.
std::size_t memoryBudgetBytes();

// TooLarge when `plans` plans at once (the automatic choice holds two: the best so far and the one
// being made) would need more than `budgetBytes`: the message says how much, for how many cells and
// photos, and what altitude or cell size would fit.
Status checkPlanMemory(const Mission& m, std::size_t budgetBytes, int plans = 1);

} // namespace pf::mission
