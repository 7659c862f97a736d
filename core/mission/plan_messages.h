// The planned mission's messages that the CLI and the desktop application word alike: the ground
// no photo sees (said once, in one unit), the covered share that never reads 100 while some ground
// is unseen, the same per aircraft, and the altitude separation between aircraft in the air
// together.
#pragma once

#include "core/fleet/altitude.h"
#include "core/geo/types.h"
#include "core/mission/mission_plan.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::mission {

// "1,012 m² of the area (1.1 %) is seen by no photo, in 2 patch(es)"; empty when all is seen.
std::string uncoveredMessage(const MissionPlan& plan);

// A covered share (0..1) in percent, with the decimals (up to 3) it takes not to read 100 while
// `uncoveredM2` > 0: "98.9", "99.99", "< 100" beyond that; "100.0" when nothing is unseen.
std::string coveragePercentText(double coveredFraction, double uncoveredM2);

// Per aircraft, its part of the area less the zones (AircraftPlan::admissibleAreaM2) and the plan's
// uncovered patches within it (AircraftPlan::uncoveredAreaM2). Patches beyond those the plan lists
// (MissionPlan::uncovered) are not attributed: see unattributedUncoveredM2.
void attributeUncovered(MissionPlan& plan, const std::vector<geo::Polygon>& noFly);

// The uncovered ground that no aircraft's figure holds (the smallest patches, not listed).
double unattributedUncoveredM2(const MissionPlan& plan);

// The share of aircraft `k`'s part seen by the photos of every aircraft (0..1); unset without a
// coverage check or a part.
std::optional<double> aircraftCoverage(const MissionPlan& plan, std::size_t k);

// One message per pair of aircraft in the air together closer than the separation, and the reason a
// proposal does not fit. A pair taking off from the same home (within 1 m) flies each over its own
// part of the area: a note (MissionPlan::notes); other pairs get a warning.
void addAltitudeMessages(MissionPlan& plan, const fleet::AltitudeCheck& check,
                         const std::vector<fleet::AltitudeSlot>& slots, double separationM,
                         const std::vector<std::optional<geo::Vec2>>& homes);

} // namespace pf::mission
