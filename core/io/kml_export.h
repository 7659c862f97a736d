// KML export through OGR (LIBKML driver, or the KML driver when GDAL lacks libkml): the mission
// area, no-fly zones and home in one folder, and per aircraft a folder with its path, photo points
// and photo footprints, styled in the aircraft's colour. Export only.
#pragma once

#include "core/io/export_context.h"
#include "core/result.h"
#include "core/sensor/footprint.h"

#include <cstddef>
#include <string>
#include <vector>

namespace pf::io {

// The photos' footprints are drawn as sensor/footprint lays them out.
using sensor::footprintCorners;

// Writes the given routes of ctx (one route: a per-aircraft file; all: the combined file).
Status writeKml(const ExportContext& ctx, const std::vector<std::size_t>& routeIndices,
                const std::string& path);

} // namespace pf::io
