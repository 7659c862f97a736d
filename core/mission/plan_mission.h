// planMission(): the planning facade, from a Mission to per-aircraft cell paths, waypoints and routes.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/types.h"
#include "core/grid/grid.h"
#include "core/mission/mission.h"
#include "core/mission/mission_plan.h"
#include "core/mission/plan_region.h"
#include "core/plan/cell_path.h"
#include "core/plan/flight_time.h"
#include "core/plan/metrics.h"
#include "core/progress.h"
#include "core/result.h"
#include "core/route/waypoint.h"
#include "core/sensor/camera.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::mission {

// Plans the mission end to end. One aircraft flies the whole admissible area; several share it
// through fleet::splitArea, balanced on the time of the route planRegion makes at a fixed grid
// angle (the mission's, or the one the search picks for the aircraft with the coarsest grid over
// the whole area), from home through the photo waypoints and back. The split is planned to the end
// and corrected with each aircraft's final/estimated time (up to 3 rounds), from the aircraft in
// the mission's order and, if that never came within 3 % of the ideal, reversed (the order places
// the subareas); of the splits tried (each planned at the fixed angle, without the coverage check),
// the one with the smallest makespan among those within 1.10 x the ideal (total time / aircraft),
// else overall, is kept (the next one if its photos miss the 0.995 coverage target or it breaches a
// no-fly margin) and planned with the mission's options. Per aircraft: planRegion over its subarea
// (grid angle: the mission's, or searched per subarea), photos another aircraft already takes are
// dropped, waypoints are kept inside the area if asked, out of every no-fly margin (detours), the
// flight gets its safe transit from and to its home (the aircraft's, else the mission's) and is cut
// into sorties that fit its endurance less options.batteryReserve. Finally altitudes are checked
// for separation (a warning per pair) and an independent check rasterises the real footprints of
// every photo (coverage ratio, uncovered patches) and counts margin breaches. Errors name the
// aircraft and the problem. With `progress`, every stage reports to it (its fraction of the whole
// and its name, "stride: grid" with the automatic choice; with several aircraft "sharing the area:
// estimating flight times" and "sharing the area: planning split 2" while the split is searched,
// then "Falcon 8: stride: grid") and a cancel() makes the call return ErrorCode::Cancelled within a
// fraction of a second (the loops check it through the JobScope this installs).
Result<MissionPlan> planMission(const Mission& m, Progress* progress = nullptr);

} // namespace pf::mission
