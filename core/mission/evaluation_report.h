// The reports of the paper's experiment (plan/evaluation): planners named from the one table of
// planner kinds, so they live here rather than beside the runs in core/plan.
#pragma once

#include "core/plan/evaluation.h"

#include <string>
#include <vector>

namespace pf::mission {

// One line per run: area,planner,start_cell,start_col,start_row,cells,visited,turns,turn_angle_deg,
// distance_m,path_length_m,jumps,revisits,estimated_time_s,planning_ms.
std::string evalCsv(const std::vector<plan::EvalRun>& runs);

// The summary table (one row per area and planner) and, when both are present, the ratios of the
// stride planner to the raster baseline per area and averaged over the areas.
std::string evalTable(const std::vector<plan::EvalSummary>& summary);

} // namespace pf::mission
