// Corridor missions: the corridor's checks, its ground as the mission's area, and its line in the
// planning frame.
#pragma once

#include "core/geo/local_frame.h"
#include "core/geo/validation.h"
#include "core/mission/mission.h"
#include "core/result.h"

#include <optional>
#include <vector>

namespace pf::mission {

// The widest corridor: wider than this, an area survey is the better plan (and the lanes would be
// many kilometres apart from the line they follow).
constexpr double kMaxCorridorWidthM = 5000.0;
// The longest corridor line: the planning frame keeps its scale error within a few centimetres over
// 50 km on either side of the middle.
constexpr double kMaxCorridorLengthM = 100000.0;

// The corridor's errors in words: fewer than two distinct points, a coordinate not finite or out of
// range (naming the point, counted from 1), a width not positive or above kMaxCorridorWidthM, a
// line longer than kMaxCorridorLengthM. Empty when it can be planned.
std::vector<geo::Problem> validateCorridor(const Corridor& c);

// The corridor's ground in WGS84 (plan::corridorGround in a frame centred on the line). Errors: the
// corridor's first problem (validateCorridor).
Result<geo::GeoPolygon> corridorArea(const Corridor& c);

// Sets the mission's corridor and its area to the corridor's ground (empty while the corridor is
// not valid); nullopt removes the corridor and leaves no area. Everything that sets a corridor goes
// through here, so that area and corridor never disagree.
void applyCorridor(Mission& m, std::optional<Corridor> c);

// Whether the mission is planned with lanes along its corridor (a corridor and the automatic
// planner choice; another planner kind plans the corridor's ground as an area, for comparison).
// Such a plan builds no grid: the grid's cell budget does not apply.
inline bool plansCorridorLanes(const Mission& m) {
    return m.corridor.has_value() && m.options.planner == PlannerKind::Auto;
}

// The corridor's centre line in `frame`, its repeated points and straight-through vertices removed.
std::vector<geo::Vec2> corridorLine(const Corridor& c, const geo::LocalFrame& frame);

// The line's length in metres, measured in a frame centred on it (0 for an invalid line).
double corridorLengthM(const Corridor& c);

} // namespace pf::mission
