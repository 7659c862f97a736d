// The order search: the construction from several first cells, the kicks, and the entry points;
// the cost model is order_cost.h, the local moves order_moves.h.
#include "core/plan/sweep/cell_order.h"

#include "core/plan/sweep/order_moves.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace pf::plan {

int OrderStep::entry(const OrderProblem& p) const {
    const auto& w = p.cells[static_cast<std::size_t>(cell)].ways[static_cast<std::size_t>(way)];
    return reversed ? w.b : w.a;
}

int OrderStep::exit(const OrderProblem& p) const {
    const auto& w = p.cells[static_cast<std::size_t>(cell)].ways[static_cast<std::size_t>(way)];
    return reversed ? w.a : w.b;
}

namespace {

using order_search::kGainEps;
using order_search::kInf;
using order_search::kNone;

// The construction (nearest neighbour from several first cells) on top of the local moves.
class Search : public order_search::OrderMoves {
public:
    using OrderMoves::OrderMoves;

    // Greedy: from `first`, always the cheapest next cell (link + its way), exact costs evaluated in
    // the order of their lower bounds until no candidate can beat the best.
    std::vector<OrderStep> nearestNeighbour(const OrderStep& first) {
        const std::size_t n = m_p.cells.size();
        std::vector<char> used(n, 0);
        std::vector<OrderStep> seq{first};
        used[static_cast<std::size_t>(first.cell)] = 1;
        struct Cand {
            double lb;
            OrderStep s;
        };
        std::vector<Cand> cands;
        while (seq.size() < n) {
            const int from = exit(seq.back());
            cands.clear();
            for (std::size_t c = 0; c < n; ++c) {
                if (used[c])
                    continue;
                const auto& ways = m_p.cells[c].ways;
                for (std::size_t w = 0; w < ways.size(); ++w)
                    for (int r = 0; r < 2; ++r) {
                        const OrderStep s{static_cast<int>(c), static_cast<int>(w), r == 1};
                        cands.push_back(Cand{bound(from, entry(s)) + wayCost(s), s});
                    }
            }
            std::stable_sort(cands.begin(), cands.end(), [](const Cand& a, const Cand& b) { return a.lb < b.lb; });
            double best = kInf;
            OrderStep pick = cands.front().s;
            for (const auto& c : cands) {
                if (c.lb >= best)
                    break;
                const double v = link(from, entry(c.s)) + wayCost(c.s);
                if (v < best) {
                    best = v;
                    pick = c.s;
                }
            }
            used[static_cast<std::size_t>(pick.cell)] = 1;
            seq.push_back(pick);
        }
        return seq;
    }
};

} // namespace

double orderCost(const OrderProblem& problem, const std::vector<OrderStep>& steps) {
    Search s(problem);
    return s.cost(steps);
}

namespace {

// The cells the construction starts from: with a take-off, the cheapest to begin with (two per
// start tried); when the start is free (all equal), cells spread over the decomposition's order
// (from one side of the area to the other), each both ways.
std::vector<OrderStep> firstCells(const OrderProblem& problem, const OrderOptions& options,
                                  Search& s) {
    const std::size_t n = problem.cells.size();
    struct First {
        double c;
        OrderStep s;
    };
    std::vector<First> firsts;
    for (std::size_t c = 0; c < n; ++c) {
        const auto& ways = problem.cells[c].ways;
        for (std::size_t w = 0; w < ways.size(); ++w)
            for (int r = 0; r < 2; ++r) {
                const OrderStep st{static_cast<int>(c), static_cast<int>(w), r == 1};
                firsts.push_back(First{s.link(kNone, st.entry(problem)) + ways[w].costS, st});
            }
    }
    std::stable_sort(firsts.begin(), firsts.end(), [](const First& a, const First& b) { return a.c < b.c; });
    const int starts = std::max(1, options.maxStarts);
    std::vector<OrderStep> tries;
    if (!problem.start) {
        for (int k = 0; k < starts && static_cast<std::size_t>(k) < n; ++k) {
            const std::size_t c = n <= static_cast<std::size_t>(starts) ? static_cast<std::size_t>(k)
                                                                        : static_cast<std::size_t>(k) * (n - 1) /
                                                                              static_cast<std::size_t>(starts - 1 > 0 ? starts - 1 : 1);
            for (int r = 0; r < 2; ++r)
                tries.push_back(OrderStep{static_cast<int>(c), 0, r == 1});
        }
    } else {
        for (std::size_t k = 0; k < firsts.size() && tries.size() < static_cast<std::size_t>(2 * starts); ++k)
            tries.push_back(firsts[k].s);
    }
    return tries;
}

// The cheapest construction: nearest neighbour from each first cell, and the sweep's own order both
// ways (each cell its best way). Its cost in `cost`.
std::vector<OrderStep> construct(const OrderProblem& problem, const OrderOptions& options,
                                 Search& s, double& cost) {
    const std::size_t n = problem.cells.size();
    std::vector<OrderStep> best;
    cost = kInf;
    for (const auto& f : firstCells(problem, options, s)) {
        auto seq = s.nearestNeighbour(f);
        const double c = s.cost(seq);
        if (c < cost) {
            cost = c;
            best = std::move(seq);
        }
    }
    if (problem.sweepOrder.size() == n) {
        for (int dir = 0; dir < 2; ++dir) {
            std::vector<OrderStep> seq;
            for (std::size_t k = 0; k < n; ++k)
                seq.push_back(OrderStep{problem.sweepOrder[dir ? n - 1 - k : k], 0, false});
            s.bestWays(seq);
            const double c = s.cost(seq);
            if (c < cost) {
                cost = c;
                best = std::move(seq);
            }
        }
    }
    return best;
}

// Iterated local search: a double bridge (A B C D -> A C B D) and a flipped way or two, then the
// local search; kept when the whole flies faster. Seeded: the same problem gives the same order.
// n: the cells.
void kickAndImprove(std::size_t n, const OrderOptions& options, Search& s,
                    std::vector<OrderStep>& steps) {
    std::mt19937 rng(12345);
    double cur = s.cost(steps);
    for (int k = 0; k < options.kicks; ++k) {
        std::vector<OrderStep> t = steps;
        std::uniform_int_distribution<std::size_t> cut(1, n - 1);
        std::size_t c1 = cut(rng), c2 = cut(rng), c3 = cut(rng);
        if (c1 > c2)
            std::swap(c1, c2);
        if (c2 > c3)
            std::swap(c2, c3);
        if (c1 > c2)
            std::swap(c1, c2);
        std::vector<OrderStep> k2(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(c1));
        k2.insert(k2.end(), t.begin() + static_cast<std::ptrdiff_t>(c2),
                  t.begin() + static_cast<std::ptrdiff_t>(c3));
        k2.insert(k2.end(), t.begin() + static_cast<std::ptrdiff_t>(c1),
                  t.begin() + static_cast<std::ptrdiff_t>(c2));
        k2.insert(k2.end(), t.begin() + static_cast<std::ptrdiff_t>(c3), t.end());
        std::uniform_int_distribution<std::size_t> any(0, n - 1);
        k2[any(rng)].reversed ^= true;
        OrderResult scratch;
        s.improve(k2, options, scratch);
        const double c = s.cost(k2);
        if (c < cur - kGainEps) {
            cur = c;
            steps = std::move(k2);
        }
    }
}

} // namespace

OrderResult orderCells(const OrderProblem& problem, const OrderOptions& options) {
    OrderResult out;
    const std::size_t n = problem.cells.size();
    Search s(problem);
    if (n == 0) {
        out.costS = out.constructedCostS = s.cost({});
        return out;
    }
    out.steps = construct(problem, options, s, out.constructedCostS);
    out.constructed = out.steps;
    if (options.improve) {
        s.improve(out.steps, options, out);
        if (!problem.near && n >= 4)
            kickAndImprove(n, options, s, out.steps);
    }
    out.costS = s.cost(out.steps);
    out.moves = s.moves;
    out.linkEvaluations = s.evaluations;
    return out;
}

OrderResult improveOrder(const OrderProblem& problem, std::vector<OrderStep> steps, const OrderOptions& options) {
    OrderResult out;
    Search s(problem);
    out.steps = std::move(steps);
    out.constructed = out.steps;
    out.constructedCostS = s.cost(out.steps);
    if (options.improve)
        s.improve(out.steps, options, out);
    out.costS = s.cost(out.steps);
    out.moves = s.moves;
    out.linkEvaluations = s.evaluations;
    return out;
}

} // namespace pf::plan
