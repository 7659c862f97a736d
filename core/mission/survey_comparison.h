// Every mission planner beside the lawnmower reference on a set of areas: measures, ratios and medians.
#pragma once

#include "core/geo/types.h"
#include "core/mission/mission.h"
#include "core/plan/evaluation.h"
#include "core/plan/lawnmower_planner.h"
#include "core/result.h"

#include <string>
#include <vector>

namespace pf::mission {

// The comparison's aircraft when none is given (the operators' test of the lanes issue): a camera of
// 60 x 45 degrees (4000 x 3000 px) at 30 m, 20 % front and side overlap, 10 m/s, 60 deg/s, the default
// acceleration.
AircraftConfig surveyAircraft();

// The take-off and landing point of every plan of an area, the lawnmower's included: the vertex of the
// area's outer ring nearest to the south-west corner of its bounding box (in the area's local frame)
// among those farther than the margin + 1 m from every zone; the nearest vertex when none is.
Result<geo::LonLat> surveyHome(const plan::EvalArea& area, double marginM);

// The mission for one area: its polygon and zones, `aircraft`, `options`, home from surveyHome.
Result<Mission> surveyMission(const plan::EvalArea& area, const AircraftConfig& aircraft, const PlannerOptions& options);

// What one plan costs, home to home, by the one flight-time model and by the two simpler measures of
// the lanes issue's table.
struct SurveyMeasures {
    bool ok = false;
    std::string error;           // why the planner gave no plan (ok false)
    double timeS = 0.0;          // plan::flightTime: legs, turns, a stop at each turn
    double simpleTimeS = 0.0;    // path / V + turn angle / omega (paper 004)
    double simpleStopsTimeS = 0.0; // the same + 3 s per turn
    int photos = 0;
    double pathM = 0.0;
    int turns = 0;
    double turnAngleDeg = 0.0;
    double coverage = 0.0;       // admissible area seen by the real footprints
    int violations = 0;          // planners: waypoints and legs closer to a zone than the margin;
                                 // lawnmower: photos in zones + legs crossing a zone or its margin
    double angleDeg = 0.0;       // grid angle (planners) or transect angle (lawnmower), CCW from east
    double planningMs = 0.0;
    std::vector<geo::Vec2> path;   // home, every waypoint, home (local metres)
    std::vector<geo::Vec2> photoPoints;
};

struct PlannerRun {
    PlannerKind kind = PlannerKind::Stride;
    SurveyMeasures m;
};

// One area: every planner and the lawnmower, in the area's local frame.
struct SurveyComparison {
    std::string area;
    int zones = 0;
    double areaM2 = 0.0;
    double admissibleM2 = 0.0;   // area minus the zones
    geo::MultiPolygon localArea;
    std::vector<geo::Polygon> localZones;
    geo::MultiPolygon margins;   // the zones grown by the safety margin
    double marginM = 0.0;
    geo::Vec2 home{0, 0};
    double trackSpacingM = 0.0;
    double photoSpacingM = 0.0;
    SurveyMeasures lawnmower;
    plan::NoFlyCrossings crossings;
    std::vector<PlannerRun> planners;
};

// Plans `m` (one aircraft, a home) with each planner kind through planMission and with
// plan::planLawnmower (the aircraft's effective footprint, the default turnaround, the same home and
// time model), and measures every plan the same way: the flown polyline home -> waypoints -> home by
// plan::flightTime. The aircraft's endurance is lifted so that no plan is cut into sorties (the
// lawnmower is one flight). A planner that fails is recorded with its error; errors: a mission without
// exactly one aircraft or without a home, geometry or camera the lawnmower cannot use.
Result<SurveyComparison> compareOnMission(const Mission& m, const std::string& areaName,
                                          const std::vector<PlannerKind>& kinds);

// A planner's figures over the lawnmower's (NaN where the lawnmower's figure is 0 or the plan failed).
struct SurveyRatios {
    double time = 0, simpleTime = 0, simpleStopsTime = 0, photos = 0, path = 0, turns = 0;
    double photosOutside = 0; // photos over the lawnmower's photos outside the zones
};
SurveyRatios ratiosTo(const SurveyMeasures& planner, const SurveyComparison& c);

// The median (the mean of the middle two for an even count) of the finite values; NaN when none.
double median(std::vector<double> values);

enum class AreaSet { All, WithoutZones, WithZones };

// Medians over the areas of `set` of each planner's ratios; the lawnmower's own medians (its crossings).
struct SurveySummary {
    PlannerKind kind = PlannerKind::Stride;
    int areas = 0;   // areas of the set where the planner gave a plan
    int failed = 0;  // areas of the set where it did not
    SurveyRatios medians;
    double minCoverage = 0.0;
    int violations = 0; // summed over the areas
};
struct LawnmowerSummary {
    int areas = 0;
    double minCoverage = 0.0;
    double medianPhotosInZones = 0.0, medianLegsCrossing = 0.0;
    int photosInZones = 0, legsCrossing = 0; // summed
};
std::vector<SurveySummary> summariseSurvey(const std::vector<SurveyComparison>& areas, AreaSet set);
LawnmowerSummary summariseLawnmower(const std::vector<SurveyComparison>& areas, AreaSet set);

// Per area one line per planner and the lawnmower, then the medians over all areas, the areas without
// zones and those with zones (each set when it has areas), as the lanes issue's table.
std::string surveyTable(const std::vector<SurveyComparison>& areas);

// One line per area and plan (the lawnmower included):
// area,zones,area_m2,planner,ok,time_s,simple_time_s,simple_stops_time_s,photos,path_m,turns,
// turn_angle_deg,coverage,violations,angle_deg,planning_ms,time_ratio,simple_time_ratio,
// simple_stops_time_ratio,photos_ratio,photos_outside_ratio,path_ratio,turns_ratio,
// lawnmower_photos_in_zones,lawnmower_legs_crossing,error
std::string surveyCsv(const std::vector<SurveyComparison>& areas);

} // namespace pf::mission
