// photoflight-cli plan
#include "app/cli/args.h"
#include "app/cli/commands.h"

namespace pf::cli {

const char* const kPlanUsage = "Usage: photoflight-cli plan\n";

int runPlan(const std::vector<std::string>& /*args*/) {
    return reportError("the plan command is not available yet", kExitInternal);
}

} // namespace pf::cli
