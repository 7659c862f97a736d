// GPX 1.1 through OGR's GPX driver: every waypoint as <wpt> (with <ele>, <name>, <type>, heading in
// <extensions>) and one <rte> per route; read back for editing.
#pragma once

#include "core/io/export_context.h"
#include "core/result.h"

#include <cstddef>
#include <string>
#include <vector>

namespace pf::io {

// The altitude reference written into every GPX file's <metadata><desc>.
constexpr const char* kGpxElevationNote =
    "Altitude reference: every ele is the flight height in metres above the take-off (home) point, "
    "not above mean sea level.";
// The note of a file planned over a terrain model, followed by kGpxTakeOffMarker and the take-off
// point's elevation when every route shares it (the reader subtracts it again).
constexpr const char* kGpxAmslNote =
    "Altitude reference: every ele is metres above mean sea level (the flight follows the terrain).";
constexpr const char* kGpxTakeOffMarker = "Take-off point elevation above mean sea level: ";

// Writes the given routes of ctx (one route: a per-aircraft file; all: the combined file).
Status writeGpx(const ExportContext& ctx, const std::vector<std::size_t>& routeIndices,
                const std::string& path);

// One route per <rte> (its <name> becomes the aircraft name); a file without routes gives one route
// made of its <wpt> in file order. <ele> is required (the altitude above take-off); a point without
// a heading extension heads for the next point; <type> photo/turn/transit gives the kind (photo
// when absent). Errors name the file and the point.
Result<ImportedWaypoints> readGpx(const std::string& path);

} // namespace pf::io
