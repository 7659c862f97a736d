// Planning a corridor mission: lanes along the corridor's line (plan::planCorridor) for each
// aircraft over its stretch of the line, the stretches balanced on flight time, each flight
// finished as every mission plan is (detours, transit, sorties, the coverage check on the
// corridor's ground).
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/types.h"
#include "core/mission/mission.h"
#include "core/mission/mission_plan.h"
#include "core/result.h"

#include <optional>
#include <vector>

namespace pf::mission {

// One aircraft's lanes over a stretch of the corridor: `line` in local metres of `frame`, `widthM`
// its width, round `noFly` (local, un-buffered) with the options' safety margin. The plan's
// waypoints are the lanes' photos (headings along the lane), their corners without a photo (Turn)
// and the safe ways between lanes (Transit); plannerChoice says how many lanes. Errors name the
// aircraft.
Result<AircraftPlan>
planCorridorStretch(const std::vector<geo::Vec2>& line, double widthM,
                    const std::vector<geo::Polygon>& noFly, const AircraftConfig& aircraft,
                    const PlannerOptions& options, const geo::LocalFrame& frame,
                    const std::optional<geo::Vec2>& home, const std::optional<geo::Vec2>& landing);

// Cuts between aircraft's stretches (stations along the line) moved out of every bend's reach: at
// least 1 m more than the inside lanes' mitre points lie from the bend (half the width times
// tan(turn / 2)), to the nearer side where the segment leaves room, else to the middle of the
// longer segment beside it. Both stretches then end square across the same segment, and the lanes
// of the stretch holding the bend turn with it whole: their grounds meet without a gap.
std::vector<double> snapCuts(const std::vector<geo::Vec2>& line, std::vector<double> cuts,
                             double widthM);

// planMission for a mission that plansCorridorLanes(m). One aircraft flies the whole corridor;
// several share its line in consecutive stretches (the mission's order along the line, or the
// reverse), balanced on the time each would fly its stretch alone from home and back: each
// stretch's length is scaled by how fast its aircraft flew the last one, until the longest time is
// within 3 % of the average (at most 8 rounds; the most balanced split is kept). Then every flight
// is finished by buildPlan and checked (coverage on the corridor's ground, margin breaches).
Result<MissionPlan> planCorridorMission(const Mission& m);

} // namespace pf::mission
