// The waypoint file formats in one place: export by format name, import by file extension.
//
// Exporting a planned mission (what `photoflight-cli plan --format ...` and the GUI call):
//
//   io::ExportContext ctx = io::makeExportContext(mission, routes); // footprints from each camera
//   ctx.trajectories = ...;                 // optional: smoothed paths to draw in KML
//   for (std::size_t i = 0; i < ctx.routes.size(); ++i)
//       io::exportRoute(ctx, i, io::WaypointFormat::QgcPlan, dir + "/" + io::routeFileName(ctx, i,
//       fmt), opts);
//   if (io::formatInfo(fmt).combined)
//       io::exportCombined(ctx, fmt, dir + "/mission.kml", opts);
//
// or all at once: io::exportAll(ctx, fmt, dir, "mission", opts) -> the list of files written, or
// for a planned mission io::exportMission (core/io/mission_export.h): one vehicle file per sortie.
// Reading a file back for editing: io::importWaypoints(path) (format from the extension).
#pragma once

#include "core/io/export_context.h"
#include "core/result.h"

#include <cstddef>
#include <string>
#include <vector>

namespace pf::io {

enum class WaypointFormat { QgcPlan, QgcWpl, Kml, Gpx, GeoJson, LitchiCsv, WpmlKmz };

struct WaypointFormatInfo {
    WaypointFormat format;
    const char* name; // as in --format: "plan", "waypoints", "kml", "gpx", "geojson", "csv", "kmz"
    const char* extension;   // written extension, with the dot
    const char* description; // one line for help texts
    bool canImport;          // every format but KML is read back
    bool combined;           // one file can hold every aircraft (KML, GPX, GeoJSON)
    double minSpacingM;      // closer waypoints are merged: DJI (Litchi) refuses under 0.6 m
    std::size_t maxWaypoints; // more are split into numbered files (Litchi: 99); 0: no limit
    // A vehicle flies the file (.plan, .waypoints, Litchi .csv, ...): it is written per battery,
    // one file per sortie, never one flying them all. Display formats (KML, GPX, GeoJSON) draw
    // the whole path. A format is a vehicle's unless it says otherwise.
    bool vehicle = true;
};

const std::vector<WaypointFormatInfo>& waypointFormats();
const WaypointFormatInfo& formatInfo(WaypointFormat format);

// "plan", "waypoints", "kml", "gpx", "geojson" (also "json"), "csv" (also "litchi"), "kmz" (also
// "wpml", "dji"), case-insensitive.
Result<WaypointFormat> formatFromName(const std::string& name);
// By extension: .plan .waypoints .kml .gpx .geojson .json .csv .kmz
Result<WaypointFormat> formatFromPath(const std::string& path);
// Parses "plan,kml,gpx"; errors name the unknown entry.
Result<std::vector<WaypointFormat>> formatListFromString(const std::string& commaSeparated);

// What an export wrote, and what the user should know about it.
struct ExportReport {
    std::vector<std::string> files;
    std::vector<std::string> notes; // merged waypoints, a route split into several files
};

// Why the route's aircraft cannot fly a file of this format, or empty: a .kmz for an aircraft that
// is not a DJI Enterprise model (wpmlAircraftProblem), Litchi's CSV or a MAVLink mission (.plan,
// .waypoints) for a DJI Enterprise aircraft. KML, GPX and GeoJSON are for viewing and fit any
// aircraft.
std::string aircraftFormatProblem(const ExportContext& ctx, std::size_t routeIndex,
                                  WaypointFormat format);

// What an export does when the route's aircraft cannot fly the format (aircraftFormatProblem):
// refuse (Unsupported, the problem as message) unless options.forceAircraft; forced, `note` says
// so, and `leaveOut` is set for a .kmz, which must name a DJI aircraft: no file is written for it.
struct AircraftFormatCheck {
    std::string note; // empty when the aircraft flies the format
    bool leaveOut = false;
};
Result<AircraftFormatCheck> checkAircraftFormat(const ExportContext& ctx, std::size_t routeIndex,
                                                WaypointFormat format,
                                                const ExportOptions& options);

// One aircraft's route in one file, after checkAircraftFormat (its note among the report's notes;
// a .kmz left out writes no file). Waypoints closer than the format's minimum are merged, and a
// route over the format's waypoint limit (Litchi: 99) is written as numbered files
// "<path stem>-part1.csv", "-part2.csv", ... each starting where the previous one ended.
Result<ExportReport> exportRouteFiles(const ExportContext& ctx, std::size_t routeIndex,
                                      WaypointFormat format, const std::string& path,
                                      const ExportOptions& options = {});
Status exportRoute(const ExportContext& ctx, std::size_t routeIndex, WaypointFormat format,
                   const std::string& path, const ExportOptions& options = {});
// Every route in one file; Unsupported for the formats that hold one vehicle's mission.
Status exportCombined(const ExportContext& ctx, WaypointFormat format, const std::string& path,
                      const ExportOptions& options = {});

// `name` with every run of characters but ASCII letters, digits, '-' and '.' (non-ASCII letters
// included, byte by byte) turned into one '_', none at the end or the start: the rule of every
// exported file name ("DJI Mavic 3 Enterprise #1" -> "DJI_Mavic_3_Enterprise_1"); "aircraft" when
// nothing is left.
std::string fileNameSafe(const std::string& name);
// The aircraft part of route `routeIndex`'s file names: fileNameSafe of its label ("Route N" if
// unnamed), with "_2", "_3", … after a name an earlier route of `ctx` already reads as.
std::string routeFileStem(const ExportContext& ctx, std::size_t routeIndex);
// "<aircraft>.<ext>" by routeFileStem.
std::string routeFileName(const ExportContext& ctx, std::size_t routeIndex, WaypointFormat format);
// Writes "<dir>/<stem>-<aircraft>.<ext>" per route (a vehicle format: one file per sortie of an
// aircraft needing several batteries, see exportMission), plus "<dir>/<stem>.<ext>" with every
// route when the format allows; returns the paths written (and the notes and warnings in `notes`).
Result<std::vector<std::string>> exportAll(const ExportContext& ctx, WaypointFormat format,
                                           const std::string& dir, const std::string& stem,
                                           const ExportOptions& options = {},
                                           std::vector<std::string>* notes = nullptr);

// Reads .plan, .waypoints, .gpx, .geojson/.json or .csv (chosen by extension).
Result<ImportedWaypoints> importWaypoints(const std::string& path);

} // namespace pf::io
