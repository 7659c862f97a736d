// Builds a Mission from the command line: a mission or area file, then flags that override it.
//
//   [MISSION.json | AREA]           a mission file (photoflight-mission JSON), or an area file in
//   any
//                                   format OGR reads (GeoJSON, KML, Shapefile, GeoPackage, GML)
//                                   holding exactly one polygon (the area)
//   --area FILE                     the area from FILE (replaces the mission's area)
//   --nofly FILE                    every polygon of FILE becomes a no-fly zone, named after its
//                                   feature (repeatable; added to the mission's zones)
//   --corridor FILE --width M       a corridor survey instead of an area: the one line of FILE
//                                   (GeoJSON, KML, GPX, Shapefile, GeoPackage, GML) as its centre
//                                   line, M metres wide (--width alone changes a mission file's
//                                   corridor)
//   --camera NAME                   a catalog camera, for every aircraft
//   --hfov DEG --vfov DEG           a camera given by its fields of view (long / short side), for
//   every
//                                   aircraft; the image size of the aircraft's camera is kept
//                                   (4000 x 3000 px if it has none)
//   --altitude M | --gsd CM         flight altitude in metres, or the wanted ground sample distance
//   in
//                                   cm/px, for every aircraft (not both)
//   --overlap F | --front F --side F  overlaps in [0, 1) (0.7 = 70 %): both, or front and side
//   apart
//   --planner stride|raster|wavefront
//   --grid-angle DEG|auto           grid rotation counter-clockwise from east, or the planner's
//   search
//   --home LON,LAT                  take-off and landing point
//   --aircraft NAME[:ALT_M]         a catalog aircraft with its default camera, optionally its own
//                                   altitude (repeatable; replaces the mission's aircraft)
//   --safety-margin M               keep-out distance around every no-fly zone
//   --max-cells N                   grid cell budget
//   --dem FILE                      terrain model; turns terrain following on unless --terrain off
//   --terrain follow|off            terrain following
//   --min-clearance M               minimum clearance of every leg above the ground
//
// Without a mission file and without --aircraft, the first aircraft of the catalog is used, and
// without --altitude or --gsd an altitude of 100 m (or the aircraft's maximum if lower); the
// defaults applied are listed in MissionInput::notes. Every error names the flag or the file at
// fault.
#pragma once

#include "app/cli/args.h"
#include "core/mission/mission.h"
#include "core/mission/validation.h"
#include "core/result.h"

#include <string>
#include <vector>

// The option lines of kMissionOptionsHelp as a string literal, so that usage texts can embed them.
#define PF_CLI_MISSION_OPTIONS_HELP \
    "  --area FILE                  the area (one polygon) from FILE: GeoJSON, KML, Shapefile, GeoPackage, GML\n" \
    "  --nofly FILE                 add every polygon of FILE as a no-fly zone (repeatable)\n" \
    "  --corridor FILE              survey a corridor along the one line of FILE (GeoJSON, KML, GPX,\n" \
    "                               Shapefile, GeoPackage, GML) instead of an area; needs --width\n" \
    "  --width M                    the corridor's full width in metres (lanes along its line)\n" \
    "  --double-grid                a second pass with lanes at 90° to the first (two views of every\n" \
    "                               point, for 3D models; ignored for a corridor)\n" \
    "  --camera-tilt DEG            oblique photos: every camera tilted DEG (0-45) forward from straight\n" \
    "                               down along the lanes (with --double-grid: four views, for 3D models)\n" \
    "  --camera NAME                a camera of the catalog, for every aircraft (see: photoflight-cli catalog)\n" \
    "  --hfov DEG --vfov DEG        a camera given by its fields of view across the long and the short side\n" \
    "  --altitude M                 flight altitude in metres, for every aircraft\n" \
    "  --gsd CM                     wanted ground sample distance in cm/px (sets the altitude instead)\n" \
    "  --overlap F                  front and side overlap, in [0, 1): 0.7 means 70 %\n" \
    "  --front F, --side F          front (along the track) and side (between tracks) overlap apart\n" \
    "  --planner NAME               auto (default: per aircraft the planner that flies soonest), sweep,\n" \
    "                               stride, raster, wavefront or lawnmower (the Survey reference)\n" \
    "  --grid-angle DEG|auto        grid rotation in degrees counter-clockwise from east, or auto\n" \
    "  --home LON,LAT               take-off and landing point (WGS84 degrees)\n" \
    "  --aircraft NAME[:ALT_M]      a catalog aircraft (multirotor, fixed-wing or VTOL, with its speed,\n" \
    "                               turns and endurance) with its default camera and optionally its own\n" \
    "                               altitude (repeatable; replaces the mission's aircraft)\n" \
    "  --safety-margin M            keep-out distance around every no-fly zone in metres (default 5)\n" \
    "  --max-cells N                grid cell budget (default 4000000)\n" \
    "  --dem FILE                   terrain model (GeoTIFF, SRTM .hgt, VRT, any CRS): follow the terrain\n" \
    "  --terrain follow|off         fly every photo at its altitude above the ground under it (follow,\n" \
    "                               the default with --dem) or above the take-off point (off)\n" \
    "  --min-clearance M            no leg closer to the ground than M metres (default 10)\n"

namespace pf::cli {

// The options missionFromArgs() understands, to append to a command's own option specs.
std::vector<OptionSpec> missionOptionSpecs();

// The help text for those options (each line indented by two spaces, ending in a newline).
extern const char* const kMissionOptionsHelp;

struct MissionInput {
    mission::Mission mission;
    std::string source;            // the mission or area file named on the command line
    bool fromMissionFile = false;  // true if `source` is a mission file
    std::vector<std::string> notes; // defaults that were applied, for the user to see
};

// Builds the mission from the positional argument at `positional` (if any) and the flags.
Result<MissionInput> missionFromArgs(const Args& args, std::size_t positional = 0);

// Applies every flag but the file, --area and --nofly to `in.mission`: aircraft, camera, altitude or
// GSD, overlaps, planner, grid angle, home, safety margin and cell budget (a default aircraft or
// altitude when the mission has none, listed in in.notes). missionFromArgs() ends with it; commands that
// build their missions themselves (eval --survey) call it on each of them.
Status applyMissionFlags(const Args& args, MissionInput& in);

// True if the file looks like a mission file rather than an area file: a JSON object that names the
// "photoflight-mission" format, or any JSON object that is not GeoJSON (the mission reader then says
// what is wrong with it).
bool isMissionFile(const std::string& path);

// Prints the report's warnings and errors on stderr ("photoflight-cli: warning: ..."). Returns
// false when the report has errors (the command then exits with kExitBadInput). Every message
// printed is added to `printed`, so a later stage repeating one of them can skip it.
bool printValidationProblems(const mission::ValidationReport& report, std::vector<std::string>* printed = nullptr);

} // namespace pf::cli
