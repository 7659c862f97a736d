// QGroundControl .plan files (JSON: fileType "Plan" version 1, mission version 2): write one
// aircraft's route as a MAVLink mission with geofence and rally point, and read .plan files back
// for editing.
#pragma once

#include "core/io/export_context.h"
#include "core/io/mission_items.h"
#include "core/result.h"

#include <cstddef>
#include <string>

namespace pf::io {


// The .plan document for route `routeIndex`: the items of missionItems() (take-off, speed, gimbal,
// waypoints with capture commands or distance triggering, return or land), every no-fly zone as an
// exclusion polygon of the geofence, the home as rally point at the route's highest altitude, and
// the planned home at ExportOptions::homeElevationM (AMSL, 0 when unknown).
Result<std::string> qgcPlanJson(const ExportContext& ctx, std::size_t routeIndex,
                                const ExportOptions& options = {});
Status writeQgcPlan(const ExportContext& ctx, std::size_t routeIndex, const std::string& path,
                    const ExportOptions& options = {});

// Reads the SimpleItem waypoints of a .plan back into one route (a waypoint followed by an image
// capture command is a photo waypoint), the geofence's exclusion polygons as no-fly zones and the
// planned home position. Errors name the file and the JSON key (or the line of a JSON syntax
// error).
Result<ImportedWaypoints> parseQgcPlan(const std::string& text, const std::string& source);
Result<ImportedWaypoints> readQgcPlan(const std::string& path);

} // namespace pf::io
