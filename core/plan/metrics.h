// Quality figures of a coverage path: the paper's turns, distance and jumps, plus time and a turn bound.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/cell_path.h"
#include "core/plan/flight_time.h"

namespace pf::plan {

struct MetricsOptions {
    FlightTimeModel time;       // V, omega and the stop at each turn
    bool diagonalSteps = false; // diagonal steps between safe neighbours are moves, not jumps (8-connected)
    bool turnLowerBound = true; // compute the lower bound on turns (computeTurnBound; not for diagonal steps)
};

struct PathMetrics {
    int visitable = 0;          // cells the grid asks to photograph
    int cells = 0;              // distinct visitable cells the path photographs (non-transit occurrences)
    int photos = 0;             // photo waypoints (filled in by the waypoint stage; 0 for a bare path)
    int occurrences = 0;        // cells in the path, transits included
    double pathLengthM = 0.0;   // sum of the straight legs between consecutive flight positions
    double distanceM = 0.0;     // the paper's distance: path length plus the leg from the last cell back
                                // to the first
    int turns = 0;              // direction changes between consecutive legs (a U-turn counts once)
    double turnAngleDeg = 0.0;  // sum of the direction changes
    int jumps = 0;              // consecutive cells joined by no allowed move
    int revisits = 0;           // transit occurrences
    double estimatedTimeS = 0.0; // plan::FlightTimeModel over the flight positions: S / V + sum(theta) /
                                 // omega (paper 004) + a stop per turn, S = path length
    double planningMs = 0.0;    // wall time of the planner (filled in by the caller)
    // computeTurnBound(grid).turns: no jump-free 4-connected path that visits every visitable cell can
    // turn fewer times. -1 when not computed (not asked, or diagonal steps count as moves).
    int turnLowerBound = -1;
    double turnRatio = 0.0;     // turns / turnLowerBound (1 when both are 0)
    bool complete() const { return cells == visitable; }
};

// Measures `path` on grid `g`. Turn directions use the grid steps between cells (so the small offsets of
// shifted flight positions do not count as turns); lengths use the flight positions in metres.
PathMetrics computeMetrics(const grid::Grid& g, const CellPath& path, const MetricsOptions& opt = {});

// The minimum number of straight runs covering all visitable cells: by Koenig's theorem, the maximum
// matching between row segments and column segments (each cell an edge), found with Hopcroft-Karp.
int minStraightRuns(const grid::Grid& g);

// Work (adjacency entries scanned) allowed to the exact part of computeTurnBound: about 10 to 30 ms on
// this machine. The sample areas need less than 1 % of it; large grids with many holes run out of it and
// get the proven part of the bound (never below straightRuns - 1).
constexpr long long kTurnBoundWork = 5'000'000;

// A lower bound on the turns of every path over the grid's allowed 4-connected moves (no jumps) that
// visits every visitable cell, whatever its start and end; metrics.cpp gives the proof. A run is a
// maximal straight line of cells joined by allowed moves, a row run (East-West) or a column run.
struct TurnBound {
    int turns = 0;        // the bound: 2M - 2, or 2M - 1 when every cover with at most M runs per side
                          // has exactly M on each (M = balancedRuns); never below straightRuns - 1
    int straightRuns = 0; // fewest runs covering all cells (minStraightRuns)
    int balancedRuns = 0; // M = min over sets of runs covering all cells of max(row runs, column runs);
                          // when !exact, a proven lower bound on M
    bool exact = false;   // M was found within the work budget (on large grids it may not be)
};
TurnBound computeTurnBound(const grid::Grid& g, long long workBudget = kTurnBoundWork);

} // namespace pf::plan
