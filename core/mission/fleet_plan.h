// Planning a mission flown by several aircraft: the split of the area searched on estimated flight
// times, corrected by planned rounds, and the best split planned in full. Internal to planMission.
#pragma once

#include "core/fleet/capability.h"
#include "core/geo/types.h"
#include "core/mission/mission.h"
#include "core/mission/mission_plan.h"
#include "core/mission/validation.h"
#include "core/result.h"

#include <optional>
#include <vector>

namespace pf::mission::detail {

// What planMission has prepared for the aircraft of a fleet (one entry each, in the mission's
// order).
struct FleetInput {
    const Mission& mission;
    const LocalGeometry& geom;
    std::vector<fleet::Capability> caps;
    std::vector<std::optional<geo::Vec2>> homes;
    std::optional<geo::Vec2> landing;
};

// planMission for two or more aircraft (see plan_mission.h for what it does). Reports its progress
// to the thread's JobScope in three parts: the grid angle of the estimates (5 %), the search of the
// split (to 70 %: every estimate and round plan moves it) and the plan of the split chosen,
// aircraft by aircraft, then the coverage check. Checks for a cancel between estimates and within
// the split's cell moves.
Result<MissionPlan> planFleet(const FleetInput& in);

// Whether another split of the area could bring a plan that misses the coverage target to it. A
// split moves only the boundaries the subareas share: ground unseen farther than `reachM` from
// every such boundary (within a zone's margin, where no aircraft may fly; a corner no lane reaches)
// stays unseen whichever split is flown. So: whether the plan would reach `target` if the uncovered
// ground within `reachM` of two subareas were seen (patches not listed in the plan, the smallest,
// count as such). `regions` are the plan's subareas, one per aircraft.
bool otherSplitCouldReachTarget(const MissionPlan& plan,
                                const std::vector<geo::MultiPolygon>& regions, double reachM,
                                double target);

} // namespace pf::mission::detail
