// photoflight-cli plan: plans the mission and writes plan.geojson and metrics.json.
#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/export_args.h"
#include "app/cli/mission_args.h"

#include "core/io/mission_export.h"
#include "core/io/plan_export.h"
#include "core/io/waypoint_formats.h"
#include "core/mission/plan_geojson.h"
#include "core/mission/plan_messages.h"
#include "core/mission/plan_mission.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/route_check.h"
#include "core/mission/simplify_input.h"
#include "core/mission/validation.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>

namespace pf::cli {

const char* const kPlanUsage =
    "Usage: photoflight-cli plan MISSION.json|AREA [OPTIONS] [--format LIST] [--out DIR]\n"
    "\n"
    "Plans the mission end to end for every aircraft: with several aircraft the area is shared "
    "between\n"
    "them (balanced on the estimated flight times), each plans its part (grid of cells, coverage "
    "path,\n"
    "photo waypoints; by default per aircraft the planner that flies soonest), photos another "
    "aircraft\n"
    "already takes are dropped,\n"
    "waypoints keep out of every no-fly zone and its safety margin (detours), each flight gets its "
    "safe\n"
    "transit from and back to its home and is cut into sorties (batteries) that fit its endurance "
    "less a\n"
    "20 % reserve. Altitudes closer than 10 m between aircraft flying together give a warning. "
    "Finally an\n"
    "independent check lays the real photo footprints over the area (coverage ratio, uncovered "
    "patches)\n"
    "and counts margin breaches. Prints a table per aircraft (photos, photos saved, flight "
    "distance, time,\n"
    "sorties, turns) and the totals with the coverage and the makespan (the longest aircraft's "
    "time).\n"
    "\n"
    "With --out, writes into DIR:\n"
    "  plan.geojson   WGS84 FeatureCollection, one feature per line (written as a stream, about "
    "190\n"
    "                 bytes per photo): per aircraft a LineString of the flown path (home, every\n"
    "                 waypoint, back home; kind \"path\", aircraft, alt_m, footprint_across_m,\n"
    "                 footprint_along_m: the real ground footprint of its photos, photos, "
    "sorties),\n"
    "                 one Point per photo (kind \"photo\", aircraft, seq, alt_m, heading_deg "
    "clockwise\n"
    "                 from north), with --footprints one Polygon per photo (kind \"footprint\",\n"
    "                 aircraft, seq), its subarea (kind \"subarea\") and the uncovered patches "
    "(kind\n"
    "                 \"uncovered\", area_m2)\n"
    "  metrics.json   {\"aircraft\": [{\"name\", cells, photos, path_length_m, distance_m, turns, "
    "jumps,\n"
    "                 revisits, estimated_time_s, time_s (home to home, every sortie), sorties,\n"
    "                 photos_saved, detours, coverage_ratio and uncovered_m2 of its part, ...}],\n"
    "                 \"total\": {..., coverage_ratio, nofly_violations, makespan_s, ideal_s,\n"
    "                 photos_saved}, \"coverage_ratio\", \"nofly_violations\", \"warnings\": "
    "[...],\n"
    "                 \"notes\": [...]}\n"
    "  and per format of --format (the desktop application's export writes the same files):\n"
    "    plan, waypoints, csv, kmz (a vehicle flies them): one file per flight, mission-AIRCRAFT.EXT for an\n"
    "                 aircraft flying one sortie, mission-AIRCRAFT-sortieN.EXT per battery for one that\n"
    "                 needs several (each from home back home; no file flies them all: fly them in\n"
    "                 order); a flight holding more mission items than its autopilot stores (ArduPilot\n"
    "                 650 on 16 KB boards, PX4 500 by default) is written with a warning on stderr\n"
    "    kml, gpx, geojson: mission-AIRCRAFT.EXT with the aircraft's whole path (KML: a folder per\n"
    "                 sortie) plus mission.EXT with every aircraft\n"
    "\n"
    "Options:\n"
    "  --out DIR                    output directory (created if missing)\n"
    "  --force                      write routes the route check finds errors in (see below), and the\n"
    "                               Litchi CSV or MAVLink mission of a DJI Enterprise aircraft; even with\n"
    "                               --force no .kmz is written for an aircraft that is not a DJI Enterprise\n"
    "                               model (a .kmz names the DJI aircraft and camera types)\n"
    "  --footprints                 plan.geojson also holds every photo's ground footprint polygon\n"
    "  --quiet                      no progress line on stderr (shown only when stderr is a terminal)\n"
    "  --progress                   a progress line per stage on stderr, with the seconds since the\n"
    "                               start, even when stderr is not a terminal (logs)\n"
    "  --format LIST                comma-separated waypoint formats to write (needs --out):\n"
    "                                 plan       QGroundControl .plan\n"
    "                                 waypoints  QGC WPL 110 .waypoints (Mission Planner)\n"
    "                                 kml        KML: area, no-fly zones, path, photos, "
    "footprints\n"
    "                                 gpx        GPX waypoints and route\n"
    "                                 geojson    GeoJSON waypoints\n"
    "                                 csv        Litchi mission hub CSV\n"
    "                                 kmz        DJI WPML for DJI Pilot 2 and FlightHub 2 (DJI Enterprise\n"
    "                                            aircraft only: Matrice 30/30T, 300/350 RTK, Mavic 3E/3T/3M,\n"
    "                                            Matrice 4E/4T)\n"
    PF_CLI_MISSION_OPTIONS_HELP
    "Options of the waypoint files (--format plan, waypoints; kmz reads --end, --home-elevation and\n"
    "--altitude-frame auto, relative or amsl):\n"
    PF_CLI_EXPORT_OPTIONS_HELP
    "\n"
    "Several aircraft: repeat --aircraft NAME[:ALT_M] (catalog names, see: photoflight-cli catalog), e.g.\n"
    "  --aircraft \"Falcon 8:40\" --aircraft \"DJI Phantom 4 Pro:45\". Each aircraft flies from its own\n"
    "home if the mission file gives one, else from the mission's home (--home).\n"
    "\n"
    "Planners: auto (the default: per aircraft the plan that flies soonest of sweep, stride and "
    "raster,\n"
    "the choice and the times compared printed after the table), sweep (straight lanes over the "
    "exact\n"
    "area, cell by cell round the no-fly zones), stride (long straight strides, few turns, no "
    "jumps),\n"
    "raster (row or column boustrophedon, the paper's baseline, may jump over holes), wavefront\n"
    "(gradient ascent on a navigation function, 8-connected, the candidate with the smallest "
    "completion\n"
    "time), lawnmower (what a ground station's Survey flies: one angle, straight over the no-fly "
    "zones;\n"
    "a yardstick whose crossings the route check refuses unless --force, and a warning names the "
    "zones\n"
    "it crosses: not a planner for a mission with no-fly zones). Every grid planner's path is\n"
    "flown as straight lanes: photos at the trigger distance, lanes ending where the area ends.\n"
    "--grid-angle auto tries 0, 5, ..., 175 degrees and the directions of the longest edges of "
    "each\n"
    "aircraft's part and keeps the plan with the smallest estimated time T = length / speed + "
    "turn\n"
    "angles / turn rate.\n"
    "\n"
    "Terrain following (--dem FILE, --terrain follow|off, --min-clearance M): every photo at its altitude\n"
    "above the ground under it (constant GSD), lanes and photo spacing for the closest ground a camera\n"
    "sees, every leg checked every metre against the DEM (waypoints inserted where the ground rises),\n"
    "coverage checked with each photo's footprint on the terrain. The MAVLink files then carry altitudes\n"
    "above sea level (--altitude-frame), KML absolute altitudes, GPX elevations above sea level, Litchi\n"
    "altitudes above take-off, a .kmz EGM96 heights (template.kml) and WGS84 ellipsoidal heights\n"
    "(waylines.wpml). A DEM that does not cover the area, holds only no-data there or cannot be\n"
    "read exits with code 2.\n"
    "\n"
    "Route check: every planned route is checked as the desktop application checks it before export:\n"
    "no waypoint or leg (home legs included) within a no-fly zone's safety margin, no waypoint above\n"
    "the aircraft's maximum altitude or below the minimum safe altitude (2 m). A route with an error\n"
    "is refused (exit 2, each problem on stderr, nothing written) unless --force is given. So is a file\n"
    "the aircraft cannot fly: a .kmz for an aircraft that is not a DJI Enterprise model (never written,\n"
    "even with --force), Litchi CSV or a MAVLink mission for a DJI Enterprise aircraft.\n"
    "\n"
    "Exit codes: 0 planned, 2 bad input (message on stderr), 1 internal error.\n"
    "Example: photoflight-cli plan resources/demo/demo_mission.json --format plan,kml --out "
    "plan/\n";

namespace {

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

// Planning progress on stderr. On a terminal one line, rewritten in place at most 10 times a second
// and cleared at the end; elsewhere nothing, unless asked (--progress): then a line per stage with the
// seconds since the start (for logs).
class PlanProgressPrinter {
public:
    PlanProgressPrinter(bool terminal, bool lines) : m_terminal(terminal), m_lines(lines) {}
    ~PlanProgressPrinter() { clear(); }
    void operator()(double f, const std::string& stage) {
        const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
        if (m_lines) {
            if (stage != m_stage)
                std::fprintf(stderr, "photoflight-cli: %6.1f s %3d %% %s\n", now, static_cast<int>(f * 100.0),
                             stage.c_str());
        } else if (m_terminal && (stage != m_stage || now - m_shown >= 0.1)) {
            std::fprintf(stderr, "\r\033[Kplanning: %3d %% %s", static_cast<int>(f * 100.0), stage.c_str());
            std::fflush(stderr);
            m_shown = now;
            m_dirty = true;
        }
        m_stage = stage;
    }
    // Removes the progress line before other output.
    void clear() {
        if (m_dirty)
            std::fprintf(stderr, "\r\033[K");
        m_dirty = false;
    }

private:
    bool m_terminal;
    bool m_lines;
    bool m_dirty = false;
    std::string m_stage;
    double m_shown = -1.0;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

// Why an aircraft cannot fly the files of `formats` (io::aircraftFormatProblem); `kmzLeftOut` counts
// the .kmz files that --force still does not write (a .kmz must name a DJI aircraft).
std::vector<std::string> aircraftProblems(const mission::Mission& m, const mission::MissionPlan& plan,
                                          const std::vector<io::WaypointFormat>& formats,
                                          std::size_t& kmzLeftOut) {
    std::vector<route::Route> routes;
    for (const auto& a : plan.aircraft)
        routes.push_back(a.route);
    const io::ExportContext ctx = io::makeExportContext(m, routes);
    std::vector<std::string> out;
    kmzLeftOut = 0;
    for (const auto fmt : formats)
        for (std::size_t i = 0; i < ctx.routes.size(); ++i) {
            if (std::string why = io::aircraftFormatProblem(ctx, i, fmt); !why.empty()) {
                out.push_back(std::string("--format ") + io::formatInfo(fmt).name + ": " + why);
                kmzLeftOut += fmt == io::WaypointFormat::WpmlKmz ? 1 : 0;
            }
        }
    return out;
}

// plan's options: the mission's, the outputs', and those of the waypoint files.
std::vector<OptionSpec> planOptionSpecs() {
    auto specs = missionOptionSpecs();
    specs.push_back({"out"});
    specs.push_back({"format"});
    specs.push_back({"force", false});
    specs.push_back({"footprints", false});
    specs.push_back({"quiet", false});
    specs.push_back({"progress", false});
    for (auto& s : exportOptionSpecs())
        specs.push_back(s);
    return specs;
}

// The waypoint formats of --format (which needs --out to write them into); none without it.
Result<std::vector<io::WaypointFormat>> formatsFromArgs(const Args& args) {
    std::vector<io::WaypointFormat> formats;
    if (const auto f = args.value("format")) {
        auto list = io::formatListFromString(*f);
        if (!list)
            return makeError(list.error().code, "--format: " + list.error().message);
        if (!args.has("out"))
            return makeError(ErrorCode::InvalidInput,
                             "--format: needs --out DIR to write the files into");
        formats = *list;
    }
    return formats;
}

// The notes on the input: the defaults applied, the hand-edited routes a fresh plan leaves out.
void printInputNotes(const MissionInput& input) {
    const mission::Mission& m = input.mission;
    for (const auto& note : input.notes)
        std::cerr << "photoflight-cli: note: " << note << '\n';
    if (!m.editedRoutes.empty())
        std::cerr << "photoflight-cli: note: the mission file holds " << m.editedRoutes.size()
                  << " hand-edited route"
                  << (m.editedRoutes.size() == 1 ? "; it is" : "s; they are")
                  << " not used: this is a fresh plan (the desktop application keeps and exports "
                     "them)\n";
}

// The mission planned, its progress on stderr as asked (--quiet, --progress).
Result<mission::MissionPlan> planWithProgress(const mission::Mission& m, const Args& args) {
    PlanProgressPrinter printer(!args.has("quiet") && ::isatty(STDERR_FILENO) != 0,
                                args.has("progress"));
    Progress progress([&](double f, const std::string& stage) { printer(f, stage); });
    auto plan = mission::planMission(m, &progress);
    printer.clear();
    return plan;
}

// The plan's warnings and notes on stderr. The planner re-checks the grid and may repeat a
// validation warning (`printed`): each thing is said once.
void printPlanMessages(const mission::MissionPlan& plan, const std::vector<std::string>& printed) {
    for (const auto& w : plan.warnings)
        if (std::find(printed.begin(), printed.end(), w) == printed.end())
            std::cerr << "photoflight-cli: warning: " << w << '\n';
    for (const auto& n : plan.notes)
        std::cerr << "photoflight-cli: note: " << n << '\n';
}

// The check every exported route passes (as in the desktop application), with the files'
// aircraft: each problem on stderr, and kExitOk when the files may be written (none, or --force).
int checkRoutesForFiles(const mission::Mission& m, const mission::MissionPlan& plan,
                        const std::vector<io::WaypointFormat>& formats, bool force) {
    // A route with an error is refused unless the user insists. Against the polygons planned
    // (simplify_input.h: a traced boundary simplified; they hold the given ones, so a route clear
    // of them is clear of the given zones).
    const mission::Mission planned = mission::simplifyInput(m, true).mission;
    auto routeProblems = mission::planRouteErrors(planned, plan);
    // The files' aircraft: a .kmz only for DJI Enterprise aircraft, no Litchi or MAVLink file for
    // them, unless --force (then the .kmz of another aircraft is left out, the others written with
    // a warning).
    std::size_t kmzLeftOut = 0;
    for (auto& p : aircraftProblems(m, plan, formats, kmzLeftOut))
        routeProblems.push_back(std::move(p));
    for (const auto& p : routeProblems)
        std::cerr << "photoflight-cli: " << (force ? "warning: " : "error: ") << p << '\n';
    if (routeProblems.empty() || force)
        return kExitOk;
    const bool onlyKmz = kmzLeftOut == routeProblems.size();
    return reportError(
        std::to_string(routeProblems.size()) +
        " problem(s) in the planned routes (listed above): nothing written; " +
        (onlyKmz ? "--force writes the other files, but no .kmz for an aircraft that is not a DJI "
                   "Enterprise model (choose a DJI aircraft for it)"
         : kmzLeftOut > 0 ? "--force writes them anyway, except the .kmz of an aircraft that is "
                            "not a DJI Enterprise model (no DJI type to name in it)"
                          : "--force writes them anyway"));
}

// The waypoint files of `formats` in `dir`, as the desktop application's export writes them
// (core/io/mission_export.h); their notes and warnings on stderr.
int writeWaypointFiles(const mission::Mission& m, const mission::MissionPlan& plan,
                       const std::vector<io::WaypointFormat>& formats,
                       const std::filesystem::path& dir, const io::ExportOptions& options,
                       std::vector<std::string>& written) {
    std::vector<route::Route> routes;
    for (const auto& a : plan.aircraft)
        routes.push_back(a.route);
    io::MissionExportRequest request;
    request.formats = formats;
    request.folder = dir.string();
    request.options = options;
    auto files = io::exportMission(m, routes, request);
    if (!files)
        return reportError(files.error());
    for (const auto& n : files->notes)
        std::cerr << "photoflight-cli: note: " << n << '\n';
    for (const auto& w : files->warnings)
        std::cerr << "photoflight-cli: warning: " << w << '\n';
    written.insert(written.end(), files->files.begin(), files->files.end());
    return kExitOk;
}

// plan.geojson, metrics.json and the waypoint files into `out` (created if missing), each file
// written listed in `written`.
int writePlanFiles(const std::string& out, const Args& args, const mission::Mission& m,
                   const mission::MissionPlan& plan, const std::vector<io::WaypointFormat>& formats,
                   const io::ExportOptions& options, std::vector<std::string>& written) {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec)
        return reportError(makeError(ErrorCode::IoError, "cannot create the output directory " +
                                                             out + ": " + ec.message()));
    const std::filesystem::path dir(out);
    mission::PlanGeoJsonOptions gj;
    gj.footprints = args.has("footprints");
    if (auto st = mission::writePlanGeoJsonFile(plan, (dir / "plan.geojson").string(), gj); !st)
        return reportError(st.error());
    const char* planner = mission::plannerKindInfo(m.options.planner).id;
    if (int rc = writeFile(dir / "metrics.json", io::planMetricsJson(plan, planner)); rc != kExitOk)
        return rc;
    written.push_back((dir / "plan.geojson").string());
    written.push_back((dir / "metrics.json").string());
    if (formats.empty())
        return kExitOk;
    return writeWaypointFiles(m, plan, formats, dir, options, written);
}

// The table on stdout: a line per aircraft, then the totals.
void printPlanTable(const mission::MissionPlan& plan) {
    char line[512];
    std::snprintf(line, sizeof line, "%-20s %-9s %6s %6s %6s %6s %6s %9s %8s %7s %6s %5s\n",
                  "aircraft", "planner", "alt_m", "angle", "cell_m", "photos", "saved", "dist_m",
                  "time_min", "sorties", "turns", "jumps");
    std::cout << line;
    for (const auto& a : plan.aircraft) {
        const auto& mt = a.metrics;
        std::snprintf(line, sizeof line,
                      "%-20.20s %-9s %6.1f %6.1f %6.1f %6d %6d %9.0f %8.1f %7d %6d %5d\n",
                      a.aircraft.c_str(), mission::plannerKindInfo(a.planner).id, a.altitudeM,
                      a.gridAngleDeg, a.cellSizeM, mt.photos, a.photosSaved, a.flightDistanceM,
                      a.timeS / 60.0, static_cast<int>(a.sorties.size()), a.flight.turns, mt.jumps);
        std::cout << line;
    }
    const auto& t = plan.totals;
    double dist = 0.0;
    int sorties = 0;
    for (const auto& a : plan.aircraft) {
        dist += a.flightDistanceM;
        sorties += static_cast<int>(a.sorties.size());
    }
    std::snprintf(line, sizeof line, "%-20s %-9s %6s %6s %6s %6d %6d %9.0f %8.1f %7d %6d %5d\n",
                  "total", "", "", "", "", t.photos, plan.photosSaved, dist, plan.makespanS / 60.0,
                  sorties, t.flightTurns, t.jumps);
    std::cout << line;
}

// The plan's figures on stdout after the table: coverage, makespan, a double grid's passes, the
// planner chosen, and each terrain-following aircraft's heights.
void printPlanSummary(const mission::MissionPlan& plan) {
    char line[512];
    // The covered share never reads 100 while ground is left unseen (the same figure as in the
    // desktop application's statistics).
    std::snprintf(
        line, sizeof line,
        "coverage %s %% (uncovered %.0f m²), makespan %.1f min (ideal %.1f min, x%.3f), no-fly "
        "violations %d\n",
        mission::coveragePercentText(plan.coverageRatio, plan.uncoveredAreaM2).c_str(),
        plan.uncoveredAreaM2, plan.makespanS / 60.0, plan.idealS / 60.0,
        plan.idealS > 0 ? plan.makespanS / plan.idealS : 1.0, plan.noFlyViolations);
    std::cout << line;
    if (plan.passCoverage.size() == 2) { // a double grid: every point seen by each pass
        std::snprintf(line, sizeof line, "coverage per pass of the double grid: %.2f %%, %.2f %%\n",
                      100.0 * plan.passCoverage[0], 100.0 * plan.passCoverage[1]);
        std::cout << line;
    }
    if (!plan.plannerChoice.empty())
        std::cout << "planner: " << plan.plannerChoice << '\n';
    for (const auto& a : plan.aircraft) {
        if (!a.terrain.active)
            continue;
        const auto& t = a.terrain;
        std::snprintf(line, sizeof line,
                      "terrain: %s %.1f m above the ground (lanes for %.1f m, photo spacing per "
                      "lane: %d photo(s) fewer on %d lane(s)), take-off ground %.1f m, lowest "
                      "clearance %.1f m, %d waypoint(s) inserted, GSD %.2f cm/px (edges down to "
                      "%.2f)\n",
                      a.aircraft.c_str(), t.heightAboveGroundM, t.planningHeightM,
                      t.photosSavedPerLane, t.lanesRespaced, t.homeGroundM, t.lowestClearanceM,
                      t.waypointsInserted, t.gsdCm, t.coarsestGsdCm);
        std::cout << line;
    }
}

} // namespace

int runPlan(const std::vector<std::string>& argv) {
    auto args = Args::parse(argv, planOptionSpecs());
    if (!args)
        return reportError(args.error());
    auto exportOptions = exportOptionsFromArgs(*args);
    if (!exportOptions)
        return reportError(exportOptions.error());
    auto formats = formatsFromArgs(*args);
    if (!formats)
        return reportError(formats.error());
    auto input = missionFromArgs(*args);
    if (!input)
        return reportError(input.error());
    const mission::Mission& m = input->mission;
    printInputNotes(*input);

    std::vector<std::string> printed;
    if (!printValidationProblems(mission::validateMission(m), &printed))
        return kExitBadInput;
    auto plan = planWithProgress(m, *args);
    if (!plan)
        return reportError(plan.error());
    printPlanMessages(*plan, printed);

    const bool force = args->has("force");
    if (int rc = checkRoutesForFiles(m, *plan, *formats, force); rc != kExitOk)
        return rc;
    exportOptions->forceAircraft = force;
    std::vector<std::string> written;
    if (const auto out = args->value("out"))
        if (int rc = writePlanFiles(*out, *args, m, *plan, *formats, *exportOptions, written);
            rc != kExitOk)
            return rc;

    printPlanTable(*plan);
    printPlanSummary(*plan);
    if (!written.empty()) {
        std::cout << "Wrote";
        for (const auto& w : written)
            std::cout << ' ' << w;
        std::cout << '\n';
    }
    return kExitOk;
}

} // namespace pf::cli
