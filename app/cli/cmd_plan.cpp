// photoflight-cli plan: plans the mission and writes plan.geojson and metrics.json.
#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/mission_args.h"

#include "core/mission/plan_mission.h"
#include "core/mission/validation.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace pf::cli {

const char* const kPlanUsage =
    "Usage: photoflight-cli plan MISSION.json|AREA [OPTIONS] [--out DIR]\n"
    "\n"
    "Computes the complete-coverage flight of each aircraft: the grid of cells, the path over them\n"
    "(stride planner by default), the photo waypoints, and the figures to compare plans. Prints a summary\n"
    "table; with --out, writes into DIR:\n"
    "  plan.geojson   WGS84 FeatureCollection: per aircraft a LineString of the flown path (home, every\n"
    "                 waypoint, back home; property aircraft) and one Point per photo with the properties\n"
    "                 aircraft, seq, alt_m, heading_deg (clockwise from north)\n"
    "  metrics.json   {\"aircraft\": [{\"name\", cells, photos, path_length_m, distance_m, turns,\n"
    "                 turn_angle_deg, jumps, revisits, estimated_time_s, planning_ms, turn_lower_bound,\n"
    "                 turn_ratio, ...}], \"total\": {...}, \"warnings\": [...]}\n"
    "\n"
    "Options:\n"
    "  --out DIR                    directory for plan.geojson and metrics.json (created if missing)\n"
    PF_CLI_MISSION_OPTIONS_HELP
    "\n"
    "Planners: stride (long straight strides, few turns, no jumps), raster (row or column\n"
    "boustrophedon, the paper's baseline, may jump over holes), wavefront (gradient ascent on a\n"
    "navigation function, 8-connected, the candidate with the smallest completion time).\n"
    "--grid-angle auto tries 0, 5, ..., 175 degrees and the directions of the area's longest edges and\n"
    "keeps the plan with the smallest estimated time T = length / speed + turn angles / turn rate.\n"
    "With several aircraft only the first is planned for now (a warning says so).\n"
    "\n"
    "Exit codes: 0 planned, 2 bad input (message on stderr), 1 internal error.\n"
    "Example: photoflight-cli plan resources/demo/demo_mission.json --grid-angle auto --out plan/\n";

namespace {

const char* plannerLabel(mission::PlannerKind k) {
    switch (k) {
    case mission::PlannerKind::Stride:
        return "stride";
    case mission::PlannerKind::Raster:
        return "raster";
    case mission::PlannerKind::Wavefront:
        return "wavefront";
    }
    return "?";
}

int writeFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    if (!f)
        return reportError(makeError(ErrorCode::IoError, "cannot write " + path.string()));
    f << text;
    f.close();
    if (!f)
        return reportError(makeError(ErrorCode::IoError, "cannot write " + path.string() + " (disk full?)"));
    return kExitOk;
}

} // namespace

int runPlan(const std::vector<std::string>& argv) {
    auto specs = missionOptionSpecs();
    specs.push_back({"out"});
    auto args = Args::parse(argv, specs);
    if (!args)
        return reportError(args.error());
    auto input = missionFromArgs(*args);
    if (!input)
        return reportError(input.error());
    const mission::Mission& m = input->mission;
    for (const auto& note : input->notes)
        std::cerr << "photoflight-cli: note: " << note << '\n';

    const mission::ValidationReport report = mission::validateMission(m);
    for (const auto& p : report.problems)
        if (p.severity == geo::Severity::Warning)
            std::cerr << "photoflight-cli: warning: " << p.message << '\n';
    if (report.hasErrors()) {
        for (const auto& p : report.problems)
            if (p.severity == geo::Severity::Error)
                std::cerr << "photoflight-cli: error: " << p.message << '\n';
        return kExitBadInput;
    }
    auto plan = mission::planMission(m);
    if (!plan)
        return reportError(plan.error());
    for (const auto& w : plan->warnings)
        std::cerr << "photoflight-cli: warning: " << w << '\n';

    const char* planner = plannerLabel(m.options.planner);
    if (const auto out = args->value("out")) {
        std::error_code ec;
        std::filesystem::create_directories(*out, ec);
        if (ec)
            return reportError(makeError(ErrorCode::IoError, "cannot create the output directory " + *out + ": " +
                                                                 ec.message()));
        const std::filesystem::path dir(*out);
        if (int rc = writeFile(dir / "plan.geojson", mission::planToGeoJson(*plan)); rc != kExitOk)
            return rc;
        if (int rc = writeFile(dir / "metrics.json", mission::planMetricsJson(*plan, planner)); rc != kExitOk)
            return rc;
    }

    char line[512];
    std::snprintf(line, sizeof line, "%-20s %-9s %7s %6s %6s %6s %9s %6s %5s %6s %6s %8s\n", "aircraft", "planner",
                  "angle", "cell_m", "cells", "photos", "length_m", "turns", "bound", "jumps", "revis", "time_min");
    std::cout << line;
    for (const auto& a : plan->aircraft) {
        const auto& mt = a.metrics;
        std::snprintf(line, sizeof line, "%-20.20s %-9s %7.1f %6.1f %6d %6d %9.0f %6d %5d %6d %6d %8.1f\n",
                      a.aircraft.c_str(), planner, a.gridAngleDeg, a.cellSizeM, mt.cells, mt.photos, mt.pathLengthM,
                      mt.turns, mt.turnLowerBound, mt.jumps, mt.revisits, mt.estimatedTimeS / 60.0);
        std::cout << line;
    }
    const auto& t = plan->totals;
    std::snprintf(line, sizeof line, "%-20s %-9s %7s %6s %6d %6d %9.0f %6d %5s %6d %6d %8.1f\n", "total", "", "", "",
                  t.cells, t.photos, t.pathLengthM, t.turns, "", t.jumps, t.revisits, t.estimatedTimeS / 60.0);
    std::cout << line;
    if (const auto out = args->value("out"))
        std::cout << "Wrote " << (std::filesystem::path(*out) / "plan.geojson").string() << " and "
                  << (std::filesystem::path(*out) / "metrics.json").string() << '\n';
    return kExitOk;
}

} // namespace pf::cli
