// photoflight-cli catalog: lists the cameras and aircraft of the catalog, as aligned text or JSON.
#include "app/cli/args.h"
#include "app/cli/commands.h"

#include "core/io/catalog.h"
#include "core/sensor/camera.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace pf::cli {

namespace {

constexpr double kReferenceAltitudeM = 100.0;

std::string fmt(const char* f, double a, double b = 0.0, double c = 0.0) {
    char buf[128];
    std::snprintf(buf, sizeof buf, f, a, b, c);
    return buf;
}

// Prints rows as columns padded to their widest cell, two spaces apart; the last column is not padded.
void printTable(std::ostream& os, const std::vector<std::vector<std::string>>& rows) {
    std::vector<std::size_t> width;
    for (const auto& row : rows)
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (width.size() <= i)
                width.push_back(0);
            width[i] = std::max(width[i], row[i].size()); // byte count: the catalog's names are ASCII
        }
    for (const auto& row : rows) {
        std::string line;
        for (std::size_t i = 0; i < row.size(); ++i) {
            line += row[i];
            if (i + 1 < row.size())
                line += std::string(width[i] - row[i].size() + 2, ' ');
        }
        os << line << '\n';
    }
}

std::string definition(const sensor::Camera& c) {
    if (c.hasOptics())
        return fmt("%g x %g mm, f %g mm", c.sensorWidthMm, c.sensorHeightMm, c.focalLengthMm);
    return fmt("FOV %g x %g deg", c.hfovDeg, c.vfovDeg);
}

} // namespace

const char* const kCatalogUsage =
    "Usage: photoflight-cli catalog [--json] [--catalog FILE]\n"
    "\n"
    "Lists the cameras (how each is defined, image size, and its photo footprint and ground sample\n"
    "distance at 100 m above ground) and the aircraft (kind: multirotor, fixed-wing or VTOL; cruise\n"
    "speed; turns: a multirotor's yaw rate, a plane's minimum turn radius and bank; endurance, maximum\n"
    "altitude, default camera) that missions and --aircraft/--camera options can name.\n"
    "\n"
    "The catalog is the bundled catalog.json (found in $PHOTOFLIGHT_DATA_DIR, the installed data folder\n"
    "or the source tree's resources/) merged with your own additions in\n"
    "$XDG_DATA_HOME/photoflight/catalog.json (default ~/.local/share/photoflight/catalog.json); an entry\n"
    "of yours with the same name replaces the bundled one.\n"
    "\n"
    "Options:\n"
    "  --json           print the catalog in the catalog file format instead of a table; save it, edit\n"
    "                   it and put it in the folder above to add your own cameras and aircraft\n"
    "  --catalog FILE   list only this catalog file (to check a file of your own)\n"
    "\n"
    "Exit codes: 0 success, 2 bad input (a catalog that cannot be read, with the file and the entry).\n";

int runCatalog(const std::vector<std::string>& argv) {
    auto args = Args::parse(argv, {{"json", false}, {"catalog", true}});
    if (!args)
        return reportError(args.error());
    if (!args->positionals().empty())
        return reportError("catalog: unexpected argument '" + args->positionals().front() + "' (see --help)");

    auto catalog = args->value("catalog") ? io::loadCatalog(*args->value("catalog")) : io::loadDefaultCatalog();
    if (!catalog)
        return reportError(catalog.error());

    if (args->has("json")) {
        std::cout << io::catalogToJson(*catalog);
        return kExitOk;
    }

    std::vector<std::vector<std::string>> cameras{
        {"CAMERA", "DEFINITION", "IMAGE (px)", "FOOTPRINT AT 100 m", "GSD AT 100 m"}};
    for (const auto& c : catalog->cameras) {
        auto fp = sensor::footprintAt(c, kReferenceAltitudeM);
        auto gsd = sensor::gsdCmAt(c, kReferenceAltitudeM);
        cameras.push_back({c.name, definition(c), std::to_string(c.imageWidthPx) + " x " + std::to_string(c.imageHeightPx),
                           fp ? fmt("%.1f x %.1f m", fp->longSideM, fp->shortSideM) : std::string("-"),
                           gsd ? fmt("%.2f cm/px", *gsd) : std::string("-")});
    }
    std::vector<std::vector<std::string>> aircraft{
        {"AIRCRAFT", "KIND", "SPEED", "TURNS", "ENDURANCE", "MAX ALTITUDE", "DEFAULT CAMERA"}};
    for (const auto& a : catalog->aircraft) {
        // A multirotor turns on the spot at its yaw rate; a plane on a circle of its minimum radius.
        const std::string turns = fleet::fliesAsPlane(a.kind)
                                      ? fmt("radius %.0f m (bank %.0f deg)",
                                            fleet::minTurnRadiusM(a.plane, a.cruiseSpeedMps),
                                            fleet::bankAngleDeg(a.plane, a.cruiseSpeedMps))
                                      : fmt("%g deg/s", a.turnRateDegS);
        aircraft.push_back({a.name, fleet::aircraftKindLabel(a.kind),
                            fmt("%g m/s", a.cruiseSpeedMps), turns, fmt("%g min", a.enduranceMin),
                            fmt("%g m", a.maxAltitudeM),
                            a.defaultCamera.empty() ? std::string("-") : a.defaultCamera});
    }

    std::cout << "Cameras (" << catalog->cameras.size() << ")\n";
    printTable(std::cout, cameras);
    std::cout << "\nAircraft (" << catalog->aircraft.size() << ")\n";
    printTable(std::cout, aircraft);
    return kExitOk;
}

} // namespace pf::cli
