// What is uploaded to a vehicle for one route: the same mission items as the .plan and .waypoints
// exports (core/io/mission_items), the no-fly zones as an exclusion geofence and the rally point,
// as MAVLink MISSION_ITEM_INT items.
#pragma once

#include "core/io/export_context.h"
#include "core/mavlink/mission_transfer.h"
#include "core/result.h"

#include <cstddef>

namespace pf::mavlink {

// ArduPilot keeps the home as mission item 0 (as the .waypoints file does): it is sent first and
// its position is not compared on read-back; PX4 gets the items without it.
Result<VehiclePlan> vehiclePlanFor(const io::ExportContext& ctx, std::size_t routeIndex,
                                   const io::ExportOptions& options = {});

// Transfer options that match the firmware (home as item 0 for ArduPilot).
TransferOptions transferOptionsFor(io::QgcFirmware firmware);

} // namespace pf::mavlink
