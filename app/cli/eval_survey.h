// The survey mode of photoflight-cli eval (every planner beside the lawnmower) and its area generator.
#pragma once

#include <string>
#include <vector>

namespace pf::cli {

// `photoflight-cli eval --survey ...` and `eval --generate N ...` (the arguments after "eval").
int runEvalSurvey(const std::vector<std::string>& argv);

} // namespace pf::cli
