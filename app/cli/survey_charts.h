// Pictures of the survey comparison: per area each planner's plan beside the lawnmower's, with Qt's
// raster painter off screen.
#pragma once

#include "core/mission/survey_comparison.h"

#include <string>
#include <vector>

namespace pf::cli {

// Writes DIR/survey_<area>.png per area: one panel per planner and one for the lawnmower, each with the
// area, the no-fly zones and their margins, the path from home and back and the photo points, and the
// figures in the panel's title. Returns the number of pictures written, 0 when this build has no Qt, or
// -1 with `error` set when a file cannot be written.
int writeSurveyCharts(const std::vector<mission::SurveyComparison>& areas, const std::string& dir, std::string* error);

} // namespace pf::cli
