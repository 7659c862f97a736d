// photoflight-cli validate: checks a mission (or an area with flags) and prints its figures and problems.
#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/mission_args.h"

#include "core/mission/corridor.h"
#include "core/mission/memory_estimate.h"
#include "core/mission/terrain_stage.h"
#include "core/mission/validation.h"

#include <cstdio>
#include <iostream>
#include <string>

namespace pf::cli {

namespace {

std::string fmt(const char* f, double v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

// 1234567 -> "1,234,567"
std::string grouped(double n) {
    std::string s = fmt("%.0f", n), out;
    const int len = static_cast<int>(s.size());
    for (int i = 0; i < len; ++i) {
        out += s[i];
        if ((len - i - 1) % 3 == 0 && i + 1 < len && s[i] != '-')
            out += ',';
    }
    return out;
}

} // namespace

const char* const kValidateUsage =
    "Usage: photoflight-cli validate MISSION.json|AREA [OPTIONS]\n"
    "\n"
    "Checks a mission file, or an area file completed by the options below, and prints the area, the\n"
    "admissible area (area minus no-fly zones), and per aircraft the altitude, GSD, photo footprint (real\n"
    "and effective), cell size and number of grid cells, followed by every problem found:\n"
    "  errors   (the mission cannot be planned): polygons with fewer than 3 distinct vertices, crossing\n"
    "           edges (with the edges and where they cross), zero area, holes outside their polygon,\n"
    "           coordinates out of range, a no-fly zone covering the whole area, altitude <= 0 or above\n"
    "           the aircraft's maximum, GSD <= 0, overlaps outside [0, 1), an area too large for the\n"
    "           cell budget (with the altitude and cell size that would fit), ...\n"
    "  warnings (planning goes on): a no-fly zone outside the area (ignored), cells wholly inside a\n"
    "           safety margin (not flown over; neighbouring photos cover them), a home point inside a\n"
    "           no-fly zone, ...\n"
    "\n"
    "Options (they override the mission file):\n"
    PF_CLI_MISSION_OPTIONS_HELP
    "  --home-elevation M           the take-off point's ground above sea level, for --terrain follow\n"
    "                               (default: the DEM's height there)\n"
    "\n"
    "Without a mission file or --aircraft the catalog's first aircraft is used, and without --altitude or\n"
    "--gsd 100 m (or the aircraft's maximum if lower); the output says so. With --grid-angle auto the\n"
    "cell figures are given for a grid at 0 degrees.\n"
    "\n"
    "Exit codes: 0 no error (warnings allowed), 2 bad input (every error also on stderr), 1 internal error.\n"
    "Example: photoflight-cli validate field.kml --nofly buildings.geojson --camera \"Sony RX1R II\" --gsd 1.5\n";

int runValidate(const std::vector<std::string>& argv) {
    auto specs = missionOptionSpecs();
    specs.push_back({"home-elevation"});
    auto args = Args::parse(argv, specs);
    if (!args)
        return reportError(args.error());
    auto input = missionFromArgs(*args);
    if (!input)
        return reportError(input.error());
    const mission::Mission& m = input->mission;
    const mission::ValidationReport r = mission::validateMission(m);

    std::ostream& os = std::cout;
    os << "Mission:          " << (m.name.empty() ? std::string("(unnamed)") : m.name) << " (" << input->source
       << ")\n";
    for (const auto& n : input->notes)
        os << "Note:             " << n << '\n';
    if (!m.editedRoutes.empty()) {
        os << "Edited routes:    " << m.editedRoutes.size() << " hand-edited route" << (m.editedRoutes.size() == 1 ? "" : "s")
           << " (";
        for (std::size_t i = 0; i < m.editedRoutes.size(); ++i)
            os << (i ? ", " : "") << m.editedRoutes[i].aircraft << ": " << m.editedRoutes[i].waypoints.size()
               << " waypoints";
        os << "), read but not checked here; 'plan' does not use them\n";
    }
    if (m.corridor) // its ground is the area below
        os << "Corridor:         " << fmt("%.2f", mission::corridorLengthM(*m.corridor) / 1000.0) << " km x "
           << fmt("%.0f", m.corridor->widthM) << " m, " << m.corridor->line.size() << " points"
           << (mission::plansCorridorLanes(m) ? " (lanes along the line)" : " (planned as an area)") << "\n";
    os << "Area:             " << grouped(r.areaM2) << " m² (" << fmt("%.2f", r.areaM2 / 10000.0) << " ha)\n";
    os << "Admissible area:  " << grouped(r.admissibleAreaM2) << " m² (area minus " << m.noFlyZones.size()
       << " no-fly zone" << (m.noFlyZones.size() == 1 ? "" : "s") << ")\n";
    if (!m.noFlyZones.empty()) {
        os << "No-fly zones:     ";
        for (std::size_t i = 0; i < m.noFlyZones.size(); ++i)
            os << (i ? ", " : "") << (m.noFlyZones[i].name.empty() ? "#" + std::to_string(i + 1) : m.noFlyZones[i].name);
        os << '\n';
    }
    os << "Safety margin:    " << fmt("%.1f", m.options.safetyMarginM) << " m\n";
    os << "Grid angle:       "
       << (m.options.gridAngleDeg ? fmt("%.1f deg", *m.options.gridAngleDeg) : std::string("auto (figures at 0 deg)"))
       << '\n';
    os << "Cell budget:      " << grouped(static_cast<double>(m.options.maxCells)) << " cells\n";
    if (!m.aircraft.empty()) {
        const mission::MemoryEstimate e = mission::estimatePlanMemory(m);
        if (e.bytes > 0)
            os << "Memory:           about " << fmt("%.2f GB", e.bytes / 1e9) << " to plan with one planner ("
               << fmt("%.2f GB", static_cast<double>(mission::memoryBudgetBytes()) / 1e9)
               << " available to planning here)\n";
    }
    for (const auto& f : r.aircraft) {
        os << "Aircraft \"" << f.name << "\":\n";
        if (f.cellSizeM <= 0) {
            os << "  (no figures: see the errors below)\n";
            continue;
        }
        os << "  altitude        " << fmt("%.1f m", f.altitudeM) << '\n';
        os << "  GSD             " << fmt("%.2f cm/px", f.gsdCm) << '\n';
        os << "  footprint       " << fmt("%.1f", f.footprint.longSideM) << " x "
           << fmt("%.1f m", f.footprint.shortSideM)
           << (f.footprint.aheadM > 0 ? " (across x along the track, the tilted camera's), centred " +
                                            fmt("%.1f m", f.footprint.aheadM) + " ahead of the aircraft\n"
                                      : std::string(" (long side across the track)\n"));
        os << "  effective       " << fmt("%.1f", f.effective.acrossM) << " x " << fmt("%.1f m", f.effective.alongM)
           << " (track spacing x photo spacing, after overlaps)\n";
        os << "  cell size       " << fmt("%.2f m", f.cellSizeM) << '\n';
        if (f.gridBuilt)
            os << "  cells           " << grouped(static_cast<double>(f.cellsToVisit)) << " to photograph ("
               << f.shiftedCells << " shifted away from no-fly zones, " << f.unflyableCells << " unflyable) in a "
               << f.cols << " x " << f.rows << " grid\n";
        else if (f.cols > 0)
            os << "  cells           " << grouped(static_cast<double>(f.cols)) << " x "
               << grouped(static_cast<double>(f.rows)) << " grid (not built: see the errors below)\n";
    }
    // Terrain following: the DEM is read over the area as planning reads it, so that a DEM that does
    // not cover the area, holds only no-data there or cannot be read is an error here too.
    std::vector<geo::Problem> problems = r.problems;
    if (m.terrain.follows() && !r.hasErrors()) {
        os << "Terrain:          following the terrain, minimum clearance " << fmt("%.1f m", m.terrain.minClearanceM)
           << '\n';
        auto geom = mission::localGeometry(m);
        auto t = geom ? mission::loadMissionTerrain(m, *geom)
                      : Result<std::shared_ptr<const mission::MissionTerrain>>(geom.error());
        if (!t) {
            problems.push_back({geo::Severity::Error, t.error().message});
        } else {
            const auto& info = (*t)->info;
            const auto range = (*t)->grid->range();
            os << "  DEM             " << info.path << " (" << info.driver << ", " << info.widthPx << " x "
               << info.heightPx << " px of " << fmt("%.1f m", info.pixelSizeM) << ", " << info.crs << ")"
               << (info.synthetic ? " SYNTHETIC" : "") << '\n';
            os << "  heights         " << info.verticalDatum << "; over the area and around it " << fmt("%.1f", range.first)
               << " to " << fmt("%.1f m", range.second) << '\n';
            if ((*t)->homeGroundM)
                os << "  take-off ground " << fmt("%.1f m", *(*t)->homeGroundM)
                   << (m.terrain.homeElevationM ? " (given)" : " (from the DEM)") << '\n';
            for (std::size_t k = 0; k < m.aircraft.size() && k < (*t)->planningHeightM.size(); ++k)
                os << "  \"" << m.aircraft[k].name << "\": " << fmt("%.1f m", (*t)->heightAboveGroundM[k])
                   << " above the ground under every photo; lanes and photo spacing for "
                   << fmt("%.1f m", (*t)->planningHeightM[k]) << " (the closest ground its camera sees)\n";
        }
    } else if (!m.terrain.demPath.empty() && !m.terrain.follows()) {
        os << "Terrain:          off (DEM " << m.terrain.demPath << " not used for planning)\n";
    }
    int errors = 0, warnings = 0;
    if (!problems.empty())
        os << "Problems:\n";
    for (const auto& p : problems) {
        const bool isError = p.severity == geo::Severity::Error;
        (isError ? errors : warnings)++;
        os << "  " << (isError ? "error: " : "warning: ") << p.message << '\n';
    }
    os << (errors ? "INVALID" : "OK") << ": " << errors << " error" << (errors == 1 ? "" : "s") << ", " << warnings
       << " warning" << (warnings == 1 ? "" : "s") << '\n';
    os.flush();
    // Errors also on stderr, for scripts; warnings are in the report above only (no second copy on the
    // terminal).
    for (const auto& p : problems)
        if (p.severity == geo::Severity::Error)
            std::cerr << "photoflight-cli: error: " << p.message << '\n';
    return errors ? kExitBadInput : kExitOk;
}

} // namespace pf::cli
