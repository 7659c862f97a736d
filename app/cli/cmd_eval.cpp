// photoflight-cli eval: the paper's experiment (every planner from every contour cell of sample areas).
#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/eval_charts.h"

#include "core/plan/evaluation.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace pf::cli {

const char* const kEvalUsage =
    "Usage: photoflight-cli eval AREA.geojson... [--planners stride,raster] [--paper-rules] [--max-starts N]\n"
    "                            [--out DIR]\n"
    "\n"
    "Runs each planner from every contour cell of each area (the experiment of Santamaria et al.) and\n"
    "prints per area and planner the cells, runs, the lower bound on turns, the average, minimum and\n"
    "maximum number of turns, the average distance (path plus the way back to the first cell), jumps,\n"
    "revisits, estimated time and planning time, then the stride/raster ratios.\n"
    "An AREA file is a GeoJSON FeatureCollection (WGS84) with one polygon whose property role is \"area\"\n"
    "and any number with role \"nofly\"; the property cell_size_m sets the cell size (default 20 m).\n"
    "Sample areas: resources/areas/*.geojson. The grids are built at angle 0 without safety margin.\n"
    "\n"
    "Options:\n"
    "  --planners LIST     comma-separated planners: stride, raster, wavefront (default stride,raster)\n"
    "  --paper-rules       the stride planner with the paper's rules only, without the lane and lead-in\n"
    "                      variants it otherwise compares (to measure what the variants add)\n"
    "  --max-starts N      at most N start cells per area, spread over the contour (default: all)\n"
    "  --out DIR           write DIR/eval.csv (one line per run) and the charts DIR/turns_<area>.png\n"
    "                      (turns per start cell, paper figures 4 and 5) and DIR/averages.png (average\n"
    "                      distance and jumps per area, paper figure 6)\n"
    "\n"
    "Exit codes: 0 done, 2 bad input (message on stderr), 1 internal error.\n"
    "Example: photoflight-cli eval resources/areas/*.geojson --out eval/\n";

int runEval(const std::vector<std::string>& argv) {
    auto args = Args::parse(argv, {{"planners"}, {"paper-rules", false}, {"max-starts"}, {"out"}});
    if (!args)
        return reportError(args.error());
    if (args->positionals().empty())
        return reportError("no area file given (see photoflight-cli eval --help)");
    plan::EvalOptions opt;
    if (const auto list = args->value("planners")) {
        opt.planners.clear();
        std::stringstream ss(*list);
        std::string name;
        while (std::getline(ss, name, ',')) {
            const auto k = plan::parsePlannerKind(name);
            if (!k)
                return reportError("--planners: unknown planner '" + name + "' (use stride, raster or wavefront)");
            opt.planners.push_back(*k);
        }
        if (opt.planners.empty())
            return reportError("--planners: give at least one planner");
    }
    opt.strideVariants = !args->has("paper-rules");
    if (!opt.strideVariants)
        std::cerr << "stride planner: the paper's rules only\n";
    if (auto n = args->number("max-starts"); !n) {
        return reportError(n.error());
    } else if (*n) {
        if (**n < 1)
            return reportError("--max-starts: must be at least 1");
        opt.maxStarts = static_cast<int>(**n);
    }

    std::vector<plan::EvalRun> runs;
    std::vector<int> bounds;
    for (const auto& path : args->positionals()) {
        auto area = plan::loadEvalArea(path);
        if (!area)
            return reportError(area.error());
        auto g = plan::evalGrid(*area);
        if (!g)
            return reportError(makeError(g.error().code, path + ": " + g.error().message));
        const int runs0 = static_cast<int>(runs.size());
        auto r = plan::evaluateArea(area->name, *g, opt);
        runs.insert(runs.end(), r.begin(), r.end());
        const int runsN = static_cast<int>(runs.size());
        bounds.push_back(plan::computeTurnBound(*g).turns);
        std::cerr << area->name << ": " << g->visitCount() << " cells, " << (runsN - runs0) << " runs\n";
    }
    const auto summary = plan::summarise(runs, bounds);
    std::cout << plan::evalTable(summary);

    if (const auto out = args->value("out")) {
        std::error_code ec;
        std::filesystem::create_directories(*out, ec);
        if (ec)
            return reportError(makeError(ErrorCode::IoError, "cannot create " + *out + ": " + ec.message()));
        const std::filesystem::path dir(*out);
        {
            std::ofstream f(dir / "eval.csv", std::ios::binary | std::ios::trunc);
            f << plan::evalCsv(runs);
            if (!f)
                return reportError(makeError(ErrorCode::IoError, "cannot write " + (dir / "eval.csv").string()));
        }
        std::string chartError;
        const int charts = writeEvalCharts(runs, summary, dir.string(), &chartError);
        if (charts < 0)
            return reportError(makeError(ErrorCode::IoError, chartError));
        std::cout << "Wrote " << (dir / "eval.csv").string();
        if (charts > 0)
            std::cout << " and " << charts << " PNG chart(s)";
        std::cout << " to " << dir.string() << '\n';
    }
    return kExitOk;
}

} // namespace pf::cli
