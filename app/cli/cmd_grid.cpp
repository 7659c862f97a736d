// photoflight-cli grid
#include "app/cli/args.h"
#include "app/cli/commands.h"

namespace pf::cli {

const char* const kGridUsage = "Usage: photoflight-cli grid\n";

int runGrid(const std::vector<std::string>& /*args*/) {
    return reportError("the grid command is not available yet", kExitInternal);
}

} // namespace pf::cli
