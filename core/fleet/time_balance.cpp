// Balancing a partition on estimated flight time: trials of direct and chained cell transfers,
// kicks out of local minima, the best partition seen kept.
#include "core/fleet/time_balance.h"

#include "core/fleet/cell_assignment.h"
#include "core/grid/grid.h"
#include "core/job_scope.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

namespace pf::fleet {

namespace {

// The estimates of several subareas, each but the first on a thread of its own beside this one:
// they are independent plans (a trial changes two or three subareas, and each is planned), so the
// times are those estimated one after the other, in about half the wall time on two cores. The
// threads work for this thread's job (they stop when it is cancelled) and are joined before this
// returns.
std::vector<Result<double>> estimateAll(const TimeEstimator& estimate, const std::vector<int>& ks,
                                        const std::vector<std::vector<int>>& cells) {
    std::vector<Result<double>> out;
    if (ks.empty())
        return out;
    const JobScope::Share job = JobScope::share();
    std::vector<std::future<Result<double>>> others;
    for (std::size_t i = 1; i < ks.size(); ++i)
        others.push_back(std::async(std::launch::async, [&, i] {
            JobScope scope(job);
            return estimate(ks[i], cells[i]);
        }));
    out.push_back(estimate(ks[0], cells[0]));
    for (auto& f : others)
        out.push_back(f.get());
    return out;
}

} // namespace

Result<BalanceReport> balanceByTime(const grid::Grid& g, Partition& p, const TimeEstimator& estimate,
                                    const BalanceOptions& opt) {
    const int n = static_cast<int>(p.cells.size());
    if (n == 0)
        return makeError(ErrorCode::InvalidInput, "No subareas to balance.");
    if (!estimate)
        return makeError(ErrorCode::InvalidInput, "No flight time estimator to balance the subareas with.");
    BalanceReport rep;
    CellAssignment as(g, p);
    std::vector<double> times(static_cast<std::size_t>(n), 0.0);
    auto cellsOf = [&](int k) {
        std::vector<int> cells;
        for (int c = 0; c < g.cellCount(); ++c)
            if (as.owner(c) == k)
                cells.push_back(c);
        return cells;
    };
    // The times of the subareas of `ks` as they are now, estimated at once (estimateAll); the first
    // error in the order of `ks`.
    auto estAll = [&](const std::vector<int>& ks) -> Result<std::vector<double>> {
        std::vector<std::vector<int>> cells;
        for (int k : ks)
            cells.push_back(cellsOf(k));
        rep.estimatorCalls += static_cast<int>(ks.size());
        std::vector<Result<double>> ts = estimateAll(estimate, ks, cells);
        std::vector<double> out;
        for (std::size_t i = 0; i < ks.size(); ++i) {
            if (!ts[i])
                return ts[i].error();
            if (!std::isfinite(*ts[i]) || *ts[i] < 0)
                return makeError(ErrorCode::Internal, "The flight time estimate of aircraft " +
                                                          std::to_string(ks[i] + 1) +
                                                          " is not a valid duration.");
            out.push_back(*ts[i]);
        }
        return out;
    };
    {
        std::vector<int> ks;
        for (int k = 0; k < n; ++k)
            if (!p.cells[static_cast<std::size_t>(k)].empty())
                ks.push_back(k);
        auto t = estAll(ks);
        if (!t)
            return t.error();
        for (std::size_t i = 0; i < ks.size(); ++i)
            times[static_cast<std::size_t>(ks[i])] = (*t)[i];
    }
    auto at = [&](int k) -> double& { return times[static_cast<std::size_t>(k)]; };
    auto makespan = [](const std::vector<double>& t) { return *std::max_element(t.begin(), t.end()); };
    const std::vector<int> targets = p.targets;
    std::vector<int> bestOwner = p.owner;
    std::vector<double> bestTimes = times;
    int moved = 0, bestMoved = 0;
    const int maxEstimates = rep.estimatorCalls + opt.maxEstimates;

    // One trial: move cells along `chain` (each link hands `counts[i]` cells to the next), re-estimate
    // the subareas involved and undo. Returns the slowest re-estimated time (infinity if a link had
    // nothing to give) and the fresh times. Transfers are deterministic, so a trial can be replayed.
    struct Trial {
        std::vector<int> chain;
        std::vector<int> counts;
        bool sweep = false;
        double worst = std::numeric_limits<double>::infinity();
        std::vector<double> fresh;
    };
    auto apply = [&](const Trial& t, std::vector<std::pair<int, std::vector<int>>>& done) {
        for (std::size_t i = t.counts.size(); i-- > 0;) {
            auto cells = as.transfer(t.chain[i], t.chain[i + 1], t.counts[i], t.sweep);
            const bool empty = cells.empty();
            done.emplace_back(t.chain[i], std::move(cells));
            if (empty)
                return false;
        }
        return true;
    };
    auto undo = [&](std::vector<std::pair<int, std::vector<int>>>& done) {
        for (auto it = done.rbegin(); it != done.rend(); ++it)
            for (auto c = it->second.rbegin(); c != it->second.rend(); ++c)
                as.assign(*c, it->first);
    };
    auto evaluate = [&](Trial& t) -> Status {
        std::vector<std::pair<int, std::vector<int>>> done;
        const bool applied = apply(t, done);
        if (stopRequested()) { // the cells moved may be fewer than asked: no trial to estimate
            undo(done);
            return makeError(ErrorCode::Cancelled, "planning cancelled");
        }
        if (applied) {
            auto e = estAll(t.chain);
            if (!e) {
                undo(done);
                return e.error();
            }
            t.fresh = std::move(*e);
            t.worst = *std::max_element(t.fresh.begin(), t.fresh.end());
        }
        undo(done);
        return {};
    };
    auto commit = [&](const Trial& t) {
        std::vector<std::pair<int, std::vector<int>>> done;
        apply(t, done);
        for (std::size_t i = 0; i < t.chain.size(); ++i)
            at(t.chain[i]) = t.fresh[i];
        for (const auto& d : done)
            moved += static_cast<int>(d.second.size());
    };

    int kicks = 0;
    std::pair<int, int> tabu{-1, -1};
    for (rep.rounds = 0; rep.rounds < opt.maxRounds && rep.estimatorCalls < maxEstimates; ++rep.rounds) {
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "planning cancelled");
        const double ideal = std::accumulate(times.begin(), times.end(), 0.0) / n;
        const int s = static_cast<int>(std::max_element(times.begin(), times.end()) - times.begin());
        const double ts = at(s);
        if (ts <= (1.0 + opt.tolerance) * ideal)
            break;
        const auto adj = as.adjacency();
        std::vector<int> neighbours;
        for (int k = 0; k < n; ++k)
            if (adj[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)] > 0)
                neighbours.push_back(k);
        std::stable_sort(neighbours.begin(), neighbours.end(), [&](int a, int b) { return at(a) < at(b); });
        // How many cells close the gap between s and r, from their times per cell (damped).
        auto cellsFor = [&](int from, int to) {
            const double perFrom = at(from) / std::max(1, as.size(from));
            const double perTo = at(to) > 0 ? at(to) / std::max(1, as.size(to)) : perFrom;
            const int m = static_cast<int>(std::floor(opt.damping * (at(from) - at(to)) / (perFrom + perTo)));
            return std::clamp(m, 1, std::max(1, as.size(from) - 1));
        };
        // Step sizes to try: the linear estimate first, then larger ones (an aircraft whose own cells
        // are several base cells wide only changes its plan once a whole strip of them is handed
        // over), then smaller ones; at most half the giver.
        auto stepSizes = [](int m0, int giverSize) {
            std::vector<int> out;
            for (int m : {m0, 2 * m0, 4 * m0, 8 * m0, m0 / 2, m0 / 4, 1})
                if (m >= 1 && m <= giverSize / 2 && std::find(out.begin(), out.end(), m) == out.end())
                    out.push_back(m);
            return out;
        };
        // Direct moves to a faster neighbour: every step size, both cell orders; the best trial wins.
        // Planned times are not smooth in the cells given (a grid of larger cells may not change at
        // all, a protruding cell may cost a whole extra stride), hence the search.
        Trial best;
        // The best trial that makes the slowest subarea faster, whatever it does to the others: the
        // kick below takes it (a trial that changes nothing for s would only spend a kick).
        Trial kick;
        const auto consider = [&](const Trial& t) {
            if (t.worst < best.worst)
                best = t;
            if (!t.fresh.empty() && t.fresh.front() < ts - 1e-9 && t.worst < kick.worst)
                kick = t;
        };
        // A trial that brings both subareas within the tolerance is taken at once (saves estimates).
        const double goodEnough = (1.0 + opt.tolerance) * ideal;
        for (int r : neighbours) {
            if (at(r) >= ts)
                break;
            if (tabu == std::make_pair(s, r))
                continue;
            for (int m : stepSizes(cellsFor(s, r), as.size(s)))
                for (bool sweep : {false, true}) {
                    if (rep.estimatorCalls >= maxEstimates)
                        break;
                    if (best.worst <= goodEnough)
                        break;
                    Trial t{{s, r}, {m}, sweep, std::numeric_limits<double>::infinity(), {}};
                    if (auto st = evaluate(t); !st)
                        return st.error();
                    consider(t);
                }
        }
        // Otherwise through a neighbour: s gives to r, which passes as many on to its fastest other
        // neighbour.
        if (!(best.worst < ts - 1e-9))
            for (int r : neighbours) {
                int f = -1;
                for (int k = 0; k < n; ++k)
                    if (k != s && k != r && adj[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)] > 0 &&
                        at(k) < ts && (f < 0 || at(k) < at(f)))
                        f = k;
                if (f < 0)
                    continue;
                for (int m : stepSizes(cellsFor(s, f), as.size(s))) {
                    if (rep.estimatorCalls >= maxEstimates)
                        break;
                    Trial t{{s, r, f}, {m, m}, true, std::numeric_limits<double>::infinity(), {}};
                    if (auto st = evaluate(t); !st)
                        return st.error();
                    consider(t);
                }
            }
        const bool accepted = best.worst < ts - 1e-9;
        if (accepted) {
            commit(best);
        } else if (kicks < opt.maxKicks && std::isfinite(kick.worst)) {
            // Stuck in a local minimum of a rough landscape: take the least bad move that relieves
            // the slowest subarea anyway (the best partition seen is kept), and forbid handing the
            // cells straight back next round.
            ++kicks;
            commit(kick);
            tabu = {kick.chain[1], kick.chain[0]};
            continue;
        }
        tabu = {-1, -1};
        if (!accepted)
            break; // no move found that makes the slowest subarea faster
        if (makespan(times) < makespan(bestTimes)) {
            bestTimes = times;
            for (int c = 0; c < g.cellCount(); ++c)
                bestOwner[static_cast<std::size_t>(c)] = as.owner(c);
            bestMoved = moved;
        }
    }

    Partition best;
    best.owner = bestOwner;
    best.targets = targets;
    best.cells.assign(static_cast<std::size_t>(n), {});
    for (int c = 0; c < g.cellCount(); ++c)
        if (bestOwner[static_cast<std::size_t>(c)] >= 0)
            best.cells[static_cast<std::size_t>(bestOwner[static_cast<std::size_t>(c)])].push_back(c);
    best.disconnectedSubareas = p.disconnectedSubareas;
    p = std::move(best);
    rep.times = bestTimes;
    rep.makespan = makespan(bestTimes);
    rep.ideal = std::accumulate(bestTimes.begin(), bestTimes.end(), 0.0) / n;
    rep.cellsMoved = bestMoved;
    return rep;
}

} // namespace pf::fleet
