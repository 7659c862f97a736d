// photoflight-cli catalog
#include "app/cli/args.h"
#include "app/cli/commands.h"

namespace pf::cli {

const char* const kCatalogUsage = "Usage: photoflight-cli catalog\n";

int runCatalog(const std::vector<std::string>& /*args*/) {
    return reportError("the catalog command is not available yet", kExitInternal);
}

} // namespace pf::cli
