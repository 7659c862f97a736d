// QGC WPL 110 ".waypoints" text files (Mission Planner, QGroundControl): write one aircraft's route
// as a MAVLink mission and read such files back for editing, including the form Mission Planner
// writes.
#pragma once

#include "core/io/export_context.h"
#include "core/result.h"

#include <cstddef>
#include <string>

namespace pf::io {

// "QGC WPL 110", then one line per item: index, current, frame, command, param1..4, latitude,
// longitude, altitude, autocontinue (tab-separated). Line 0 after the header is the home (frame 0).
// The items are those of the .plan export (take-off, waypoints with capture commands, return or
// land).
Result<std::string> qgcWplText(const ExportContext& ctx, std::size_t routeIndex,
                               const ExportOptions& options = {});
Status writeQgcWpl(const ExportContext& ctx, std::size_t routeIndex, const std::string& path,
                   const ExportOptions& options = {});

// Reads CRLF or LF files, with or without a final newline; fields may be separated by tabs or
// spaces. Errors name the file and the line.
Result<ImportedWaypoints> parseQgcWpl(const std::string& text, const std::string& source);
Result<ImportedWaypoints> readQgcWpl(const std::string& path);

} // namespace pf::io
