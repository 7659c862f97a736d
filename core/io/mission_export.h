// Writing a planned mission's waypoint files: the one function behind `photoflight-cli plan
// --format` and the desktop application's export, so both write the same files for the same
// mission. A vehicle file never asks one battery for more than it holds.
#pragma once

#include "core/io/export_context.h"
#include "core/io/mission_limits.h"
#include "core/io/waypoint_formats.h"
#include "core/mission/mission.h"
#include "core/result.h"
#include "core/route/waypoint.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::io {

struct MissionExportRequest {
    std::vector<WaypointFormat> formats;
    std::string folder;           // must exist
    std::string stem = "mission"; // every file name starts with it
    bool perAircraft = true;      // display formats: "<stem>-<aircraft>.<ext>" per aircraft
    bool combined = true;         // display formats: "<stem>.<ext>" with every aircraft
    ExportOptions options;
    // KML draws each flight's smoothed trajectory (computed here, kept out of the no-fly margins).
    bool kmlTrajectories = true;
};

struct MissionExportReport {
    std::vector<std::string> files;    // in the order written
    std::vector<std::string> notes;    // sorties, merged waypoints, Litchi parts
    std::vector<std::string> warnings; // flights over their autopilot's mission item limit
};

// Writes the files of every route (one per aircraft, as planned or edited: an aircraft needing
// several batteries flies through home between two sorties), format after format:
// - vehicle formats (WaypointFormatInfo::vehicle): "<stem>-<aircraft>.<ext>" for an aircraft flying
//   one sortie; for one needing several batteries "<stem>-<aircraft>-sortieN.<ext>", one flight per
//   battery from home back home, and no file flying them all (a note names them). A flight with
//   more mission items than its autopilot stores (.plan: the firmware chosen, .waypoints:
//   ArduPilot) is written with a warning naming the aircraft, the sortie, the count and the limit.
// - display formats: "<stem>-<aircraft>.<ext>" per aircraft (perAircraft) and "<stem>.<ext>" with
//   every aircraft (combined: with several aircraft, or when there are no per-aircraft files); the
//   whole path, in KML each sortie in a folder of its own.
// Stops at the first file that cannot be written.
Result<MissionExportReport> exportMission(const mission::Mission& mission,
                                          const std::vector<route::Route>& routes,
                                          const MissionExportRequest& request);

// Route `routeIndex` of ctx written in a vehicle format, after the check of its aircraft against
// the format (checkAircraftFormat, once for all its flights): to `path` when it flies one sortie, else
// one file per sortie, "<path without extension>-sortieN.<ext>" (a note names them); a warning
// names its flights holding more mission items than their autopilot stores.
Result<MissionExportReport> exportVehicleFlights(const ExportContext& ctx, std::size_t routeIndex,
                                                 WaypointFormat format, const std::string& path,
                                                 const ExportOptions& options = {});

// The same for one format of a context already made (request.formats is not read).
Result<MissionExportReport> exportFormat(const ExportContext& ctx, WaypointFormat format,
                                         const MissionExportRequest& request);

// The autopilot a format's missions are written for: .plan by options.firmware, .waypoints
// ArduPilot (Mission Planner); none for the other formats.
std::optional<Autopilot> autopilotFor(WaypointFormat format, const ExportOptions& options);

// The warning for route `routeIndex` of ctx flown as one mission (empty when it fits): its items
// as missionItems() makes them with `options`, against `autopilot` (none: the smallest limit). The
// flight is named `name`, else by its route label.
std::string flightItemWarning(const ExportContext& ctx, std::size_t routeIndex,
                              const ExportOptions& options, std::optional<Autopilot> autopilot,
                              const std::string& name = {});

// Each of the route's sorties as a flight of its own (home to home, the mission's landing point
// unused: every sortie comes back home), labelled "<aircraft>, sortie N"; the route itself when it
// is one sortie.
ExportContext sortieContext(const ExportContext& ctx, std::size_t routeIndex);
// The route's number of sorties (at least 1).
std::size_t sortieCount(const ExportContext& ctx, std::size_t routeIndex);
// One flight to upload: sortie `sortie` (0-based) of the route as route 0 of a context of its own,
// labelled "<aircraft>, sortie 2 of 5" (the aircraft's name when it flies one sortie).
ExportContext sortieFlight(const ExportContext& ctx, std::size_t routeIndex, std::size_t sortie);

} // namespace pf::io
