// The lawnmower reference: what a ground station's Survey pattern flies, the yardstick for every plan.
#pragma once

#include "core/geo/types.h"
#include "core/plan/flight_time.h"
#include "core/plan/lanes/lane.h"
#include "core/result.h"

#include <optional>
#include <vector>

namespace pf::plan {

// A multirotor Survey's default turnaround distance: the transect is extended this far beyond the area
// at both ends so that the aircraft is steady on the line before the first photo (the common ground
// station default for multirotors; fixed wings get 30 m).
constexpr double kSurveyTurnaroundM = 10.0;

struct LawnmowerOptions {
    double trackSpacingM = 0.0;  // between transects: across-track footprint x (1 - side overlap), > 0
    double photoSpacingM = 0.0;  // trigger distance: along-track footprint x (1 - front overlap), > 0
    double turnaroundM = kSurveyTurnaroundM; // >= 0
    FlightTimeModel time;        // the one time model: chooses the angle and entry, and is reported
    std::optional<geo::Vec2> home;   // take-off and landing: counted in the time, picks the entry
    std::optional<double> angleDeg;  // transect direction, degrees counter-clockwise from east; unset:
                                     // the fastest angle
    // The real ground footprint of one photo across and along the track. When both are set and the
    // angle is searched, the fastest angle and entry whose photos see at least minCoverage of the area
    // are chosen (a degree off an edge often flies a little shorter and leaves corners unseen: no
    // operator would pick it); the best-covering of the 40 fastest angles when none does.
    double footprintAcrossM = 0.0;
    double footprintAlongM = 0.0;
    double minCoverage = 0.995;
    // The search's coverage raster (pixel side in metres, > 0): 1 m by default; a planner that only
    // wants the Survey's direction as a candidate of its own checks coarser.
    double searchCoverageResolutionM = 1.0;
};

struct LawnmowerPlan {
    double angleDeg = 0.0;           // transect direction, counter-clockwise from east, [0, 180)
    std::vector<Lane> transects;     // in flight order; stripStart/stripEnd are where the flown
                                     // transect enters and leaves the area, photos as the Survey takes them
    std::vector<geo::Vec2> flight;   // every point flown, in order: turnaround, entry, exit, turnaround,
                                     // ... (home excluded)
    std::optional<geo::Vec2> home;   // the options' home (take-off and landing), if any
    int photos = 0;
    int anglesTried = 0;
    double coverage = -1.0;          // share of the area its real footprints see (1 m raster) when the
                                     // search checked it, else -1
    FlightTime time;                 // of home -> flight -> home when home is set, else of the flight;
                                     // totalS includes photos x photoDwellS
};

// The Survey pattern over `area` (local metres), written from the documented behaviour of the common
// ground stations' Survey:
// - parallel transects `trackSpacingM` apart at one angle; a transect runs along its line from the first
//   to the last crossing of the area's boundary (every ring of every polygon): a concave area or a hole
//   is flown straight across, as the Survey does by default (it does not split concave polygons);
// - the lines are centred across the area: ceil(width / spacing) of them, so that their strips cover
//   it edge to edge (the Survey's grid phase is arbitrary; this is its best case);
// - boustrophedon order, each transect extended by `turnaroundM` at both ends, the legs between
//   transects straight;
// - the camera triggers by distance on each transect: the trigger starts with a photo where the flown
//   transect enters the area, takes one every `photoSpacingM`, and stops with a photo where it leaves
//   (floor(length / spacing) + 2 photos, one fewer when the length is a whole number of spacings; none
//   in the turnarounds). The exit photo is what keeps the far end of every transect covered;
// - the entry corner (first transect and its direction, the four choices the Survey offers) and, when
//   `angleDeg` is unset, the angle (every degree and every edge direction of the area) are those with
//   the least flight time by `flightTime` (to the millisecond; ties: fewer photos, then the entry nearest
//   to home, then the smaller angle), among those that cover the area when the footprint is given.
// It ignores no-fly zones, as the Survey does (see countNoFlyCrossings). Errors: spacings not positive,
// turnaround negative, a time model with a speed or turn rate not positive, an area without area.
Result<LawnmowerPlan> planLawnmower(const geo::MultiPolygon& area, const LawnmowerOptions& options);

// What a plan that ignores the zones costs in safety.
struct NoFlyCrossings {
    int photosInZones = 0;      // photo points inside a zone (on its boundary included)
    int legsCrossing = 0;       // straight legs (home legs included) coming closer to a zone than the margin
    int photosOutsideZones = 0; // the others: the honest photo yardstick when zones exist
};
NoFlyCrossings countNoFlyCrossings(const LawnmowerPlan& plan, const std::vector<geo::Polygon>& zones, double marginM);

// The whole flown polyline: home, the flight, home (without home when the plan has none).
std::vector<geo::Vec2> flownPath(const LawnmowerPlan& plan);

} // namespace pf::plan
