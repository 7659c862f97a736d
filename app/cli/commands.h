// The photoflight-cli commands; each lives in its own cmd_*.cpp and returns an exit code.
#pragma once

#include <string>
#include <vector>

namespace pf::cli {

using CommandFn = int (*)(const std::vector<std::string>& args);

struct Command {
    const char* name;
    const char* summary;
    const char* usage; // full help text printed by `photoflight-cli COMMAND --help`
    CommandFn run;
};

int runValidate(const std::vector<std::string>& args);
int runGrid(const std::vector<std::string>& args);
int runPlan(const std::vector<std::string>& args);
int runEval(const std::vector<std::string>& args);
int runCatalog(const std::vector<std::string>& args);
int runConvert(const std::vector<std::string>& args);
int runUpload(const std::vector<std::string>& args);
int runMosaic(const std::vector<std::string>& args);

extern const char* const kValidateUsage;
extern const char* const kGridUsage;
extern const char* const kPlanUsage;
extern const char* const kEvalUsage;
extern const char* const kCatalogUsage;
extern const char* const kConvertUsage;
extern const char* const kUploadUsage;
extern const char* const kMosaicUsage;

} // namespace pf::cli
