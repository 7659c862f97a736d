#include "core/mavlink/vehicle_plan.h"

#include "core/io/mission_items.h"

#include <cmath>

namespace pf::mavlink {

namespace {

MissionItemInt wireItem(const io::MissionItem& it) {
    MissionItemInt m;
    m.command = static_cast<std::uint16_t>(it.command);
    m.frame = static_cast<std::uint8_t>(it.frame);
    for (std::size_t i = 0; i < 4; ++i)
        m.params[i] = static_cast<float>(it.params[i]);
    if (it.hasPosition()) {
        m.x = static_cast<std::int32_t>(std::lround(it.params[4] * 1e7));
        m.y = static_cast<std::int32_t>(std::lround(it.params[5] * 1e7));
    } else {
        // A command without a position carries params 5 and 6 as plain numbers (x, y).
        m.x = static_cast<std::int32_t>(std::lround(it.params[4]));
        m.y = static_cast<std::int32_t>(std::lround(it.params[5]));
    }
    m.z = static_cast<float>(it.params[6]);
    m.autocontinue = 1;
    return m;
}

std::vector<MissionItemInt> wire(const std::vector<io::MissionItem>& items) {
    std::vector<MissionItemInt> out;
    out.reserve(items.size());
    for (const auto& it : items)
        out.push_back(wireItem(it));
    return out;
}

} // namespace

Result<VehiclePlan> vehiclePlanFor(const io::ExportContext& ctx, std::size_t routeIndex,
                                   const io::ExportOptions& options) {
    auto items = io::missionItems(ctx, routeIndex, options);
    if (!items)
        return items.error();
    VehiclePlan plan;
    plan.home = wireItem(io::homeItem(ctx, routeIndex, options));
    for (const auto& it : wire(*items))
        plan.mission.push_back(it);
    plan.fence = wire(io::fenceItems(ctx));
    plan.rally = wire(io::rallyItems(ctx, routeIndex));
    return plan;
}

} // namespace pf::mavlink
