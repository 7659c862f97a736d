// The one table of the mission's planner kinds: the name in files and on the command line, the label
// shown to the user and a sentence on what each does. Every list of planners is made from it.
#pragma once

#include "core/mission/mission.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::mission {

struct PlannerKindInfo {
    PlannerKind kind;
    const char* id;      // in mission files and on the command line: "stride"
    const char* label;   // shown to the user: "Stride"
    const char* summary; // one sentence for tool tips and help
};

// Every planner kind, in the order lists show them.
const std::vector<PlannerKindInfo>& plannerKinds();
const PlannerKindInfo& plannerKindInfo(PlannerKind kind);
std::optional<PlannerKind> plannerKindFromId(const std::string& id);
// "stride, raster or wavefront", for messages that list what is accepted.
std::string plannerKindIdList();

} // namespace pf::mission
