// Detailed traced boundaries (cadastral outlines, a field edge walked with a GNSS receiver) come
// with hundreds of thousands of vertices, most of them centimetres apart. The planner's stages grow
// with the vertex count, and no photo sees the difference: such an area and its no-fly zones are
// simplified before they are checked and planned, and the plan says by how much.
#pragma once

#include "core/mission/mission.h"

#include <cstddef>
#include <string>

namespace pf::mission {

// Missions whose area and no-fly zones have at most this many vertices in all are planned as given
// (hand-drawn and imported areas of ordinary detail are never touched).
constexpr std::size_t kSimplifyAboveVertices = 5'000;

// The most vertices (area and zones together, after simplifying) a mission may have: beyond it,
// checking and planning take more than a few seconds.
constexpr std::size_t kMaxPlanVertices = 20'000;

// The simplification tolerance: 5 % of the smallest track spacing among the aircraft, at most 0.5
// m. At 5 % of the spacing, the side overlap (20 % and more of a footprint) absorbs the change many
// times over; 0.5 m is below what a survey aircraft without RTK holds its position to (1-2 m), so
// no flight could follow the finer detail. 0.5 m when no aircraft has a footprint yet.
constexpr double kSimplifyShareOfSpacing = 0.05;
constexpr double kMaxSimplifyToleranceM = 0.5;
double simplifyToleranceM(const Mission& m);

struct InputSimplification {
    Mission mission; // as given, or with its area and no-fly zones simplified
    bool simplified = false;
    double toleranceM = 0.0;
    std::size_t areaVerticesBefore = 0, areaVerticesAfter = 0;
    std::size_t zoneVerticesBefore = 0, zoneVerticesAfter = 0;
    double areaBeforeM2 = 0.0, areaAfterM2 = 0.0;
    std::string note;  // what changed, for the plan's messages (empty when nothing changed)
    std::string error; // more than kMaxPlanVertices even after simplifying (empty when it fits)
};

// Simplifies the area and every no-fly zone of a mission of more than kSimplifyAboveVertices
// vertices (not a corridor's ground, which is built from its line) within simplifyToleranceM, each
// ring by Douglas-Peucker that keeps the topology (GEOS), then widens each polygon by the
// tolerance: the simplified area holds every point of the given one (no strip of it is left out of
// the plan) and each simplified zone holds all of its given zone (no route enters it). Polygons
// that cannot be simplified (invalid ones, which validation reports) stay as given. validateMission
// and planMission both start from it, so the check, the CLI and the GUI see the same mission; route
// checks after planning check against its polygons (they hold the given ones). `checkedValid`: the
// caller found no error in the area and the zones (validateMission), they are not checked again.
InputSimplification simplifyInput(const Mission& m, bool checkedValid = false);

} // namespace pf::mission
