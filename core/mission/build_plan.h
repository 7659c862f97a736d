// Planning a mission for given regions, one per aircraft (the split made, or the whole area for one):
// each aircraft over its region, the photos another already takes dropped, the flights finished
// (keep-inside, no-fly detours, transit from and back home, sorties, altitude separation), checked
// (coverage, margin breaches) and totalled; with the small helpers planMission shares with it.
// Internal to mission/plan_mission.
#pragma once

#include "core/mission/aircraft_naming.h"
#include "core/mission/mission.h"
#include "core/mission/mission_plan.h"
#include "core/mission/validation.h"
#include "core/result.h"

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pf::mission::detail {

// The covered fraction of the admissible area below which a plan gets a warning.
constexpr double kCoverageTarget = 0.995;
// The makespan / ideal (total time / aircraft) a shared plan aims to stay within.
constexpr double kBalanceTarget = 1.10;

inline Error cancelledError() { return makeError(ErrorCode::Cancelled, "planning cancelled"); }

inline std::string aircraftLabel(const AircraftConfig& a) {
    return mission::aircraftLabel(a.name);
}

inline double polylineLength(const std::vector<geo::Vec2>& p) {
    double s = 0.0;
    for (std::size_t i = 1; i < p.size(); ++i)
        s += (p[i] - p[i - 1]).norm();
    return s;
}

inline std::string metres(double v, int decimals = 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// Plans aircraft k over its region (step 2) in place of planRegion: a corridor's lanes.
using RegionPlanner =
    std::function<Result<AircraftPlan>(std::size_t k, const geo::MultiPolygon& region)>;

// Steps 2 to 6 of planMission for given regions (one per aircraft), planned with `opt` (by
// planRegion, or by `planner` when given). Without `check`, step 6 (the coverage raster and the
// margin breaches) is left out: the candidates of the split are compared on their times alone, and
// only the plan returned is checked.
Result<MissionPlan> buildPlan(const Mission& m, const PlannerOptions& opt,
                              const LocalGeometry& geom,
                              const std::vector<geo::MultiPolygon>& regions,
                              const std::vector<std::optional<geo::Vec2>>& homes,
                              const std::optional<geo::Vec2>& landing, bool check,
                              std::vector<double>* aloneTimes = nullptr,
                              const RegionPlanner& planner = {});

} // namespace pf::mission::detail
