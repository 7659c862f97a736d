// What every coverage planner is asked (start, take-off and landing cells) and one entry point over them.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/cell_path.h"
#include "core/plan/flight_time.h"
#include "core/result.h"

#include <optional>
#include <string>

namespace pf::plan {

// The grid coverage planners; their names and descriptions are in the one table of planner kinds
// (core/mission/planner_kinds).
enum class PlannerKind { Stride, Raster, Wavefront };

struct CoverageRequest {
    // Where the coverage path begins. -1: the take-off cell if set, else the first visitable cell in
    // index order (the lowest row's leftmost cell, always on the contour). The raster and wavefront
    // planners and the stride planner's paper rules photograph it first; the stride planner's lead-in
    // variants may first fly from it, without photographing, to a corner of the area.
    int start = -1;
    // Cell under the take-off point: when it differs from the start, a transit path over allowed
    // moves leads from it to the start. -1: none.
    int takeoff = -1;
    // Cell under the landing point: a transit path over allowed moves leads from the last cell to it.
    // For the wavefront planner it is also the goal of the navigation function. -1: none.
    int landing = -1;
};

struct WavefrontOptions {
    bool moore = true;         // 8-connected (Moore) moves; false: 4-connected (von Neumann)
    int maxCandidates = 8;     // candidate paths compared (branches at recorded ties), >= 1
    FlightTimeModel time;      // what the candidate paths are compared on
};

// How the stride planner compares its variants' paths: byTime false, the fewest turns (the paper's
// measure), then the shorter path; true, the shortest time by the one flight-time model, then fewer
// turns.
struct StrideChoice {
    bool byTime = false;
    FlightTimeModel time;
};

struct PlanOptions {
    PlannerKind kind = PlannerKind::Stride;
    WavefrontOptions wavefront;
    // Stride planner: compare its rule variants (planStride); false: the paper's rules only, one plan
    // (faster: for estimates planned many times over).
    bool strideVariants = true;
    // What the variants are compared on (a mission: an aircraft that turns fast flies a shorter path
    // with a few more turns sooner).
    StrideChoice stride;
};

// Checks the request against the grid: errors name the problem (no cell to photograph, a start,
// take-off or landing cell outside the grid or not visitable). Returns the resolved start cell.
Result<int> resolveStart(const grid::Grid& g, const CoverageRequest& req);

// Wraps a planner's coverage `body`, which starts at `start`, with safe transits from the request's
// take-off cell and to its landing cell (shortest paths over allowed moves, flagged as revisits).
CellPath withTakeoffAndLanding(const grid::Grid& g, const CoverageRequest& req, int start, CellPath body);

// Runs the chosen planner. Every visitable cell appears at least once without the transit flag.
Result<CellPath> planCoverage(const grid::Grid& g, const CoverageRequest& req, const PlanOptions& opt);

// True if the planner may fly from a to b: an allowed 4-move, or (when `diagonal`) a diagonal step
// between two visitable cells whose straight segment is safe.
bool isAllowedStep(const grid::Grid& g, int a, int b, bool diagonal);

} // namespace pf::plan
