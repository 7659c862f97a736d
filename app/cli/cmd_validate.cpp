// photoflight-cli validate
#include "app/cli/args.h"
#include "app/cli/commands.h"

namespace pf::cli {

const char* const kValidateUsage = "Usage: photoflight-cli validate\n";

int runValidate(const std::vector<std::string>& /*args*/) {
    return reportError("the validate command is not available yet", kExitInternal);
}

} // namespace pf::cli
