// photoflight-cli convert
#include "app/cli/args.h"
#include "app/cli/commands.h"

namespace pf::cli {

const char* const kConvertUsage = "Usage: photoflight-cli convert\n";

int runConvert(const std::vector<std::string>& /*args*/) {
    return reportError("the convert command is not available yet", kExitInternal);
}

} // namespace pf::cli
