// Splitting a shared area between several aircraft: flood-fill partition of a base grid (paper 001,
// section V), redistribution to target sizes, balancing on estimated flight time, subarea polygons.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace pf::grid {
class Grid;
}

namespace pf::fleet {

// The base grid the partition works on: the cells to share out and the moves linking them. Kept
// apart from grid::Grid so the partition can be tested on synthetic masks and reused on any grid.
struct BaseGrid {
    int cols = 0;
    int rows = 0;
    double cellSize = 1.0;
    double angleDeg = 0.0;     // grid rotation, counter-clockwise from east (as grid::Grid)
    geo::Vec2 origin{0, 0};    // local position of the (col 0, row 0) corner
    std::vector<std::uint8_t> active;  // 1: a cell to cover, shared out between the aircraft
    std::vector<std::uint8_t> moves;   // bit d (grid::Dir order E, N, W, S): move to that neighbour
    std::vector<std::uint8_t> touches; // 1: the cell touches the area (active or not): for polygons

    // Active = cells needing a visit, moves = the grid's allowed moves, touches = not Outside.
    static BaseGrid fromGrid(const grid::Grid& g);
    // Synthetic: mask != 0 is active; moves between 4-adjacent active cells.
    static BaseGrid fromMask(int cols, int rows, const std::vector<std::uint8_t>& mask, double cellSize = 1.0,
                             geo::Vec2 origin = geo::Vec2(0, 0));

    int cellCount() const { return cols * rows; }
    // Neighbour in direction d (0..3 = E, N, W, S) or -1 past the edge.
    int neighbour(int i, int d) const;
    bool canMove(int i, int d) const { return (moves[static_cast<std::size_t>(i)] >> d) & 1u; }
    geo::Vec2 cellCenter(int i) const;
    // The cell's square, counter-clockwise, in local metres.
    geo::Ring cellSquare(int i) const;
};

struct Partition {
    std::vector<int> owner;              // per base cell: aircraft index, -1 where not active
    std::vector<std::vector<int>> cells; // per aircraft: its base cells, ascending
    std::vector<int> targets;            // per aircraft: the cell count its share asked for
    // Subareas made of several pieces. Only happens when the area itself falls apart into more
    // pieces (separated by no-fly zones) than there are aircraft to give one each.
    int disconnectedSubareas = 0;
};

// Splits the active cells between aircraft in proportion to `shares` (positive; normalised here):
//  1. integer targets by largest remainder;
//  2. one seed per aircraft, taken in turn at the far end of the cells still free (a double BFS
//     sweep), so the subareas line up instead of boxing each other in;
//  3. flood-fill growth to the target, preferring the free cell with the most 4-neighbours already
//     in the subarea (paper fig. 8), then the one with the most walls (edge, hole, other subarea),
//     then the one nearest the sweep's start;
//  4. cells left free afterwards (paper fig. 9) join an adjacent subarea, as whole pieces;
//  5. redistribution: boundary cells move, one at a time, from subareas above target towards the
//     nearest subarea below it (through intermediate subareas if needed), never disconnecting the
//     subarea that gives the cell.
// Every subarea is connected through the base grid's moves whenever the area itself is connected.
// Errors: no shares, a share not positive, fewer active cells than aircraft.
Result<Partition> partitionCells(const BaseGrid& g, const std::vector<double>& shares);

// True if `cells` (non-empty) form one piece through the base grid's moves.
bool isConnected(const BaseGrid& g, const std::vector<int>& cells);

// Flight time of aircraft k over the subarea made of `cells`, in seconds: the facade passes the
// real planner; tests pass an analytic model.
using TimeEstimator = std::function<Result<double>(int aircraft, const std::vector<int>& cells)>;

struct BalanceOptions {
    int maxRounds = 60;        // accepted moves at most
    int maxEstimates = 300;    // estimator calls at most, after the first estimate of each aircraft
    double tolerance = 0.05;   // stop when the makespan is within this fraction of the ideal
    double damping = 0.7;      // fraction of the computed cell transfer tried first
    int maxKicks = 3;          // times a non-improving move may be taken to leave a local minimum
};

struct BalanceReport {
    std::vector<double> times; // per aircraft, of the returned partition
    double makespan = 0.0;     // the longest time
    double ideal = 0.0;        // total time / number of aircraft
    int rounds = 0;
    int estimatorCalls = 0;
    int cellsMoved = 0;        // net moves kept in the returned partition
};

// Goes beyond the paper's cell-count balance: estimates each aircraft's flight time, then moves
// boundary cells from the slowest subarea to an adjacent faster one (how many: the time gap divided
// by both subareas' time per cell, damped; then twice, half, a quarter of that and a single cell,
// since planned times do not change smoothly with the cells given), re-estimates both, and keeps the
// move only if the slower of the two is now faster than the slowest was. When no direct move helps,
// it tries chains: slowest -> neighbour -> that neighbour's fastest neighbour. The best trial of a
// round wins. When none helps, the least bad one is taken anyway a few times (maxKicks) to leave a
// local minimum, without handing the cells straight back. Repeats until the makespan is within the
// tolerance, no move helps, or the round or estimate budget is spent.
// Subareas stay connected. `p` is replaced by the best partition seen (smallest makespan).
Result<BalanceReport> balanceByTime(const BaseGrid& g, Partition& p, const TimeEstimator& estimate,
                                    const BalanceOptions& opt = {});

// The subarea of each aircraft as polygons in local metres: the union of its cells, plus the cells
// touching the area that are not active (assigned to the nearest subarea so that nothing of the
// area is left out), clipped to `clipTo`. Neighbouring subareas share their boundary.
std::vector<geo::MultiPolygon> subareaPolygons(const BaseGrid& g, const Partition& p,
                                               const geo::MultiPolygon& clipTo);
// One set of cells as polygons (for estimators that plan over a candidate subarea).
geo::MultiPolygon cellsPolygon(const BaseGrid& g, const std::vector<int>& cells, const geo::MultiPolygon& clipTo);

} // namespace pf::fleet
