#include "core/mission/planner_kinds.h"

namespace pf::mission {

const std::vector<PlannerKindInfo>& plannerKinds() {
    static const std::vector<PlannerKindInfo> kinds = {
        {PlannerKind::Auto, "auto", "Auto",
         "per aircraft the plan that flies soonest of sweep, stride and raster (the default)"},
        {PlannerKind::Sweep, "sweep", "Sweep",
         "straight lanes over the exact area, cell by cell round the no-fly zones, cells ordered by flight time"},
        {PlannerKind::Stride, "stride", "Stride",
         "long straight strides that follow the area's limits, few turns, no jumps"},
        {PlannerKind::Raster, "raster", "Raster",
         "row or column back-and-forth over the grid (the baseline), jumps where a row is cut"},
        {PlannerKind::Wavefront, "wavefront", "Wavefront",
         "uphill on a distance map from the landing cell, 8-connected, the quickest of 8 candidates"},
        {PlannerKind::Lawnmower, "lawnmower", "Lawnmower (Survey)",
         "what a ground station's Survey flies: one angle, straight over the no-fly zones (a yardstick, "
         "its crossings fail the route check)"},
    };
    return kinds;
}

const PlannerKindInfo& plannerKindInfo(PlannerKind kind) {
    for (const auto& k : plannerKinds())
        if (k.kind == kind)
            return k;
    return plannerKinds().front();
}

std::optional<PlannerKind> plannerKindFromId(const std::string& id) {
    for (const auto& k : plannerKinds())
        if (id == k.id)
            return k.kind;
    return std::nullopt;
}

std::string plannerKindIdList() {
    const auto& kinds = plannerKinds();
    std::string s;
    for (std::size_t i = 0; i < kinds.size(); ++i)
        s += std::string(i == 0 ? "" : i + 1 == kinds.size() ? " or " : ", ") + kinds[i].id;
    return s;
}

} // namespace pf::mission
