#include "core/io/plan_export.h"

#include "core/mission/plan_messages.h"
#include "core/mission/planner_kinds.h"

#include <cpl_json.h>

namespace pf::io {

using mission::MissionPlan;
using mission::PlanTotals;

namespace {

void addMetrics(CPLJSONObject& o, const plan::PathMetrics& m) {
    o.Add("visitable_cells", m.visitable);
    o.Add("cells", m.cells);
    o.Add("complete", m.complete());
    o.Add("photos", m.photos);
    o.Add("path_length_m", m.pathLengthM);
    o.Add("distance_m", m.distanceM);
    o.Add("turns", m.turns);
    o.Add("turn_angle_deg", m.turnAngleDeg);
    o.Add("jumps", m.jumps);
    o.Add("revisits", m.revisits);
    o.Add("estimated_time_s", m.estimatedTimeS);
    o.Add("planning_ms", m.planningMs);
    o.Add("turn_lower_bound", m.turnLowerBound);
    o.Add("turn_ratio", m.turnRatio);
}

} // namespace


std::string planMetricsJson(const MissionPlan& plan, const std::string& plannerName) {
    CPLJSONDocument doc;
    CPLJSONObject root = doc.GetRoot();
    root.Add("planner", plannerName);
    if (!plan.plannerChoice.empty())
        root.Add("planner_choice", plan.plannerChoice);
    CPLJSONArray list;
    for (std::size_t k = 0; k < plan.aircraft.size(); ++k) {
        const auto& a = plan.aircraft[k];
        CPLJSONObject o;
        o.Add("name", a.aircraft);
        o.Add("planner", mission::plannerKindInfo(a.planner).id);
        if (!a.plannerChoice.empty())
            o.Add("planner_choice", a.plannerChoice);
        o.Add("altitude_m", a.altitudeM);
        o.Add("cell_size_m", a.cellSizeM);
        o.Add("grid_angle_deg", a.gridAngleDeg);
        o.Add("angles_tried", a.anglesTried);
        addMetrics(o, a.metrics);
        o.Add("time_s", a.timeS);
        o.Add("flight_distance_m", a.flightDistanceM);
        o.Add("flight_turns", a.flight.turns);
        o.Add("flight_turn_angle_deg", a.flight.turnAngleDeg);
        o.Add("sorties", static_cast<int>(a.sorties.size()));
        CPLJSONArray sorties;
        for (const auto& s : a.sorties) {
            CPLJSONObject so;
            so.Add("first_waypoint", s.firstWaypoint);
            so.Add("last_waypoint", s.lastWaypoint);
            so.Add("photos", s.photos);
            so.Add("length_m", s.lengthM);
            so.Add("time_s", s.timeS);
            sorties.Add(so);
        }
        o.Add("sortie_list", sorties);
        o.Add("photos_saved", a.photosSaved);
        o.Add("detours", a.detours);
        o.Add("waypoints_moved", a.waypointsMoved);
        o.Add("kept_inside", a.keptInside);
        o.Add("footprint_across_m", a.footprint.real.longSideM);
        o.Add("footprint_along_m", a.footprint.real.shortSideM);
        // Its part of the area as the independent check saw it (plan_messages.h).
        if (const auto cov = mission::aircraftCoverage(plan, k)) {
            o.Add("coverage_ratio", *cov);
            o.Add("uncovered_m2", a.uncoveredAreaM2);
        }
        if (a.terrain.active) { // terrain following (terrain_stage.h)
            CPLJSONObject t;
            t.Add("height_above_ground_m", a.terrain.heightAboveGroundM);
            t.Add("planning_height_m", a.terrain.planningHeightM);
            t.Add("lanes_respaced", a.terrain.lanesRespaced);
            t.Add("photos_saved_per_lane", a.terrain.photosSavedPerLane);
            t.Add("home_ground_m", a.terrain.homeGroundM);
            t.Add("lowest_clearance_m", a.terrain.lowestClearanceM);
            t.Add("waypoints_inserted", a.terrain.waypointsInserted);
            t.Add("gsd_cm", a.terrain.gsdCm);
            t.Add("coarsest_gsd_cm", a.terrain.coarsestGsdCm);
            o.Add("terrain", t);
        }
        list.Add(o);
    }
    root.Add("aircraft", list);
    const PlanTotals& t = plan.totals;
    CPLJSONObject total;
    total.Add("aircraft", t.aircraft);
    total.Add("visitable_cells", t.visitable);
    total.Add("cells", t.cells);
    total.Add("photos", t.photos);
    total.Add("path_length_m", t.pathLengthM);
    total.Add("distance_m", t.distanceM);
    total.Add("turns", t.turns);
    total.Add("flight_turns", t.flightTurns);
    total.Add("turn_angle_deg", t.turnAngleDeg);
    total.Add("jumps", t.jumps);
    total.Add("revisits", t.revisits);
    total.Add("estimated_time_s", t.estimatedTimeS);
    total.Add("planning_ms", t.planningMs);
    total.Add("makespan_s", plan.makespanS);
    total.Add("ideal_s", plan.idealS);
    total.Add("makespan_ratio", plan.idealS > 0 ? plan.makespanS / plan.idealS : 1.0);
    total.Add("coverage_ratio", plan.coverageRatio);
    total.Add("uncovered_m2", plan.uncoveredAreaM2);
    total.Add("nofly_violations", plan.noFlyViolations);
    total.Add("photos_saved", plan.photosSaved);
    total.Add("altitude_conflicts", plan.altitudeConflicts);
    int sortieCount = 0;
    for (const auto& a : plan.aircraft)
        sortieCount += static_cast<int>(a.sorties.size());
    total.Add("sorties", sortieCount);
    root.Add("total", total);
    // Also at the top level, where the plan-wide checks are looked for first.
    root.Add("coverage_ratio", plan.coverageRatio);
    root.Add("nofly_violations", plan.noFlyViolations);
    root.Add("makespan_s", plan.makespanS);
    CPLJSONArray warnings;
    for (const auto& w : plan.warnings)
        warnings.Add(w);
    root.Add("warnings", warnings);
    CPLJSONArray notes;
    for (const auto& n : plan.notes)
        notes.Add(n);
    root.Add("notes", notes);
    return doc.SaveAsString();
}

} // namespace pf::io
