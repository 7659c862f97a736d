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

double makespan(const std::vector<double>& t) {
    return *std::max_element(t.begin(), t.end());
}

// Step sizes to try: the linear estimate first, then larger ones (an aircraft whose own cells
// are several base cells wide only changes its plan once a whole strip of them is handed
// over), then smaller ones; at most half the giver.
std::vector<int> stepSizes(int m0, int giverSize) {
    std::vector<int> out;
    for (int m : {m0, 2 * m0, 4 * m0, 8 * m0, m0 / 2, m0 / 4, 1})
        if (m >= 1 && m <= giverSize / 2 && std::find(out.begin(), out.end(), m) == out.end())
            out.push_back(m);
    return out;
}

// One trial: move cells along `chain` (each link hands `counts[i]` cells to the next), re-estimate
// the subareas involved and undo. `worst` is the slowest re-estimated time (infinity if a link had
// nothing to give), `fresh` the new times. Transfers are deterministic, so a trial can be replayed.
struct Trial {
    std::vector<int> chain;
    std::vector<int> counts;
    bool sweep = false;
    double worst = std::numeric_limits<double>::infinity();
    std::vector<double> fresh;
};

// The cells a trial moved, per giver, in the order moved: what undoing it puts back.
using Moves = std::vector<std::pair<int, std::vector<int>>>;

// What one round searches from: the slowest subarea and its neighbours, and the trials it found.
struct Round {
    int s = -1;                        // the slowest subarea
    double ts = 0.0;                   // its time
    double goodEnough = 0.0;           // a trial this good is taken at once (saves estimates)
    std::vector<std::vector<int>> adj; // shared move-edges between subareas
    std::vector<int> neighbours;       // of s, fastest first
    Trial best;                        // the trial with the smallest slowest time
    Trial kick;                        // the best one that makes s faster, whatever else it does
};

// The balancing state: the working assignment, the current and the best times, the budgets.
class TimeBalancer {
public:
    TimeBalancer(const grid::Grid& g, const Partition& p, const TimeEstimator& estimate,
                 const BalanceOptions& opt)
        : m_g(g), m_n(static_cast<int>(p.cells.size())), m_estimate(estimate), m_opt(opt),
          m_as(g, p), m_times(static_cast<std::size_t>(m_n), 0.0), m_bestOwner(p.owner) {}

    Status estimateStart(const Partition& p);
    Status runRounds();
    BalanceReport finish(Partition& p);

private:
    double& at(int k) { return m_times[static_cast<std::size_t>(k)]; }
    std::vector<int> cellsOf(int k) const;
    Result<std::vector<double>> estimateNow(const std::vector<int>& ks);
    bool apply(const Trial& t, Moves& done);
    void undo(const Moves& done);
    Status evaluate(Trial& t);
    void commit(const Trial& t);
    Round startRound(int s, double ideal);
    int cellsFor(int from, int to);
    void consider(Round& r, const Trial& t) const;
    Status tryDirectMoves(Round& r, std::pair<int, int> tabu);
    Status tryChainedMoves(Round& r);
    void keepIfBest();

    const grid::Grid& m_g;
    const int m_n;
    const TimeEstimator& m_estimate;
    const BalanceOptions& m_opt;
    CellAssignment m_as;
    BalanceReport m_rep;
    std::vector<double> m_times;
    std::vector<int> m_bestOwner;
    std::vector<double> m_bestTimes;
    int m_moved = 0, m_bestMoved = 0;
    int m_maxEstimates = 0;
};

// The cells subarea k owns now, ascending: what the estimator plans over.
std::vector<int> TimeBalancer::cellsOf(int k) const {
    std::vector<int> cells;
    for (int c = 0; c < m_g.cellCount(); ++c)
        if (m_as.owner(c) == k)
            cells.push_back(c);
    return cells;
}

// The times of the subareas of `ks` as they are now, estimated at once (estimateAll); the first
// error in the order of `ks`.
Result<std::vector<double>> TimeBalancer::estimateNow(const std::vector<int>& ks) {
    std::vector<std::vector<int>> cells;
    for (int k : ks)
        cells.push_back(cellsOf(k));
    m_rep.estimatorCalls += static_cast<int>(ks.size());
    std::vector<Result<double>> ts = estimateAll(m_estimate, ks, cells);
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
}

// The first estimate of every non-empty subarea: the starting times, the best seen so far, and
// the estimate budget counted from here.
Status TimeBalancer::estimateStart(const Partition& p) {
    std::vector<int> ks;
    for (int k = 0; k < m_n; ++k)
        if (!p.cells[static_cast<std::size_t>(k)].empty())
            ks.push_back(k);
    auto t = estimateNow(ks);
    if (!t)
        return t.error();
    for (std::size_t i = 0; i < ks.size(); ++i)
        m_times[static_cast<std::size_t>(ks[i])] = (*t)[i];
    m_bestTimes = m_times;
    m_maxEstimates = m_rep.estimatorCalls + m_opt.maxEstimates;
    return {};
}

// Moves the trial's cells, from the last link of the chain back; false if a link had none to give.
bool TimeBalancer::apply(const Trial& t, Moves& done) {
    for (std::size_t i = t.counts.size(); i-- > 0;) {
        auto cells = m_as.transfer(t.chain[i], t.chain[i + 1], t.counts[i], t.sweep);
        const bool empty = cells.empty();
        done.emplace_back(t.chain[i], std::move(cells));
        if (empty)
            return false;
    }
    return true;
}

// Hands the moved cells back, in the reverse order, so the assignment is as before the trial.
void TimeBalancer::undo(const Moves& done) {
    for (auto it = done.rbegin(); it != done.rend(); ++it)
        for (auto c = it->second.rbegin(); c != it->second.rend(); ++c)
            m_as.assign(*c, it->first);
}

// Tries the trial (apply, estimate, undo), filling its `worst` and `fresh` times.
Status TimeBalancer::evaluate(Trial& t) {
    Moves done;
    const bool applied = apply(t, done);
    if (stopRequested()) { // the cells moved may be fewer than asked: no trial to estimate
        undo(done);
        return makeError(ErrorCode::Cancelled, "planning cancelled");
    }
    if (applied) {
        auto e = estimateNow(t.chain);
        if (!e) {
            undo(done);
            return e.error();
        }
        t.fresh = std::move(*e);
        t.worst = *std::max_element(t.fresh.begin(), t.fresh.end());
    }
    undo(done);
    return {};
}

// Replays an evaluated trial for good: its cells move and its fresh times become the current ones.
void TimeBalancer::commit(const Trial& t) {
    Moves done;
    apply(t, done);
    for (std::size_t i = 0; i < t.chain.size(); ++i)
        at(t.chain[i]) = t.fresh[i];
    for (const auto& d : done)
        m_moved += static_cast<int>(d.second.size());
}

// The round's starting point: s, its time, and its neighbours from the fastest.
Round TimeBalancer::startRound(int s, double ideal) {
    Round r;
    r.s = s;
    r.ts = at(s);
    r.goodEnough = (1.0 + m_opt.tolerance) * ideal;
    r.adj = m_as.adjacency();
    for (int k = 0; k < m_n; ++k)
        if (r.adj[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)] > 0)
            r.neighbours.push_back(k);
    std::stable_sort(r.neighbours.begin(), r.neighbours.end(),
                     [&](int a, int b) { return at(a) < at(b); });
    return r;
}

// How many cells close the gap between `from` and `to`, from their times per cell (damped).
int TimeBalancer::cellsFor(int from, int to) {
    const double perFrom = at(from) / std::max(1, m_as.size(from));
    const double perTo = at(to) > 0 ? at(to) / std::max(1, m_as.size(to)) : perFrom;
    const int m =
        static_cast<int>(std::floor(m_opt.damping * (at(from) - at(to)) / (perFrom + perTo)));
    return std::clamp(m, 1, std::max(1, m_as.size(from) - 1));
}

// Keeps the trial as the round's best, and as its kick if it makes s faster (a trial that changes
// nothing for s would only spend a kick).
void TimeBalancer::consider(Round& r, const Trial& t) const {
    if (t.worst < r.best.worst)
        r.best = t;
    if (!t.fresh.empty() && t.fresh.front() < r.ts - 1e-9 && t.worst < r.kick.worst)
        r.kick = t;
}

// Direct moves to a faster neighbour: every step size, both cell orders; the best trial wins.
// Planned times are not smooth in the cells given (a grid of larger cells may not change at
// all, a protruding cell may cost a whole extra stride), hence the search. `tabu` is the
// hand-back a kick forbids.
Status TimeBalancer::tryDirectMoves(Round& r, std::pair<int, int> tabu) {
    for (int n : r.neighbours) {
        if (at(n) >= r.ts)
            break;
        if (tabu == std::make_pair(r.s, n))
            continue;
        for (int m : stepSizes(cellsFor(r.s, n), m_as.size(r.s)))
            for (bool sweep : {false, true}) {
                if (m_rep.estimatorCalls >= m_maxEstimates)
                    break;
                if (r.best.worst <= r.goodEnough)
                    break;
                Trial t{{r.s, n}, {m}, sweep, std::numeric_limits<double>::infinity(), {}};
                if (auto st = evaluate(t); !st)
                    return st.error();
                consider(r, t);
            }
    }
    return {};
}

// Moves through a neighbour: s gives to n, which passes as many on to its fastest other
// neighbour.
Status TimeBalancer::tryChainedMoves(Round& r) {
    for (int n : r.neighbours) {
        int f = -1;
        for (int k = 0; k < m_n; ++k)
            if (k != r.s && k != n &&
                r.adj[static_cast<std::size_t>(n)][static_cast<std::size_t>(k)] > 0 &&
                at(k) < r.ts && (f < 0 || at(k) < at(f)))
                f = k;
        if (f < 0)
            continue;
        for (int m : stepSizes(cellsFor(r.s, f), m_as.size(r.s))) {
            if (m_rep.estimatorCalls >= m_maxEstimates)
                break;
            Trial t{{r.s, n, f}, {m, m}, true, std::numeric_limits<double>::infinity(), {}};
            if (auto st = evaluate(t); !st)
                return st.error();
            consider(r, t);
        }
    }
    return {};
}

// Remembers the current partition if its makespan is the smallest seen.
void TimeBalancer::keepIfBest() {
    if (makespan(m_times) < makespan(m_bestTimes)) {
        m_bestTimes = m_times;
        for (int c = 0; c < m_g.cellCount(); ++c)
            m_bestOwner[static_cast<std::size_t>(c)] = m_as.owner(c);
        m_bestMoved = m_moved;
    }
}

// The rounds: each searches moves away from the slowest subarea and takes the best one (or a
// kick), until the makespan is within the tolerance, nothing helps, or a budget is spent.
Status TimeBalancer::runRounds() {
    int kicks = 0;
    std::pair<int, int> tabu{-1, -1};
    for (m_rep.rounds = 0; m_rep.rounds < m_opt.maxRounds && m_rep.estimatorCalls < m_maxEstimates;
         ++m_rep.rounds) {
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "planning cancelled");
        const double ideal = std::accumulate(m_times.begin(), m_times.end(), 0.0) / m_n;
        const int s =
            static_cast<int>(std::max_element(m_times.begin(), m_times.end()) - m_times.begin());
        if (at(s) <= (1.0 + m_opt.tolerance) * ideal)
            break;
        Round r = startRound(s, ideal);
        if (auto st = tryDirectMoves(r, tabu); !st)
            return st;
        if (!(r.best.worst < r.ts - 1e-9))
            if (auto st = tryChainedMoves(r); !st)
                return st;
        const bool accepted = r.best.worst < r.ts - 1e-9;
        if (accepted) {
            commit(r.best);
        } else if (kicks < m_opt.maxKicks && std::isfinite(r.kick.worst)) {
            // Stuck in a local minimum of a rough landscape: take the least bad move that relieves
            // the slowest subarea anyway (the best partition seen is kept), and forbid handing the
            // cells straight back next round.
            ++kicks;
            commit(r.kick);
            tabu = {r.kick.chain[1], r.kick.chain[0]};
            continue;
        }
        tabu = {-1, -1};
        if (!accepted)
            break; // no move found that makes the slowest subarea faster
        keepIfBest();
    }
    return {};
}

// Replaces `p` by the best partition seen and reports its times.
BalanceReport TimeBalancer::finish(Partition& p) {
    Partition best;
    best.owner = m_bestOwner;
    best.targets = p.targets;
    best.cells.assign(static_cast<std::size_t>(m_n), {});
    for (int c = 0; c < m_g.cellCount(); ++c)
        if (const int k = m_bestOwner[static_cast<std::size_t>(c)]; k >= 0)
            best.cells[static_cast<std::size_t>(k)].push_back(c);
    best.disconnectedSubareas = p.disconnectedSubareas;
    p = std::move(best);
    m_rep.times = m_bestTimes;
    m_rep.makespan = makespan(m_bestTimes);
    m_rep.ideal = std::accumulate(m_bestTimes.begin(), m_bestTimes.end(), 0.0) / m_n;
    m_rep.cellsMoved = m_bestMoved;
    return m_rep;
}

} // namespace

Result<BalanceReport> balanceByTime(const grid::Grid& g, Partition& p,
                                    const TimeEstimator& estimate, const BalanceOptions& opt) {
    if (p.cells.empty())
        return makeError(ErrorCode::InvalidInput, "No subareas to balance.");
    if (!estimate)
        return makeError(ErrorCode::InvalidInput,
                         "No flight time estimator to balance the subareas with.");
    TimeBalancer balancer(g, p, estimate, opt);
    if (auto st = balancer.estimateStart(p); !st)
        return st.error();
    if (auto st = balancer.runRounds(); !st)
        return st.error();
    return balancer.finish(p);
}

} // namespace pf::fleet
