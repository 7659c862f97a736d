// Terrain following: each waypoint at a height above the ground under it, every leg checked against
// the terrain along its length, waypoints inserted where the ground rises between two of them.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"
#include "core/route/waypoint.h"
#include "core/terrain/height_grid.h"

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pf::route {

struct TerrainFollowOptions {
    double heightAboveGroundM = 0.0; // every waypoint this high above the ground under it (> 0)
    double minClearanceM = 0.0;      // no point of a leg closer to the ground (<= the height)
    double sampleStepM = 1.0;        // legs are sampled this often
    double homeGroundM = 0.0;        // the take-off point's ground, metres above sea level
};

// The lowest clearance along one leg flown from (a, za) to (b, zb), altitudes above sea level
// linear in between, sampled every `stepM` metres (both ends included); +infinity where the grid
// has no data along all of it.
struct LegClearance {
    double clearanceM = std::numeric_limits<double>::infinity();
    double distanceM = 0.0; // from a, where it is lowest
    double uncheckedM = 0.0; // length over no data
};
LegClearance legClearance(const terrain::HeightGrid& grid, const geo::Vec2& a, double za, const geo::Vec2& b,
                          double zb, double stepM = 1.0);

struct TerrainFollowResult {
    std::vector<LocalWaypoint> waypoints;     // the input's, with the inserted ones in flight order
    std::vector<double> groundM;              // per waypoint: the ground under it, above sea level
    std::vector<double> altitudeM;            // per waypoint: above sea level
    std::vector<bool> inserted;               // per waypoint: added to keep the clearance
    std::vector<std::pair<int, int>> sorties; // the input's sortie ranges, in the new indices
    double lowestClearanceM = std::numeric_limits<double>::infinity(); // along every leg checked
    double uncheckedM = 0.0;                  // leg length over ground the grid does not know
    int insertedCount = 0;
    std::vector<std::string> warnings;
};

// Sets the altitude of every waypoint of `flown` to the ground under it plus the height above
// ground, and checks every leg every sampleStepM metres: between two waypoints the aircraft flies a
// straight line between their altitudes; out of `home` it climbs there to the first waypoint's
// altitude and flies level to it; back home it flies level at the last waypoint's altitude (a return
// to launch that keeps its height). Where the ground along a leg comes closer than the minimum
// clearance, a waypoint is inserted at the worst point, the height above ground over it, and both
// halves are checked again (a Turn waypoint between survey waypoints, a Transit one on transit
// legs). `sorties` are inclusive index ranges of `flown`, each flown from home to home (one range over
// everything without a home); the last one returns to `landing` when given. Errors: a height or
// clearance out of range, a grid with no data under every waypoint.
Result<TerrainFollowResult> followTerrain(const std::vector<LocalWaypoint>& flown,
                                          const std::vector<std::pair<int, int>>& sorties,
                                          const std::optional<geo::Vec2>& home, const terrain::HeightGrid& grid,
                                          const TerrainFollowOptions& options,
                                          const std::optional<geo::Vec2>& landing = std::nullopt);

} // namespace pf::route
