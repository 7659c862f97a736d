// Litchi mission hub CSV: one waypoint per row with the columns the hub imports, so DJI operators
// can load a route; read back for editing.
#pragma once

#include "core/io/export_context.h"
#include "core/result.h"

#include <cstddef>
#include <string>

namespace pf::io {

// The header row: latitude,longitude,altitude(m),heading(deg),curvesize(m),rotationdir,gimbalmode,
// gimbalpitchangle,actiontype1,actionparam1,...,actiontype15,actionparam15,altitudemode,speed(m/s),
// poi_latitude,poi_longitude,poi_altitude(m),poi_altitudemode,photo_timeinterval,photo_distinterval
std::string litchiCsvHeader();

// Photo waypoints carry action 1 ("take photo"); the gimbal points straight down (-90,
// interpolated); altitudes are relative to take-off (altitudemode 0); curve size 0 (the aircraft
// stops at each waypoint).
Result<std::string> litchiCsvText(const ExportContext& ctx, std::size_t routeIndex);
Status writeLitchiCsv(const ExportContext& ctx, std::size_t routeIndex, const std::string& path);

// Needs the latitude, longitude, altitude(m) and heading(deg) columns; a row with an action of type
// 1 is a photo waypoint. A file saved by a spreadsheet with ';' between the fields and decimal
// commas is read too. Errors name the file, the line and the column.
Result<ImportedWaypoints> parseLitchiCsv(const std::string& text, const std::string& source);
Result<ImportedWaypoints> readLitchiCsv(const std::string& path);

} // namespace pf::io
