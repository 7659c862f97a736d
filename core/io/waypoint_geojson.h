// Routes as GeoJSON through OGR's GeoJSON driver: the area, no-fly zones, home, each route's path
// and its waypoints as features with properties; read back for editing.
#pragma once

#include "core/io/export_context.h"
#include "core/result.h"

#include <cstddef>
#include <string>
#include <vector>

namespace pf::io {

// Features and their "kind" property: "area" and "no-fly zone" polygons, a "home" point, one "path"
// line per route, and one point per waypoint with kind "photo", "turn" or "transit" and the
// properties aircraft, index (1-based order in the route), altitude_m (above take-off),
// heading_deg.
Status writeWaypointGeoJson(const ExportContext& ctx, const std::vector<std::size_t>& routeIndices,
                            const std::string& path);

// Point features with a waypoint kind (or no kind) become waypoints, grouped by "aircraft" in order
// of first appearance and ordered by "index" when every point has one (file order otherwise).
// "altitude_m" is required (or a third coordinate); a missing "heading_deg" heads for the next
// point. "no-fly zone" polygons and the "home" point are read too. Errors name the file and the
// feature, or the line of a JSON syntax error.
Result<ImportedWaypoints> readWaypointGeoJson(const std::string& path);

} // namespace pf::io
