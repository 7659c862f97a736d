// Mission-level checks: every problem with its severity, plus the figures a user checks before flying.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/validation.h"
#include "core/grid/grid.h"
#include "core/mission/mission.h"
#include "core/mission/route_check.h"
#include "core/result.h"
#include "core/sensor/camera.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::mission {

// What one aircraft would fly: its settings resolved and the grid it would get over the whole area.
struct AircraftFigures {
    std::string name;
    double altitudeM = 0.0;       // given, or derived from the wanted GSD
    double gsdCm = 0.0;           // 0 when the camera's optics are unknown (field of view only)
    sensor::Footprint footprint;  // real ground footprint of one photo
    sensor::EffectiveFootprint effective;
    double cellSizeM = 0.0;       // longest side of the effective footprint (paper 001)
    double gridAngleDeg = 0.0;    // the mission's grid angle; 0 when the angle is chosen automatically
    long long cols = 0, rows = 0; // grid extent over the admissible area
    int cellsToVisit = 0;         // Free + Shifted cells (0 when the grid could not be built)
    int shiftedCells = 0;
    int unflyableCells = 0;
    bool gridBuilt = false;
};

struct ValidationReport {
    std::vector<geo::Problem> problems; // in the order found: area, no-fly zones, options, aircraft
    double areaM2 = 0.0;
    double admissibleAreaM2 = 0.0;      // area minus the (un-buffered) no-fly zones
    std::vector<AircraftFigures> aircraft;
    bool hasErrors() const { return geo::hasError(problems); }
    // All error messages joined by "; " (for a one-line Error).
    std::string errorSummary() const;
};

// The smallest photo footprint a mission may fly (m, the real footprint's short side on the ground):
// smaller photos need so many cells that planning takes minutes and the flight hours, and no survey
// needs them (a 60 x 45 degree camera at 5 m covers 5.8 x 4.1 m; it may fly down to 3.7 m).
constexpr double kMinFootprintM = 3.0;

// The errors of flying aircraft `a` of mission `m` at `altitudeM` (the value typed, or derived from
// the wanted GSD): not a number or below the minimum safe altitude (kMinSafeAltitudeM; 0 and below
// say that the aircraft would fly on the ground), above the aircraft's maximum, a photo footprint
// below kMinFootprintM, or a grid over the admissible area beyond the cell budget. Each message
// names the aircraft, the value and the limit. Empty when the altitude can be flown. The aircraft
// panel checks the value typed with it; validateMission reports the same errors.
std::vector<std::string> altitudeErrors(const Mission& m, const AircraftConfig& a, double altitudeM);

// Checks the whole mission: the area and every no-fly zone as polygons, zones outside the area
// (warning: ignored) or covering all of it (error), the home point, the planner options, and per
// aircraft its kind (planeErrors, planeRoutingError; a warning when a plane's turn radius asks for
// a bank steeper than 60 degrees), the camera, altitude (altitudeErrors: minimum safe altitude,
// maximum, footprint) or GSD
// (> 0), overlaps in [0, 1) and the cell budget (an error that says how many cells and which
// altitude and cell size would fit). Never fails: every finding is in the report.
ValidationReport validateMission(const Mission& m);

// The mission's geometry in its local planning frame (centred on the area), as the grid needs it.
// No-fly zones that do not touch the area are left out. Errors name the first invalid polygon.
struct LocalGeometry {
    geo::LocalFrame frame;
    geo::Polygon area;
    std::vector<geo::Polygon> noFly;
    std::vector<std::string> noFlyNames; // parallel to noFly
};
Result<LocalGeometry> localGeometry(const Mission& m);

// The warning for ground enclosed by merged no-fly margins (grid::Grid::pockets): how many, their area,
// and that they are photographed from outside, never entered.
std::string pocketWarning(const geo::MultiPolygon& pockets);

// The errors of a plane's figures (its kind flies as a plane): a minimum turn radius of 0 m or
// less, a bank limit outside 0-90 degrees, climb or sink rates of 0 or less, a negative run-in, a
// stall speed of 0 or less, or a cruise speed below fleet::kStallMargin x the stall speed. Each
// names `who`, the value and the limit. Empty for a multirotor.
std::vector<std::string> planeErrors(const AircraftConfig& a, const std::string& who);

// The grid planners' routes (and the lawnmower yardstick's) turn on the spot at every cell or lane
// end: only a multirotor can fly them. The error for an aircraft that flies its survey as a plane
// (fixed-wing or VTOL) given such a planner, naming it and the planners that do plan for planes;
// empty for a multirotor or a planner that serves planes (sweep, auto). validateMission reports it
// and planning refuses with it, so that a plane never gets a multirotor's route.
std::string planeRoutingError(const AircraftConfig& a, PlannerKind planner, const std::string& who);

// Lanes along a corridor (plansCorridorLanes) turn on the spot at each lane end as well: the error
// for an aircraft that flies as a plane in such a mission, naming it and the way that does plan it
// (the sweep over the corridor's ground); empty otherwise. validateMission reports it and the
// corridor planning refuses with it.
std::string corridorPlaneError(const Mission& m, const AircraftConfig& a, const std::string& who);

// The flight altitude of an aircraft: its altitude, or the one giving its GSD. Errors name the aircraft.
Result<double> resolvedAltitude(const AircraftConfig& a);

// Grid options for one aircraft of the mission (cell size from its effective footprint, the mission's
// grid angle or `autoAngleDeg` when it is automatic, safety margin, cell budget).
Result<grid::GridOptions> gridOptionsFor(const Mission& m, std::size_t aircraftIndex, double autoAngleDeg = 0.0);

} // namespace pf::mission
