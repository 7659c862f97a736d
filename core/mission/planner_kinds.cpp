#include "core/mission/planner_kinds.h"

namespace pf::mission {

namespace {

constexpr const char* kGridNotForPlanes =
    "a grid planner's path steps from cell to cell and turns on the spot, which a plane cannot fly";

} // namespace

const std::vector<PlannerKindInfo>& plannerKinds() {
    static const std::vector<PlannerKindInfo> kinds = {
        {PlannerKind::Auto, "auto", "Auto",
         "per aircraft the plan that flies soonest of sweep, stride and raster (for a plane: of "
         "those that "
         "plan for planes) (the default)",
         std::nullopt},
        {PlannerKind::Sweep, "sweep", "Sweep",
         "straight lanes over the exact area, cell by cell round the no-fly zones, cells ordered "
         "by flight time "
         "(for a plane: lanes joined by turns of its radius, every k-th lane where they lie closer "
         "than two radii)",
         std::nullopt},
        {PlannerKind::Stride, "stride", "Stride",
         "long straight strides that follow the area's limits, few turns, no jumps",
         plan::PlannerKind::Stride, true, kGridNotForPlanes},
        {PlannerKind::Raster, "raster", "Raster",
         "row or column back-and-forth over the grid (the baseline), jumps where a row is cut",
         plan::PlannerKind::Raster, true, kGridNotForPlanes},
        {PlannerKind::Wavefront, "wavefront", "Wavefront",
         "uphill on a distance map from the landing cell, 8-connected, the quickest of 8 "
         "candidates",
         plan::PlannerKind::Wavefront, true, kGridNotForPlanes},
        {PlannerKind::Lawnmower, "lawnmower", "Lawnmower (Survey)",
         "what a ground station's Survey flies: one angle, straight over the no-fly zones (a "
         "yardstick, "
         "its crossings fail the route check)",
         std::nullopt, false,
         "the yardstick flies a ground station's Survey, whose lines cross the no-fly zones and "
         "end "
         "where a plane cannot turn"},
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

namespace {

// "a, b or c".
std::string idList(const std::vector<const char*>& ids) {
    std::string s;
    for (std::size_t i = 0; i < ids.size(); ++i)
        s += std::string(i == 0 ? "" : i + 1 == ids.size() ? " or " : ", ") + ids[i];
    return s;
}

} // namespace

std::string plannerKindIdList() {
    std::vector<const char*> ids;
    for (const auto& k : plannerKinds())
        ids.push_back(k.id);
    return idList(ids);
}

std::string planePlannerIdList() {
    std::vector<const char*> ids;
    for (const auto& k : plannerKinds())
        if (servesPlanes(k))
            ids.push_back(k.id);
    return idList(ids);
}

const PlannerKindInfo& plannerKindInfo(plan::PlannerKind kind) {
    for (const auto& k : plannerKinds())
        if (k.gridPlanner == kind)
            return k;
    return plannerKindInfo(PlannerKind::Stride);
}

std::optional<plan::PlannerKind> gridPlannerFromId(const std::string& id) {
    for (const auto& k : plannerKinds())
        if (k.gridPlanner && id == k.id)
            return k.gridPlanner;
    return std::nullopt;
}

std::string gridPlannerIdList() {
    std::vector<const char*> ids;
    for (const auto& k : plannerKinds())
        if (k.gridPlanner)
            ids.push_back(k.id);
    return idList(ids);
}

} // namespace pf::mission
