// The sweep planner's working state: each merged cell with its lanes and the ways between them, a
// direction's lane-height variant, the full plan of one (order problems, orders, router), and the
// lane-level order that flies the lanes row by row. Internal to the sweep planner.
#pragma once

#include "core/plan/sweep/cell_order.h"
#include "core/plan/sweep/decomposition.h"
#include "core/plan/sweep/sweep_lanes.h"
#include "core/plan/sweep/sweep_routing.h"

#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace pf::plan::sweep_detail {

// One merged cell of a direction, with its lanes and the connections between consecutive lanes.
struct PlannedCell {
    int merged = 0;
    std::vector<CellLane> lanes;
    int firstPoint = 0;              // lane j: first photo = firstPoint + 2j, last = firstPoint + 2j + 1
    std::vector<Route> right, left;  // between lanes j and j + 1 at their right (last) / left (first) ends
    double laneTimeS = 0.0;
    bool reachable = true;
    int pt(std::size_t j, bool last) const { return firstPoint + 2 * static_cast<int>(j) + (last ? 1 : 0); }
};

// The lanes of a way: lane j flown left to right when (j + parity) is even.
inline bool leftToRight(std::size_t j, int parity) { return (j + static_cast<std::size_t>(parity)) % 2 == 0; }

struct DirectionPlan {
    double angleDeg = 0.0;
    double estimateS = 0.0;
    std::shared_ptr<const Decomposition> dec;           // shared by the lane-height variants of a direction
    std::shared_ptr<const std::vector<MergedCell>> mc;
    std::vector<double> sharedLines; // the variant's shared lines (SweepLaneParams), or none
    std::vector<std::vector<double>> heights;
    std::vector<std::vector<char>> pinned; // lanes that neighbours lean on
    const Decomposition& d() const { return *dec; }
    const std::vector<MergedCell>& merged() const { return *mc; }
};

struct FullPlan {
    double angleDeg = 0.0;
    std::unique_ptr<Router> router;
    std::vector<PlannedCell> cells;      // every merged cell (unreachable ones flagged)
    std::vector<int> orderCellOf;        // order problem cell -> index into cells
    OrderProblem problem;                // cells, two ways each
    OrderResult order;
    OrderProblem laneProblem;            // lanes, one way each (first photo to last), for the lane-level search
    std::vector<std::vector<int>> near;  // per end point: the nearest end points of other lanes
    std::vector<std::pair<int, int>> laneRef; // lane-level cell -> (index into cells, lane)
    std::vector<int> laneBase;           // per planned cell: its first lane-level id
    std::vector<OrderStep> steps;        // lane-level order: the improved one
    std::vector<OrderStep> constructed;  // lane-level order of the cell-level construction alone
    double timeS = std::numeric_limits<double>::infinity();
    double missedM2 = 0.0;               // ground beside lane ends no photo may reach (estimate)
    int laneMoves = 0;
    bool rowStart = false;               // the kept lane order came from the row-by-row start
    int homePt = -1, landingPt = -1;
    const DirectionPlan* dir = nullptr;
};

// The lane-level sequence that flies the lanes row by row (lanes less than half a spacing apart across
// the lanes form a row, flown along the lanes' direction in turn), the best of the four corners to
// begin at by the problem's own cost; empty without lanes.
std::vector<OrderStep> rowOrders(const OrderProblem& lanes, const std::vector<std::pair<int, int>>& laneRef,
                                 const std::vector<PlannedCell>& cells, const SweepFrame& frame, double spacing);

} // namespace pf::plan::sweep_detail
