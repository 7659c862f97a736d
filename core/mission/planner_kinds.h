// The one table of the mission's planner kinds: the name in files and on the command line, the label
// shown to the user and a sentence on what each does. Every list of planners is made from it.
#pragma once

#include "core/mission/mission.h"
#include "core/plan/planner.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::mission {

struct PlannerKindInfo {
    PlannerKind kind;
    const char* id;      // in mission files and on the command line: "stride"
    const char* label;   // shown to the user: "Stride"
    const char* summary; // one sentence for tool tips and help
    // The grid coverage planner behind the kind (plan::planCoverage), for stride, raster, wavefront.
    std::optional<plan::PlannerKind> gridPlanner;
    // Whether its routes keep out of the no-fly zones. The lawnmower does not (it flies what a
    // ground station's Survey flies): a yardstick, not offered as the planner of a mission whose
    // zones it crosses.
    bool avoidsNoFly = true;
    // Why it cannot plan for a plane (fixed-wing, or VTOL in cruise), completing "cannot plan for a
    // plane: ..."; nullptr when it can (its lanes are then joined by turns of the plane's radius).
    const char* notForPlanes = nullptr;
};

// Every planner kind, in the order lists show them.
const std::vector<PlannerKindInfo>& plannerKinds();
const PlannerKindInfo& plannerKindInfo(PlannerKind kind);
std::optional<PlannerKind> plannerKindFromId(const std::string& id);
// "auto, sweep, stride, raster, wavefront or lawnmower", for messages that list what is accepted.
std::string plannerKindIdList();
// Whether the kind plans for a plane (Auto does: it chooses among those that do).
inline bool servesPlanes(const PlannerKindInfo& k) {
    return k.notForPlanes == nullptr;
}
// "auto or sweep": the kinds that plan for a plane, for messages.
std::string planePlannerIdList();

// The same table seen from the grid planners (plan::PlannerKind): their row, their name ("stride") on
// the command line of `photoflight-cli eval` and in its reports, and the list "stride, raster or wavefront".
const PlannerKindInfo& plannerKindInfo(plan::PlannerKind kind);
std::optional<plan::PlannerKind> gridPlannerFromId(const std::string& id);
std::string gridPlannerIdList();

} // namespace pf::mission
