// photoflight-cli eval
#include "app/cli/args.h"
#include "app/cli/commands.h"

namespace pf::cli {

const char* const kEvalUsage = "Usage: photoflight-cli eval\n";

int runEval(const std::vector<std::string>& /*args*/) {
    return reportError("the eval command is not available yet", kExitInternal);
}

} // namespace pf::cli
