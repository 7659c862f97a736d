// The wavefront planner (paper 004): gradient ascent on a navigation function, minimum completion time.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/cell_path.h"
#include "core/plan/planner.h"
#include "core/result.h"

#include <vector>

namespace pf::plan {

// The navigation function by wavefront propagation from `goal`: 1 at the goal, k + 1 on the cells k moves
// away (4- or 8-connected allowed moves), 0 where the goal cannot be reached.
std::vector<int> navigationFunction(const grid::Grid& g, int goal, bool moore);

struct WavefrontTrace {
    std::vector<double> candidateTimes; // T of each candidate path, in the order they were built
    int chosen = -1;                    // index of the kept candidate (minimum T)
    int tiePoints = 0;                  // ties recorded on the first candidate (unexpanded nodes)
};

// Coverage by gradient ascent from the start (goal = the landing cell, else the start): always to the
// unvisited neighbour of highest potential. Ties are broken by the smallest turn, then E, N, W, S (and
// NE, NW, SW, SE) order, and recorded; further candidates take the second choice at recorded ties
// spread over the first path. At a dead end the shortest safe path leads to the nearest unvisited
// cell. The candidate with the smallest T = S / V + sum(theta) / omega is returned.
Result<CellPath> planWavefront(const grid::Grid& g, const CoverageRequest& req, const WavefrontOptions& opt,
                               WavefrontTrace* trace = nullptr);

} // namespace pf::plan
