// QGroundControl .plan files (JSON: fileType "Plan" version 1, mission version 2): write one
// aircraft's route as a MAVLink mission with geofence and rally point, and read .plan files back
// for editing.
#pragma once

#include "core/io/export_context.h"
#include "core/result.h"

#include <cstddef>
#include <string>

namespace pf::io {

// MAVLink commands and frames used in .plan and .waypoints files.
namespace mav {
constexpr int kNavWaypoint = 16;
constexpr int kNavReturnToLaunch = 20;
constexpr int kNavLand = 21;
constexpr int kNavTakeoff = 22;
constexpr int kDoDigicamControl = 203;
constexpr int kImageStartCapture = 2000;
constexpr int kFrameGlobal = 0;            // altitude above mean sea level
constexpr int kFrameMission = 2;           // command without a position
constexpr int kFrameGlobalRelativeAlt = 3; // altitude above home
} // namespace mav

// The .plan document for route `routeIndex`: take-off at the home, one waypoint per route waypoint
// (yaw = heading), an image capture command after every photo waypoint, return-to-launch or land at
// the end; every no-fly zone as an exclusion polygon of the geofence; the home as rally point.
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
