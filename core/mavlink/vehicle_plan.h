// What is uploaded to a vehicle for one route: the same mission items as the .plan and .waypoints
// exports (core/io/mission_items), the no-fly zones as an exclusion geofence and the rally point,
// as MAVLink MISSION_ITEM_INT items.
#pragma once

#include "core/io/export_context.h"
#include "core/mavlink/mission_transfer.h"
#include "core/result.h"

#include <cstddef>

namespace pf::mavlink {

// The home item is kept apart: an ArduPilot vehicle (told by its heartbeat) gets it as mission
// item 0, as the .waypoints file holds it; PX4 gets the items without it. options.firmware does
// not matter here.
Result<VehiclePlan> vehiclePlanFor(const io::ExportContext& ctx, std::size_t routeIndex,
                                   const io::ExportOptions& options = {});

} // namespace pf::mavlink
