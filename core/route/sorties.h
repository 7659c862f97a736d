// Endurance: splitting a survey that is too long for one battery into sorties that each return home.
#pragma once

#include "core/geo/types.h"
#include "core/plan/flight_time.h"
#include "core/result.h"
#include "core/route/safety.h"
#include "core/route/waypoint.h"

#include <string>
#include <vector>

namespace pf::route {

// Flight times come from the one model, plan::FlightTimeModel (straight legs, turns, stops).
using FlightModel = plan::FlightTimeModel;

// Time to fly the polyline from rest to rest (plan::flightTime(...).totalS).
double flightTimeS(const std::vector<geo::Vec2>& polyline, const FlightModel& model);

struct SortieOptions {
    double enduranceMin = 20.0;
    double reserveFraction = 0.2; // of the endurance, kept for the unexpected: in [0, 1)
};

struct Sortie {
    std::vector<LocalWaypoint> waypoints; // Transit out, survey waypoints, Transit back
    int firstSurvey = 0;                  // indices into the survey waypoints, inclusive
    int lastSurvey = 0;
    double lengthM = 0.0; // home to home
    double timeS = 0.0;   // home to home
};

struct SortiePlan {
    std::vector<Sortie> sorties;
    double budgetS = 0.0;   // endurance less the reserve
    double totalTimeS = 0.0;
    int batteries() const { return static_cast<int>(sorties.size()); }
};

// Cuts the survey at waypoints into sorties, each flying out from `home` by the safe transit,
// covering a run of consecutive survey waypoints and returning home, every one within the budget
// (endurance less the reserve). Each sortie takes as many waypoints as fit. A survey that fits is
// one sortie. Errors (naming `aircraft`): bad endurance or reserve, a waypoint too far to reach and
// come back within the budget, no safe way out or back.
Result<SortiePlan> splitIntoSorties(const std::vector<LocalWaypoint>& survey, const geo::Vec2& home,
                                    const SafePathFinder& finder, const FlightModel& model,
                                    const SortieOptions& opt, const std::string& aircraft);

} // namespace pf::route
