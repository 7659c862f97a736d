// photoflight-cli: the headless planner. Dispatches to one command per sub-command name.
#include "app/cli/args.h"
#include "app/cli/commands.h"

#include <cstring>
#include <exception>
#include <iostream>

namespace {

using pf::cli::Command;

const Command kCommands[] = {
    {"validate", "check a mission or area file and report area, cells, footprint, GSD", pf::cli::kValidateUsage,
     pf::cli::runValidate},
    {"grid", "write the cell grid of a mission as GeoJSON", pf::cli::kGridUsage, pf::cli::runGrid},
    {"plan", "compute coverage paths and photo waypoints", pf::cli::kPlanUsage, pf::cli::runPlan},
    {"eval", "compare planners from every contour start cell (the paper's experiment)", pf::cli::kEvalUsage,
     pf::cli::runEval},
    {"catalog", "list the cameras and aircraft of the catalog", pf::cli::kCatalogUsage, pf::cli::runCatalog},
    {"convert", "convert a waypoint file between formats (by file extension)", pf::cli::kConvertUsage,
     pf::cli::runConvert},
    {"upload", "send missions to vehicles over MAVLink and read them back", pf::cli::kUploadUsage, pf::cli::runUpload},
    {"mosaic", "stitch the photos of a flight into a georeferenced GeoTIFF", pf::cli::kMosaicUsage, pf::cli::runMosaic},
};

void printHelp(std::ostream& os) {
    os << "Usage: photoflight-cli COMMAND [ARGS...]\n"
          "       photoflight-cli COMMAND --help\n\n"
          "Plans complete-coverage photo flights for one or several UAVs.\n\nCommands:\n";
    for (const auto& c : kCommands)
        os << "  " << c.name << std::string(10 - std::strlen(c.name), ' ') << c.summary << '\n';
    os << "\nExit codes: 0 success, 2 bad input (message on stderr), 1 internal error.\n"
          "Options: --help, --version\n";
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        printHelp(std::cerr);
        return pf::cli::kExitBadInput;
    }
    const std::string cmd = argv[1];
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
        printHelp(std::cout);
        return pf::cli::kExitOk;
    }
    if (cmd == "--version") {
        std::cout << "photoflight-cli " << PF_VERSION << '\n';
        return pf::cli::kExitOk;
    }
    for (const auto& c : kCommands) {
        if (cmd != c.name)
            continue;
        std::vector<std::string> args(argv + 2, argv + argc);
        for (const auto& a : args) {
            if (a == "--help" || a == "-h") {
                std::cout << c.usage;
                return pf::cli::kExitOk;
            }
        }
        try {
            return c.run(args);
        } catch (const std::exception& e) { // never let a bug end in an abort without a message
            return pf::cli::reportError(std::string("internal error: ") + e.what(), pf::cli::kExitInternal);
        }
    }
    return pf::cli::reportError("unknown command '" + cmd + "' (see photoflight-cli --help)");
}
