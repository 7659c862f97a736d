// The reports of photoflight-cli eval: one CSV line per run, the summary table with the stride/raster ratios.
#include "core/mission/evaluation_report.h"

#include "core/mission/planner_kinds.h"

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace pf::mission {

std::string evalCsv(const std::vector<plan::EvalRun>& runs) {
    std::string out = "area,planner,start_cell,start_col,start_row,cells,visited,turns,turn_angle_deg,distance_m,"
                      "path_length_m,jumps,revisits,estimated_time_s,planning_ms\n";
    char line[512];
    for (const auto& r : runs) {
        const auto& m = r.metrics;
        std::snprintf(line, sizeof line, "%s,%s,%d,%d,%d,%d,%d,%d,%.3f,%.3f,%.3f,%d,%d,%.3f,%.4f\n", r.area.c_str(),
                      plannerKindInfo(r.planner).id, r.startCell, r.startCol, r.startRow, m.visitable, m.cells, m.turns,
                      m.turnAngleDeg, m.distanceM, m.pathLengthM, m.jumps, m.revisits, m.estimatedTimeS,
                      m.planningMs);
        out += line;
    }
    return out;
}

std::string evalTable(const std::vector<plan::EvalSummary>& summary) {
    std::string out;
    char line[512];
    std::snprintf(line, sizeof line, "%-14s %-9s %5s %5s %5s %8s %5s %5s %10s %6s %6s %8s %8s\n", "area", "planner",
                  "cells", "runs", "bound", "turns", "min", "max", "distance_m", "jumps", "revis", "time_s",
                  "ms/run");
    out += line;
    for (const auto& s : summary) {
        std::snprintf(line, sizeof line, "%-14.14s %-9s %5d %5d %5d %8.1f %5.0f %5.0f %10.0f %6.2f %6.1f %8.0f %8.3f%s\n",
                      s.area.c_str(), plannerKindInfo(s.planner).id, s.cells, s.runs, s.turnLowerBound, s.avgTurns,
                      s.minTurns, s.maxTurns, s.avgDistanceM, s.avgJumps, s.avgRevisits, s.avgTimeS,
                      s.avgPlanningMs, s.incomplete ? "  INCOMPLETE RUNS" : "");
        out += line;
    }
    // Stride versus raster, per area and on average.
    std::map<std::string, std::pair<const plan::EvalSummary*, const plan::EvalSummary*>> pairs;
    std::vector<std::string> order;
    for (const auto& s : summary) {
        if (s.planner != plan::PlannerKind::Stride && s.planner != plan::PlannerKind::Raster)
            continue;
        if (!pairs.count(s.area))
            order.push_back(s.area);
        (s.planner == plan::PlannerKind::Stride ? pairs[s.area].first : pairs[s.area].second) = &s;
    }
    double sumTurns = 0, sumDist = 0, strideJumps = 0;
    int n = 0;
    std::string ratios;
    for (const auto& a : order) {
        const auto [st, ra] = pairs[a];
        if (!st || !ra || ra->avgTurns <= 0 || ra->avgDistanceM <= 0)
            continue;
        const double rt = st->avgTurns / ra->avgTurns, rd = st->avgDistanceM / ra->avgDistanceM;
        std::snprintf(line, sizeof line, "%-14.14s turns x%.3f  distance x%.3f  stride jumps %.2f\n", a.c_str(), rt,
                      rd, st->avgJumps);
        ratios += line;
        sumTurns += rt;
        sumDist += rd;
        strideJumps += st->avgJumps;
        ++n;
    }
    if (n > 0) {
        out += "\nstride / raster (averages over all contour start cells):\n" + ratios;
        std::snprintf(line, sizeof line, "%-14s turns x%.3f  distance x%.3f  stride jumps %.2f\n", "mean of areas",
                      sumTurns / n, sumDist / n, strideJumps / n);
        out += line;
    }
    return out;
}

} // namespace pf::mission
