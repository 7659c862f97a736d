// A planned mission's figures as JSON (the CLI's metrics.json): per aircraft its planner and why,
// altitude, cells, photos, lengths, turns, times, sorties, photos saved, detours, terrain figures; the
// totals with the coverage, the no-fly violations and the makespan; the warnings.
#pragma once

#include "core/mission/mission_plan.h"

#include <string>

namespace pf::io {

// {"planner", "aircraft": [{"name", ...metrics, time_s, sorties, photos_saved}], "total": {...,
// coverage_ratio, nofly_violations, makespan_s}, "coverage_ratio", "nofly_violations", "warnings": [...]}.
std::string planMetricsJson(const mission::MissionPlan& plan, const std::string& plannerName);

} // namespace pf::io
