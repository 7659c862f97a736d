// photoflight-cli eval: the paper's experiment (every planner from every contour cell of sample areas).
#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/eval_charts.h"
#include "app/cli/eval_survey.h"

#include "core/mission/evaluation_report.h"
#include "core/mission/planner_kinds.h"
#include "core/plan/evaluation.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace pf::cli {

const char* const kEvalUsage =
    "Usage: photoflight-cli eval AREA.geojson... [--planners stride,raster] [--paper-rules] [--max-starts N]\n"
    "                            [--out DIR]\n"
    "       photoflight-cli eval --survey AREA.geojson... [--generate N ...] [--planners LIST] [MISSION OPTIONS]\n"
    "                            [--out DIR]\n"
    "       photoflight-cli eval --generate N [--seed S] [--zones N|MIN-MAX] [--size-km2 MIN-MAX]\n"
    "                            [--shapes LIST] --out DIR\n"
    "\n"
    "Without --survey: the stride paper's experiment. Runs each planner from every contour cell of each\n"
    "area and prints per area and planner the cells, runs, the lower bound on turns, the average, minimum\n"
    "and maximum number of turns, the average distance (path plus the way back to the first cell), jumps,\n"
    "revisits, estimated time and planning time, then the stride/raster ratios. The grids are built at\n"
    "angle 0 without safety margin, with the areas' cell size.\n"
    "\n"
    "--survey: the lawnmower comparison. Each area becomes a mission (defaults: a camera of 60 x 45\n"
    "degrees at 30 m, 20 % front and side overlap, 10 m/s, 60 deg/s, the default acceleration, 5 m safety\n"
    "margin, automatic grid angle, endurance unlimited so that no plan is cut into sorties; the mission\n"
    "options below override them), with home at the area's vertex nearest the south-west corner of its\n"
    "bounding box that is clear of the zones' margins, the same for every plan. It is planned with each\n"
    "planner and with the lawnmower, a Survey pattern as ground stations fly it (transects at the track\n"
    "spacing clipped to the area, 10 m turnarounds, a photo where each transect enters the area, then\n"
    "every trigger distance and one where it leaves, the fastest angle and entry that cover the area),\n"
    "which flies straight over the no-fly zones. Printed per area and as medians (all areas, without\n"
    "zones, with zones): each planner's flight time by the one time model, the two simpler measures\n"
    "(path/V + turn angle/omega, the same + 3 s per turn), photos, path and turns as ratios to the\n"
    "lawnmower, photos over the lawnmower's photos outside the zones, coverage and no-fly violations,\n"
    "and the lawnmower's crossings (photos in zones, legs crossing a zone or its margin). A planner that\n"
    "finds no plan is listed with its error.\n"
    "\n"
    "--generate N: N seeded test areas (0.1-0.25 km2 rectangles, rectilinear L/U/T/staircase and convex or\n"
    "concave polygonal sites, with rectangle, circle and U-shaped no-fly zones and zones 2-10 m apart whose\n"
    "margins merge into unreachable pockets). Alone it writes them to --out as area files; with --survey\n"
    "they are compared (and written to DIR/areas/ with --out).\n"
    "\n"
    "An AREA file is a GeoJSON FeatureCollection (WGS84) with one polygon whose property role is \"area\"\n"
    "and any number with role \"nofly\"; the property cell_size_m sets the experiment's cell size (default\n"
    "20 m). Sample areas: resources/areas/*.geojson.\n"
    "\n"
    "Options of the experiment:\n"
    "  --planners LIST     comma-separated planners: stride, raster, wavefront (default stride,raster)\n"
    "  --paper-rules       the stride planner with the paper's rules only, without the lane and lead-in\n"
    "                      variants it otherwise compares (to measure what the variants add)\n"
    "  --max-starts N      at most N start cells per area, spread over the contour (default: all)\n"
    "  --out DIR           write DIR/eval.csv (one line per run) and the charts DIR/turns_<area>.png\n"
    "                      (turns per start cell, paper figures 4 and 5) and DIR/averages.png (average\n"
    "                      distance and jumps per area, paper figure 6)\n"
    "\n"
    "Options of --survey:\n"
    "  --planners LIST     the mission planners to compare (default: every planner)\n"
    "  --out DIR           write DIR/survey.csv (one line per area and plan) and DIR/survey_<area>.png\n"
    "                      (each plan beside the lawnmower's: area, zones, margins, path, photos)\n"
    "  mission options     as for plan, except --area, --nofly and --planner:\n"
    "  --camera NAME | --hfov DEG --vfov DEG, --altitude M | --gsd CM, --overlap F | --front F --side F,\n"
    "  --aircraft NAME[:ALT_M] (one), --grid-angle DEG|auto, --home LON,LAT (for every area),\n"
    "  --safety-margin M, --max-cells N\n"
    "\n"
    "Options of --generate:\n"
    "  --seed S            seed (default 1); area i depends only on S and i, so a larger N extends a set\n"
    "  --zones N|MIN-MAX   no-fly zones per area, drawn uniformly (default 0-20; 0 for a set without zones)\n"
    "  --size-km2 MIN-MAX  area sizes (default 0.1-0.25)\n"
    "  --shapes LIST       rectangle, rectilinear, polygonal (default all three, in turn)\n"
    "\n"
    "Exit codes: 0 done, 2 bad input (message on stderr), 1 internal error.\n"
    "Examples: photoflight-cli eval resources/areas/*.geojson --out eval/\n"
    "          photoflight-cli eval --survey resources/areas/*.geojson --out survey/\n"
    "          photoflight-cli eval --survey --generate 60 --seed 1 --out survey-generated/\n"
    "          photoflight-cli eval --generate 50 --zones 0 --out areas-without-zones/\n";

int runEval(const std::vector<std::string>& argv) {
    for (const auto& a : argv)
        if (a == "--survey" || a == "--generate" || a.rfind("--generate=", 0) == 0)
            return runEvalSurvey(argv);
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
            const auto k = mission::gridPlannerFromId(name);
            if (!k)
                return reportError("--planners: unknown planner '" + name + "' (use " + mission::gridPlannerIdList() +
                                   ")");
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
    std::cout << mission::evalTable(summary);

    if (const auto out = args->value("out")) {
        std::error_code ec;
        std::filesystem::create_directories(*out, ec);
        if (ec)
            return reportError(makeError(ErrorCode::IoError, "cannot create " + *out + ": " + ec.message()));
        const std::filesystem::path dir(*out);
        {
            std::ofstream f(dir / "eval.csv", std::ios::binary | std::ios::trunc);
            f << mission::evalCsv(runs);
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
