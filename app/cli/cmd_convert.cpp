// photoflight-cli convert: a waypoint file from one format to another, chosen by the file
// extensions.
#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/export_args.h"

#include "core/io/catalog.h"
#include "core/io/mission_export.h"
#include "core/io/waypoint_formats.h"
#include "core/mission/route_check.h"

#include <algorithm>
#include <iostream>

namespace pf::cli {

const char* const kConvertUsage =
    "Usage: photoflight-cli convert IN OUT [options]\n"
    "\n"
    "Converts a waypoint file, for example a .waypoints file edited in Mission Planner back to a\n"
    "QGroundControl .plan. The formats come from the extensions:\n"
    "  .plan        QGroundControl mission (read and write)\n"
    "  .waypoints   QGC WPL 110 as written by Mission Planner (read and write)\n"
    "  .gpx         GPX 1.1 (read and write; several routes in one file)\n"
    "  .geojson     GeoJSON, also .json (read and write; several routes in one file)\n"
    "  .csv         Litchi mission hub CSV (read and write)\n"
    "  .kmz         DJI WPML for DJI Pilot 2 and FlightHub 2 (read and write; DJI Enterprise aircraft)\n"
    "  .kml         KML for Google Earth (write only)\n"
    "\n"
    "Options:\n"
    "  --aircraft NAME       convert only the route of this aircraft (needed when IN holds "
    "several\n"
    "                        routes and OUT is a .plan, .waypoints, .csv or .kmz)\n"
    PF_CLI_EXPORT_OPTIONS_HELP
    "  --model NAME          the catalog aircraft (with its default camera) that flies the route: a .kmz\n"
    "                        names it, and Litchi and MAVLink files are checked against it (default:\n"
    "                        the catalog aircraft named like the route, as a .kmz names its routes)\n"
    "  --max-altitude M      the highest waypoint altitude allowed (default 120)\n"
    "  --safety-margin M     keep-out distance around the file's no-fly zones (default 5)\n"
    "  --force               write the file even if the route check finds errors or the aircraft\n"
    "                        cannot fly it (Litchi CSV or a MAVLink mission for a DJI Enterprise model);\n"
    "                        a .kmz is never written for an aircraft that is not a DJI Enterprise model\n"
    "\n"
    "Route check: before writing, every route is checked: no waypoint or leg (the legs from and back\n"
    "to home included) within the safety margin of a no-fly zone the file holds (a .plan's geofence\n"
    "exclusion polygons), no waypoint above --max-altitude or below the minimum safe altitude (2 m).\n"
    "A route with an error is refused (exit 2, each problem on stderr) unless --force is given.\n"
    "\n"
    "Take-off, capture, return and landing items are regenerated from the waypoints; a .plan's "
    "geofence\n"
    "and home are kept when the output can hold them.\n"
    "A route that passes through home between sorties (a GPX or GeoJSON route exported with every\n"
    "battery's flight) becomes one .plan, .waypoints, .csv or .kmz per battery, OUT-sortieN.EXT: a vehicle\n"
    "file never flies several batteries.\n"
    "Exit codes: 0 written, 2 bad input (the message names the file and the line or JSON key).\n";

namespace {

// The aircraft flying each route, from the catalog: --model's, else the one named like the route (a
// .kmz names its routes after the DJI aircraft it declares). What the .kmz export and the check of the
// aircraft against the output format need; routes no catalog aircraft flies keep none.
Status addCatalogAircraft(io::ExportContext& ctx, const std::optional<std::string>& model) {
    auto cat = io::loadDefaultCatalog();
    if (!cat)
        return model ? makeError(cat.error().code, "--model: " + cat.error().message) : Status{};
    const fleet::AircraftSpec* chosen = model ? cat->findAircraft(*model) : nullptr;
    if (model && !chosen)
        return makeError(ErrorCode::NotFound,
                         "--model: no aircraft named '" + *model + "' in the catalog (see: photoflight-cli catalog)");
    for (std::size_t i = 0; i < ctx.routes.size(); ++i) {
        auto& r = ctx.routes[i];
        const fleet::AircraftSpec* spec = chosen ? chosen : cat->findAircraft(r.aircraft);
        if (!spec)
            continue;
        // The file may have named the kind only (a plane's .plan): the catalog's aircraft replaces it.
        const auto given = std::find_if(ctx.mission.aircraft.begin(), ctx.mission.aircraft.end(),
                                        [&](const mission::AircraftConfig& a) { return a.name == r.aircraft; });
        if (given != ctx.mission.aircraft.end() && given->camera.imageWidthPx > 0)
            continue; // a whole aircraft already
        mission::AircraftConfig a = mission::aircraftFromCatalog(*spec, cat->findCamera(spec->defaultCamera));
        if (r.aircraft.empty() && given == ctx.mission.aircraft.end())
            r.aircraft = spec->name;
        a.name = r.aircraft;
        if (given != ctx.mission.aircraft.end())
            *given = a;
        else
            ctx.mission.aircraft.push_back(a);
    }
    return {};
}

} // namespace

int runConvert(const std::vector<std::string>& argv) {
    auto specs = exportOptionSpecs();
    specs.push_back({"aircraft"});
    specs.push_back({"model"});
    specs.push_back({"max-altitude"});
    specs.push_back({"safety-margin"});
    specs.push_back({"force", false});
    auto args = Args::parse(argv, specs);
    if (!args)
        return reportError(args.error());
    if (args->positionals().size() != 2)
        return reportError(
            "convert needs an input and an output file (see photoflight-cli convert --help)");
    const std::string& in = args->positionals()[0];
    const std::string& out = args->positionals()[1];

    auto options = exportOptionsFromArgs(*args);
    if (!options)
        return reportError(options.error());
    io::ExportOptions& opt = *options;

    mission::RouteLimits limits;
    limits.maxAltitudeM = 120.0;
    for (auto [name, slot] : {std::pair{"max-altitude", &*limits.maxAltitudeM},
                              std::pair{"safety-margin", &limits.safetyMarginM}}) {
        auto v = args->number(name);
        if (!v)
            return reportError(v.error());
        if (*v) {
            if (!(**v >= 0))
                return reportError(std::string("--") + name + ": must be zero or a positive number of metres");
            *slot = **v;
        }
    }

    auto outFormat = io::formatFromPath(out);
    if (!outFormat)
        return reportError(outFormat.error());
    // --force cannot make a .kmz for an aircraft that is not a DJI Enterprise model (it would have no
    // DJI type to name): that stays an error, not a run that writes nothing.
    opt.forceAircraft = args->has("force") && *outFormat != io::WaypointFormat::WpmlKmz;
    auto imported = io::importWaypoints(in);
    if (!imported)
        return reportError(imported.error());

    if (auto name = args->value("aircraft")) {
        std::vector<route::Route> keep;
        std::string known;
        for (const auto& r : imported->routes) {
            known += (known.empty() ? "" : ", ") +
                     (r.aircraft.empty() ? std::string("(unnamed)") : r.aircraft);
            if (r.aircraft == *name)
                keep.push_back(r);
        }
        if (keep.empty())
            return reportError(in + ": no route of aircraft '" + *name +
                               "' (the file has: " + known + ")");
        imported->routes = keep;
    }
    limits.zones = imported->noFlyZones;
    std::size_t problems = 0;
    for (std::size_t i = 0; i < imported->routes.size(); ++i) {
        const auto& r = imported->routes[i];
        limits.home = r.home ? r.home : imported->home;
        const std::string label = r.aircraft.empty() ? "route " + std::to_string(i + 1) : r.aircraft;
        for (const auto& line : mission::checkRoute(r, limits).messages(in + ": " + label)) {
            std::cerr << "photoflight-cli: " << (args->has("force") ? "warning: " : "error: ") << line << '\n';
            ++problems;
        }
    }
    if (problems > 0 && !args->has("force"))
        return reportError(std::to_string(problems) + " problem(s) in the route check (listed above): " + out +
                           " not written; --force writes it anyway");
    io::ExportContext ctx = io::contextFromImport(*imported);
    if (auto st = addCatalogAircraft(ctx, args->value("model")); !st)
        return reportError(st.error());
    const auto& info = io::formatInfo(*outFormat);
    Status written;
    std::vector<std::string> files{out};
    if (ctx.routes.size() == 1 && info.vehicle) {
        // A route passing through home between sorties is written one file per battery.
        auto r = io::exportVehicleFlights(ctx, 0, *outFormat, out, opt);
        if (!r)
            return reportError(r.error());
        for (const auto& n : r->notes)
            std::cerr << "photoflight-cli: note: " << n << '\n';
        for (const auto& w : r->warnings)
            std::cerr << "photoflight-cli: warning: " << w << '\n';
        files = r->files;
    } else if (ctx.routes.size() == 1) {
        auto r = io::exportRouteFiles(ctx, 0, *outFormat, out, opt);
        if (!r)
            return reportError(r.error());
        for (const auto& n : r->notes)
            std::cerr << "photoflight-cli: note: " << n << '\n';
        files = r->files;
    } else if (info.combined) {
        written = io::exportCombined(ctx, *outFormat, out, opt);
    } else {
        std::string names;
        for (std::size_t i = 0; i < ctx.routes.size(); ++i)
            names += (i ? ", " : "") + ctx.routeLabel(i);
        return reportError(in + " holds " + std::to_string(ctx.routes.size()) + " routes (" +
                           names + ") but a " + info.extension +
                           " file holds one; choose one with --aircraft NAME");
    }
    if (!written)
        return reportError(written.error());
    std::size_t n = 0;
    for (const auto& r : ctx.routes)
        n += r.waypoints.size();
    std::string names;
    for (const auto& f : files)
        names += (names.empty() ? "" : ", ") + f;
    std::cout << "wrote " << names << ": " << ctx.routes.size()
              << (ctx.routes.size() == 1 ? " route, " : " routes, ") << n << " waypoints\n";
    return kExitOk;
}

} // namespace pf::cli
