#include "core/plan/cell_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>

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

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kGainEps = 1e-7;
constexpr int kNone = -1; // the take-off or landing side of a link
// Or-opt with every way re-chosen costs n^3 ways: only for a handful of cells (larger plans gain
// nothing from it that the lane-level search does not find).
constexpr int kWaysSearchCells = 12;

class Search {
public:
    explicit Search(const OrderProblem& p) : m_p(p) {}

    // u == kNone: from the take-off; v == kNone: to the landing.
    double link(int u, int v) {
        if (u == kNone && v == kNone)
            return 0.0;
        if (u == kNone)
            return m_p.start ? m_p.start(v) : 0.0;
        if (v == kNone)
            return m_p.finish ? m_p.finish(u) : 0.0;
        const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(u, v))) << 32) |
                                  static_cast<std::uint32_t>(std::max(u, v));
        auto it = m_cache.find(key);
        if (it != m_cache.end())
            return it->second;
        ++evaluations;
        const double c = m_p.link(u, v);
        m_cache.emplace(key, c);
        return c;
    }
    double bound(int u, int v) {
        if (u == kNone || v == kNone)
            return link(u, v);
        if (!m_p.lowerBound)
            return 0.0;
        const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(u, v))) << 32) |
                                  static_cast<std::uint32_t>(std::max(u, v));
        auto it = m_cache.find(key);
        return it != m_cache.end() ? it->second : m_p.lowerBound(u, v);
    }
    double wayCost(const OrderStep& s) const {
        return m_p.cells[static_cast<std::size_t>(s.cell)].ways[static_cast<std::size_t>(s.way)].costS;
    }
    int entry(const OrderStep& s) const { return s.entry(m_p); }
    int exit(const OrderStep& s) const { return s.exit(m_p); }

    double cost(const std::vector<OrderStep>& steps) {
        if (steps.empty())
            return link(kNone, kNone);
        double c = link(kNone, entry(steps.front())) + link(exit(steps.back()), kNone);
        for (std::size_t i = 0; i < steps.size(); ++i) {
            c += wayCost(steps[i]);
            if (i + 1 < steps.size())
                c += link(exit(steps[i]), entry(steps[i + 1]));
        }
        return c;
    }

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

    // Reverse seq[i..j] (each cell flown the other way round): only the two outer links change.
    bool twoOpt(std::vector<OrderStep>& seq) {
        const int n = static_cast<int>(seq.size());
        bool any = false;
        for (int i = 0; i < n; ++i) {
            const int before = i > 0 ? exit(seq[static_cast<std::size_t>(i - 1)]) : kNone;
            for (int j = i + 1; j < n; ++j) {
                const int after = j + 1 < n ? entry(seq[static_cast<std::size_t>(j + 1)]) : kNone;
                const int ei = entry(seq[static_cast<std::size_t>(i)]), xj = exit(seq[static_cast<std::size_t>(j)]);
                const double old = link(before, ei) + link(xj, after);
                if (old - (bound(before, xj) + bound(ei, after)) <= kGainEps)
                    continue;
                const double now = link(before, xj) + link(ei, after);
                if (old - now > kGainEps) {
                    std::reverse(seq.begin() + i, seq.begin() + j + 1);
                    for (int k = i; k <= j; ++k)
                        seq[static_cast<std::size_t>(k)].reversed = !seq[static_cast<std::size_t>(k)].reversed;
                    ++moves;
                    any = true;
                    return any; // the neighbourhood changed: restart the pass
                }
            }
        }
        return any;
    }

    // Move seq[i, i + len) between two other neighbours, either way round.
    bool orOpt(std::vector<OrderStep>& seq) {
        const int n = static_cast<int>(seq.size());
        for (int len = 1; len <= 3; ++len)
            for (int i = 0; i + len <= n; ++i) {
                const int last = i + len - 1;
                const int prev = i > 0 ? exit(seq[static_cast<std::size_t>(i - 1)]) : kNone;
                const int next = last + 1 < n ? entry(seq[static_cast<std::size_t>(last + 1)]) : kNone;
                const int bi = entry(seq[static_cast<std::size_t>(i)]), bx = exit(seq[static_cast<std::size_t>(last)]);
                const double removed = link(prev, bi) + link(bx, next);
                if (removed - bound(prev, next) <= kGainEps)
                    continue;
                const double removeGain = removed - link(prev, next);
                if (removeGain <= kGainEps)
                    continue;
                // insert between k and k + 1 (k = -1: at the front), k outside [i - 1, last]
                for (int k = -1; k < n; ++k) {
                    if (k >= i - 1 && k <= last)
                        continue;
                    const int a = k >= 0 ? exit(seq[static_cast<std::size_t>(k)]) : kNone;
                    const int b = k + 1 < n ? entry(seq[static_cast<std::size_t>(k + 1)]) : kNone;
                    const double ab = link(a, b);
                    // a single cell may also change its way where it lands
                    const OrderStep moved = seq[static_cast<std::size_t>(i)];
                    const int ways = len == 1 ? static_cast<int>(m_p.cells[static_cast<std::size_t>(moved.cell)].ways.size()) : 1;
                    for (int c = 0; c < 2 * ways; ++c) {
                        const int r = c % 2;
                        OrderStep as = moved;
                        if (len == 1) {
                            as.way = c / 2;
                            as.reversed = r == 1;
                        }
                        const int in = len == 1 ? entry(as) : (r ? bx : bi), out = len == 1 ? exit(as) : (r ? bi : bx);
                        const double wayDelta = len == 1 ? wayCost(as) - wayCost(moved) : 0.0;
                        if (removeGain - wayDelta - (bound(a, in) + bound(out, b) - ab) <= kGainEps)
                            continue;
                        const double add = link(a, in) + link(out, b) - ab;
                        if (removeGain - wayDelta - add <= kGainEps)
                            continue;
                        std::vector<OrderStep> block(seq.begin() + i, seq.begin() + i + len);
                        if (len == 1) {
                            block[0] = as;
                        } else if (r) {
                            std::reverse(block.begin(), block.end());
                            for (auto& s : block)
                                s.reversed = !s.reversed;
                        }
                        std::vector<OrderStep> out2;
                        out2.reserve(seq.size());
                        if (k == -1)
                            out2.insert(out2.end(), block.begin(), block.end());
                        for (int t = 0; t < n; ++t) {
                            if (t >= i && t <= last)
                                continue;
                            out2.push_back(seq[static_cast<std::size_t>(t)]);
                            if (t == k)
                                out2.insert(out2.end(), block.begin(), block.end());
                        }
                        seq = std::move(out2);
                        ++moves;
                        return true;
                    }
                }
            }
        return false;
    }

    // Where each end point sits in the sequence (step index), for the neighbour-list moves.
    void indexPoints(const std::vector<OrderStep>& seq, int from = 0, int to = -1) {
        if (to < 0)
            to = static_cast<int>(seq.size()) - 1;
        for (int i = from; i <= to; ++i) {
            for (const auto& w : m_p.cells[static_cast<std::size_t>(seq[static_cast<std::size_t>(i)].cell)].ways) {
                for (int pt : {w.a, w.b}) {
                    if (pt >= static_cast<int>(m_stepOf.size()))
                        m_stepOf.resize(static_cast<std::size_t>(pt) + 1, -1);
                    m_stepOf[static_cast<std::size_t>(pt)] = i;
                }
            }
        }
    }
    int stepOf(int point) const {
        return point >= 0 && point < static_cast<int>(m_stepOf.size()) ? m_stepOf[static_cast<std::size_t>(point)] : -1;
    }
    // A link worth removing: dearer than the caller's focus (a plain turn between lanes is not).
    bool dear(int u, int v) { return link(u, v) > m_focus; }

    // 2-opt restricted to reversals that join near end points; one pass, moves applied as found.
    bool twoOptNear(std::vector<OrderStep>& seq, int budget) {
        const int n = static_cast<int>(seq.size());
        indexPoints(seq);
        bool any = false;
        auto tryReverse = [&](int i, int j) { // reverse [i, j], 0 <= i < j < n
            if (i < 0 || j >= n || i >= j)
                return false;
            const int before = i > 0 ? exit(seq[static_cast<std::size_t>(i - 1)]) : kNone;
            const int after = j + 1 < n ? entry(seq[static_cast<std::size_t>(j + 1)]) : kNone;
            const int ei = entry(seq[static_cast<std::size_t>(i)]), xj = exit(seq[static_cast<std::size_t>(j)]);
            const double old = link(before, ei) + link(xj, after);
            if (old - (bound(before, xj) + bound(ei, after)) <= kGainEps)
                return false;
            const double now = link(before, xj) + link(ei, after);
            if (old - now <= kGainEps)
                return false;
            std::reverse(seq.begin() + i, seq.begin() + j + 1);
            for (int k = i; k <= j; ++k)
                seq[static_cast<std::size_t>(k)].reversed = !seq[static_cast<std::size_t>(k)].reversed;
            indexPoints(seq, i, j);
            ++moves;
            return true;
        };
        for (int i = 0; i < n && moves < budget; ++i) {
            const int prevExit = i > 0 ? exit(seq[static_cast<std::size_t>(i - 1)]) : kNone;
            const int nextEntry = i + 1 < n ? entry(seq[static_cast<std::size_t>(i + 1)]) : kNone;
            const bool dearBefore = dear(prevExit, entry(seq[static_cast<std::size_t>(i)]));
            const bool dearAfter = dear(exit(seq[static_cast<std::size_t>(i)]), nextEntry);
            if (!dearBefore && !dearAfter)
                continue;
            for (int end = 0; end < 2; ++end) {
                const int p = end ? exit(seq[static_cast<std::size_t>(i)]) : entry(seq[static_cast<std::size_t>(i)]);
                const std::vector<int> cand = m_p.near(p);
                for (int q : cand) {
                    const int j = stepOf(q);
                    if (j < 0 || j == i)
                        continue;
                    const int lo = std::min(i, j), hi = std::max(i, j);
                    if (tryReverse(lo + 1, hi) || tryReverse(lo, hi - 1)) {
                        any = true;
                        break;
                    }
                }
            }
        }
        return any;
    }

    // Or-opt restricted to insertions next to a near end point; one pass.
    bool orOptNear(std::vector<OrderStep>& seq, int budget) {
        indexPoints(seq);
        bool any = false;
        for (int len = 1; len <= 3; ++len)
            for (int i = 0; i + len <= static_cast<int>(seq.size()) && moves < budget; ++i) {
                const int n = static_cast<int>(seq.size());
                const int last = i + len - 1;
                const int prev = i > 0 ? exit(seq[static_cast<std::size_t>(i - 1)]) : kNone;
                const int next = last + 1 < n ? entry(seq[static_cast<std::size_t>(last + 1)]) : kNone;
                const int bi = entry(seq[static_cast<std::size_t>(i)]), bx = exit(seq[static_cast<std::size_t>(last)]);
                if (!dear(prev, bi) && !dear(bx, next))
                    continue;
                const double removed = link(prev, bi) + link(bx, next);
                if (removed - bound(prev, next) <= kGainEps)
                    continue;
                const double removeGain = removed - link(prev, next);
                if (removeGain <= kGainEps)
                    continue;
                bool moved = false;
                for (int endp : {bi, bx}) {
                    const std::vector<int> cand = m_p.near(endp);
                    for (int q : cand) {
                        const int j = stepOf(q);
                        if (j < 0 || (j >= i && j <= last))
                            continue;
                        for (int k : {j - 1, j}) {
                            if (k >= i - 1 && k <= last)
                                continue;
                            if (applyInsert(seq, i, len, k, removeGain)) {
                                // everything between the block's old and new places moved
                                indexPoints(seq, std::max(0, std::min(i, k + 1)), std::min(n - 1, std::max(last, k)));
                                moved = true;
                                break;
                            }
                        }
                        if (moved)
                            break;
                    }
                    if (moved)
                        break;
                }
                any = any || moved;
            }
        return any;
    }

    // Moves seq[i, i + len) between k and k + 1 (either way round) if that gains more than it costs.
    bool applyInsert(std::vector<OrderStep>& seq, int i, int len, int k, double removeGain) {
        const int n = static_cast<int>(seq.size());
        const int last = i + len - 1;
        const int bi = entry(seq[static_cast<std::size_t>(i)]), bx = exit(seq[static_cast<std::size_t>(last)]);
        const int a = k >= 0 ? exit(seq[static_cast<std::size_t>(k)]) : kNone;
        const int b = k + 1 < n ? entry(seq[static_cast<std::size_t>(k + 1)]) : kNone;
        const double ab = link(a, b);
        for (int r = 0; r < 2; ++r) {
            const int in = r ? bx : bi, out = r ? bi : bx;
            if (removeGain - (bound(a, in) + bound(out, b) - ab) <= kGainEps)
                continue;
            const double add = link(a, in) + link(out, b) - ab;
            if (removeGain - add <= kGainEps)
                continue;
            std::vector<OrderStep> block(seq.begin() + i, seq.begin() + i + len);
            if (r) {
                std::reverse(block.begin(), block.end());
                for (auto& s : block)
                    s.reversed = !s.reversed;
            }
            std::vector<OrderStep> out2;
            out2.reserve(seq.size());
            if (k == -1)
                out2.insert(out2.end(), block.begin(), block.end());
            for (int t = 0; t < n; ++t) {
                if (t >= i && t <= last)
                    continue;
                out2.push_back(seq[static_cast<std::size_t>(t)]);
                if (t == k)
                    out2.insert(out2.end(), block.begin(), block.end());
            }
            seq = std::move(out2);
            ++moves;
            return true;
        }
        return false;
    }

    // Or-opt judged with the best ways of the whole sequence after the move (a move may pay only once
    // its neighbours change their way too): for problems of cells, not of thousands of lanes.
    bool orOptWithWays(std::vector<OrderStep>& seq) {
        const int n = static_cast<int>(seq.size());
        if (n > kWaysSearchCells)
            return false;
        double cur = cost(seq);
        for (int len = 1; len <= 2; ++len)
            for (int i = 0; i + len <= n; ++i)
                for (int k = -1; k < n; ++k) {
                    const int last = i + len - 1;
                    if (k >= i - 1 && k <= last)
                        continue;
                    std::vector<OrderStep> block(seq.begin() + i, seq.begin() + i + len), cand;
                    cand.reserve(seq.size());
                    if (k == -1)
                        cand.insert(cand.end(), block.begin(), block.end());
                    for (int t = 0; t < n; ++t) {
                        if (t >= i && t <= last)
                            continue;
                        cand.push_back(seq[static_cast<std::size_t>(t)]);
                        if (t == k)
                            cand.insert(cand.end(), block.begin(), block.end());
                    }
                    bestWays(cand, false);
                    const double c = cost(cand);
                    if (c < cur - kGainEps) {
                        seq = std::move(cand);
                        ++moves;
                        return true;
                    }
                }
        return false;
    }

    // The best way and direction for every cell, given the order: a shortest path over the choices.
    bool bestWays(std::vector<OrderStep>& seq, bool count = true) {
        const std::size_t n = seq.size();
        if (n == 0)
            return false;
        std::vector<std::vector<OrderStep>> opts(n);
        for (std::size_t i = 0; i < n; ++i) {
            const auto& ways = m_p.cells[static_cast<std::size_t>(seq[i].cell)].ways;
            for (std::size_t w = 0; w < ways.size(); ++w)
                for (int r = 0; r < 2; ++r)
                    opts[i].push_back(OrderStep{seq[i].cell, static_cast<int>(w), r == 1});
        }
        std::vector<std::vector<double>> best(n);
        std::vector<std::vector<int>> from(n);
        for (std::size_t i = 0; i < n; ++i) {
            best[i].assign(opts[i].size(), kInf);
            from[i].assign(opts[i].size(), -1);
            for (std::size_t k = 0; k < opts[i].size(); ++k) {
                const double own = wayCost(opts[i][k]);
                if (i == 0) {
                    best[i][k] = link(kNone, entry(opts[i][k])) + own;
                    continue;
                }
                for (std::size_t j = 0; j < opts[i - 1].size(); ++j) {
                    const double v = best[i - 1][j] + link(exit(opts[i - 1][j]), entry(opts[i][k])) + own;
                    if (v < best[i][k]) {
                        best[i][k] = v;
                        from[i][k] = static_cast<int>(j);
                    }
                }
            }
        }
        double total = kInf;
        int k = 0;
        for (std::size_t j = 0; j < opts[n - 1].size(); ++j) {
            const double v = best[n - 1][j] + link(exit(opts[n - 1][j]), kNone);
            if (v < total) {
                total = v;
                k = static_cast<int>(j);
            }
        }
        if (!(total < cost(seq) - kGainEps))
            return false;
        for (std::size_t i = n; i-- > 0;) {
            seq[i] = opts[i][static_cast<std::size_t>(k)];
            k = from[i][static_cast<std::size_t>(k)];
        }
        if (count)
            ++moves;
        return true;
    }

    void improve(std::vector<OrderStep>& steps, const OrderOptions& options, OrderResult& out) {
        // The ways first (cheap and always useful), then moves until none pays. Every move strictly
        // improves, so the search ends; the budget bounds pathological cases.
        const bool near = static_cast<bool>(m_p.near);
        const int n = static_cast<int>(steps.size());
        const int budget = moves + 50 * n + 200;
        m_focus = options.focusAboveS;
        if (!near)
            bestWays(steps);
        for (out.rounds = 0; out.rounds < options.maxRounds; ++out.rounds) {
            bool changed = false;
            if (near) {
                changed = twoOptNear(steps, budget) || changed;
                changed = orOptNear(steps, budget) || changed;
            }
            while (!near && moves < budget && twoOpt(steps))
                changed = true;
            while (!near && moves < budget && orOpt(steps))
                changed = true;
            if (!near && bestWays(steps))
                changed = true;
            while (!near && !changed && moves < budget && orOptWithWays(steps))
                changed = true;
            if (!changed)
                break;
        }
    }

    std::int64_t evaluations = 0;
    int moves = 0;

private:
    const OrderProblem& m_p;
    std::unordered_map<std::uint64_t, double> m_cache;
    std::vector<int> m_stepOf;
    double m_focus = -kInf;
};

} // namespace

double orderCost(const OrderProblem& problem, const std::vector<OrderStep>& steps) {
    Search s(problem);
    return s.cost(steps);
}

OrderResult orderCells(const OrderProblem& problem, const OrderOptions& options) {
    OrderResult out;
    const std::size_t n = problem.cells.size();
    Search s(problem);
    if (n == 0) {
        out.costS = out.constructedCostS = s.cost({});
        return out;
    }
    // First cells: the cheapest to begin with from the take-off; when the start is free (all equal),
    // cells spread over the decomposition's order (from one side of the area to the other).
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
    double bestC = kInf;
    for (const auto& f : tries) {
        auto seq = s.nearestNeighbour(f);
        const double c = s.cost(seq);
        if (c < bestC) {
            bestC = c;
            out.steps = std::move(seq);
        }
    }
    if (problem.sweepOrder.size() == n) {
        for (int dir = 0; dir < 2; ++dir) {
            std::vector<OrderStep> seq;
            for (std::size_t k = 0; k < n; ++k)
                seq.push_back(OrderStep{problem.sweepOrder[dir ? n - 1 - k : k], 0, false});
            s.bestWays(seq);
            const double c = s.cost(seq);
            if (c < bestC) {
                bestC = c;
                out.steps = std::move(seq);
            }
        }
    }
    out.constructedCostS = bestC;
    if (options.improve) {
        s.improve(out.steps, options, out);
        if (!problem.near && n >= 4) {
            // Iterated local search: a double bridge (A B C D -> A C B D) and a flipped way or two,
            // then the local search; kept when the whole flies faster.
            std::mt19937 rng(12345);
            double cur = s.cost(out.steps);
            for (int k = 0; k < options.kicks; ++k) {
                std::vector<OrderStep> t = out.steps;
                std::uniform_int_distribution<std::size_t> cut(1, n - 1);
                std::size_t c1 = cut(rng), c2 = cut(rng), c3 = cut(rng);
                if (c1 > c2)
                    std::swap(c1, c2);
                if (c2 > c3)
                    std::swap(c2, c3);
                if (c1 > c2)
                    std::swap(c1, c2);
                std::vector<OrderStep> k2(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(c1));
                k2.insert(k2.end(), t.begin() + static_cast<std::ptrdiff_t>(c2), t.begin() + static_cast<std::ptrdiff_t>(c3));
                k2.insert(k2.end(), t.begin() + static_cast<std::ptrdiff_t>(c1), t.begin() + static_cast<std::ptrdiff_t>(c2));
                k2.insert(k2.end(), t.begin() + static_cast<std::ptrdiff_t>(c3), t.end());
                std::uniform_int_distribution<std::size_t> any(0, n - 1);
                k2[any(rng)].reversed ^= true;
                OrderResult scratch;
                s.improve(k2, options, scratch);
                const double c = s.cost(k2);
                if (c < cur - kGainEps) {
                    cur = c;
                    out.steps = std::move(k2);
                }
            }
        }
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
    out.constructedCostS = s.cost(out.steps);
    if (options.improve)
        s.improve(out.steps, options, out);
    out.costS = s.cost(out.steps);
    out.moves = s.moves;
    out.linkEvaluations = s.evaluations;
    return out;
}

} // namespace pf::plan
