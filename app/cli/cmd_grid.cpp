// photoflight-cli grid: writes the cell grid of a mission (one aircraft) as GeoJSON.
#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/mission_args.h"

#include "core/io/grid_export.h"
#include "core/mission/validation.h"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace pf::cli {

const char* const kGridUsage =
    "Usage: photoflight-cli grid MISSION.json|AREA [OPTIONS] --out FILE.geojson\n"
    "\n"
    "Builds the grid of cells the planners work on and writes it as a GeoJSON FeatureCollection: one\n"
    "WGS84 polygon per cell with the properties\n"
    "  index, col, row   the cell (index = row * cols + col, row 0 at the grid's bottom)\n"
    "  state             free: photographed from its centre\n"
    "                    shifted: its centre is within a no-fly zone's safety margin, so it is flown at\n"
    "                             the nearest safe point of the cell\n"
    "                    unflyable: overlaps the area but lies wholly within a safety margin (not flown)\n"
    "                    outside: not part of the area (only with --all-cells)\n"
    "  contour           true for a cell to photograph next to a cell that is not (the area's contour)\n"
    "  flight_lon/lat    where the aircraft photographs the cell (null when it does not)\n"
    "The cells are squares whose side is the longest side of the aircraft's effective footprint (the\n"
    "footprint reduced by the overlaps), rotated by the grid angle about the area's centre. A cell is part\n"
    "of the area when it overlaps the area minus the no-fly zones by more than a millionth of its size.\n"
    "\n"
    "Options:\n"
    "  --out FILE                   the GeoJSON file to write (required)\n"
    "  --index N                    the grid of the mission's N-th aircraft (default 1)\n"
    "  --all-cells                  also write the cells outside the area\n"
    PF_CLI_MISSION_OPTIONS_HELP
    "\n"
    "With --grid-angle auto (the default of a mission without an angle) the grid is written at 0 degrees;\n"
    "the planner chooses its own angle when planning.\n"
    "\n"
    "Exit codes: 0 written, 2 bad input (message on stderr), 1 internal error.\n"
    "Example: photoflight-cli grid resources/demo/demo_mission.json --grid-angle 15 --out grid.geojson\n";

int runGrid(const std::vector<std::string>& argv) {
    auto specs = missionOptionSpecs();
    specs.push_back({"out"});
    specs.push_back({"index"});
    specs.push_back({"all-cells", false});
    auto args = Args::parse(argv, specs);
    if (!args)
        return reportError(args.error());
    const auto out = args->value("out");
    if (!out || out->empty())
        return reportError("--out is missing: give the GeoJSON file to write (--out FILE.geojson)");
    auto input = missionFromArgs(*args);
    if (!input)
        return reportError(input.error());
    const mission::Mission& m = input->mission;

    std::size_t which = 0;
    if (auto n = args->number("index"); !n) {
        return reportError(n.error());
    } else if (*n) {
        const double v = **n;
        if (v < 1 || std::floor(v) != v || v > static_cast<double>(m.aircraft.size()))
            return reportError("--index: must be a whole number from 1 to " + std::to_string(m.aircraft.size()) +
                               " (the mission's aircraft), got " + *args->value("index"));
        which = static_cast<std::size_t>(v) - 1;
    }

    if (!printValidationProblems(mission::validateMission(m)))
        return kExitBadInput;
    auto geom = mission::localGeometry(m);
    if (!geom)
        return reportError(geom.error());
    auto opt = mission::gridOptionsFor(m, which);
    if (!opt)
        return reportError(opt.error());
    auto g = grid::Grid::build(geom->area, geom->noFly, *opt);
    if (!g)
        return reportError(g.error());
    io::GridExportOptions eo;
    eo.includeOutside = args->has("all-cells");
    if (auto s = io::writeGridGeoJson(*g, geom->frame, *out, eo); !s)
        return reportError(s.error());

    int shifted = 0, unflyable = 0, outside = 0;
    for (int i = 0; i < g->cellCount(); ++i) {
        shifted += g->state(i) == grid::CellState::Shifted;
        unflyable += g->state(i) == grid::CellState::Unflyable;
        outside += g->state(i) == grid::CellState::Outside;
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "Wrote %d cells to %s: %d to photograph (%d shifted), %d unflyable%s; grid %d x %d, cell size %.2f m, "
                  "angle %.1f deg (aircraft \"%s\")\n",
                  g->cellCount() - (eo.includeOutside ? 0 : outside), out->c_str(), g->visitCount(), shifted,
                  unflyable, eo.includeOutside ? (", " + std::to_string(outside) + " outside").c_str() : "",
                  g->cols(), g->rows(), g->cellSize(), g->angleDeg(), m.aircraft[which].name.c_str());
    std::cout << line;
    return kExitOk;
}

} // namespace pf::cli
