// PNG charts of an evaluation (paper figures 4 to 6), drawn with Qt's raster painter off screen.
#pragma once

#include "core/plan/evaluation.h"

#include <string>
#include <vector>

namespace pf::cli {

// Writes DIR/turns_<area>.png per area (turns per start cell, one line per planner) and DIR/averages.png
// (average distance and average jumps per area and planner). Returns the number of charts written, 0
// when this build has no Qt, or -1 with `error` set when a file cannot be written.
int writeEvalCharts(const std::vector<plan::EvalRun>& runs, const std::vector<plan::EvalSummary>& summary,
                    const std::string& dir, std::string* error);

// Shared by the chart writers: an area name as a file-name part, and (Qt builds only) a headless
// QGuiApplication for the raster paint engine and fonts (no display needed; it lives until the program
// ends).
std::string chartFileName(const std::string& name);
void ensureHeadlessGui();

} // namespace pf::cli
