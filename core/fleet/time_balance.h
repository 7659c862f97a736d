// Balancing a partition on estimated flight time: boundary cells move from the slowest subarea to
// faster neighbours until the makespan is near the ideal (the one balancing loop of the fleet stage).
#pragma once

#include "core/fleet/partition.h"
#include "core/result.h"

#include <functional>
#include <vector>

namespace pf::fleet {

// Flight time of aircraft k over the subarea made of `cells`, in seconds: the facade passes the
// real planner; tests pass an analytic model. balanceByTime calls it from several threads at once
// (the subareas a trial changes are estimated together), each working for the caller's job
// (JobScope): it must be safe to call concurrently.
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
// since planned times do not change smoothly with the cells given), re-estimates both, and keeps
// the move only if the slower of the two is now faster than the slowest was. When no direct move
// helps, it tries chains: slowest -> neighbour -> that neighbour's fastest neighbour. The best
// trial of a round wins. When none helps, the least bad one is taken anyway a few times (maxKicks)
// to leave a local minimum, without handing the cells straight back. Repeats until the makespan is
// within the tolerance, no move helps, or the round or estimate budget is spent. Subareas stay
// connected. `p` is replaced by the best partition seen (smallest makespan). A cancelled job
// (stopRequested()) gets ErrorCode::Cancelled within one cell move, `p` left as it was.
Result<BalanceReport> balanceByTime(const grid::Grid& g, Partition& p, const TimeEstimator& estimate,
                                    const BalanceOptions& opt = {});

} // namespace pf::fleet
