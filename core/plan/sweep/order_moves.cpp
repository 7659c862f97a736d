// The order search's local moves (2-opt, or-opt, their near-point variants, the best ways) and the
// improvement loop that applies them until none pays.
#include "core/plan/sweep/order_moves.h"

#include <algorithm>
#include <cmath>

namespace pf::plan::order_search {

namespace {

// Or-opt with every way re-chosen costs n^3 ways: only for a handful of cells (larger plans gain
// nothing from it that the lane-level search does not find).
constexpr int kWaysSearchCells = 12;

// seq with the block seq[i, i + len) taken out and `block` put between k and k + 1 (k = -1: at the
// front), k outside [i - 1, i + len - 1].
std::vector<OrderStep> withBlockMoved(const std::vector<OrderStep>& seq, int i, int len, int k,
                                      const std::vector<OrderStep>& block) {
    const int n = static_cast<int>(seq.size());
    const int last = i + len - 1;
    std::vector<OrderStep> out;
    out.reserve(seq.size());
    if (k == -1)
        out.insert(out.end(), block.begin(), block.end());
    for (int t = 0; t < n; ++t) {
        if (t >= i && t <= last)
            continue;
        out.push_back(seq[static_cast<std::size_t>(t)]);
        if (t == k)
            out.insert(out.end(), block.begin(), block.end());
    }
    return out;
}

} // namespace

// Reverse seq[i..j] (each cell flown the other way round): only the two outer links change.
bool OrderMoves::twoOpt(std::vector<OrderStep>& seq) {
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

// What taking seq[i, i + len) out gains (its two links replaced by one), or 0 when that cannot pay
// for any insertion; with `dearOnly`, also 0 unless one of its links is dear.
double OrderMoves::removalGain(const std::vector<OrderStep>& seq, int i, int len, bool dearOnly) {
    const int n = static_cast<int>(seq.size());
    const int last = i + len - 1;
    const int prev = i > 0 ? exit(seq[static_cast<std::size_t>(i - 1)]) : kNone;
    const int next = last + 1 < n ? entry(seq[static_cast<std::size_t>(last + 1)]) : kNone;
    const int bi = entry(seq[static_cast<std::size_t>(i)]), bx = exit(seq[static_cast<std::size_t>(last)]);
    if (dearOnly && !dear(prev, bi) && !dear(bx, next))
        return 0.0;
    const double removed = link(prev, bi) + link(bx, next);
    if (removed - bound(prev, next) <= kGainEps)
        return 0.0;
    const double gain = removed - link(prev, next);
    return gain > kGainEps ? gain : 0.0;
}

// Move seq[i, i + len) between two other neighbours, either way round.
bool OrderMoves::orOpt(std::vector<OrderStep>& seq) {
    const int n = static_cast<int>(seq.size());
    for (int len = 1; len <= 3; ++len)
        for (int i = 0; i + len <= n; ++i) {
            const int last = i + len - 1;
            const double removeGain = removalGain(seq, i, len, false);
            if (removeGain <= kGainEps)
                continue;
            // insert between k and k + 1 (k = -1: at the front), k outside [i - 1, last]
            for (int k = -1; k < n; ++k)
                if (!(k >= i - 1 && k <= last) && applyInsert(seq, i, len, k, removeGain, true))
                    return true;
        }
    return false;
}

// Where each end point sits in the sequence (step index), for the neighbour-list moves.
void OrderMoves::indexPoints(const std::vector<OrderStep>& seq, int from, int to) {
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

// 2-opt restricted to reversals that join near end points; one pass, moves applied as found.
bool OrderMoves::twoOptNear(std::vector<OrderStep>& seq, int budget) {
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
            const std::vector<int>& cand = m_p.near(p);
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
bool OrderMoves::orOptNear(std::vector<OrderStep>& seq, int budget) {
    indexPoints(seq);
    bool any = false;
    for (int len = 1; len <= 3; ++len)
        for (int i = 0; i + len <= static_cast<int>(seq.size()) && moves < budget; ++i) {
            const int n = static_cast<int>(seq.size());
            const int last = i + len - 1;
            const double removeGain = removalGain(seq, i, len, true);
            if (removeGain <= kGainEps)
                continue;
            const int bi = entry(seq[static_cast<std::size_t>(i)]), bx = exit(seq[static_cast<std::size_t>(last)]);
            bool moved = false;
            for (int endp : {bi, bx}) {
                const std::vector<int>& cand = m_p.near(endp);
                for (int q : cand) {
                    const int j = stepOf(q);
                    if (j < 0 || (j >= i && j <= last))
                        continue;
                    for (int k : {j - 1, j}) {
                        if (k >= i - 1 && k <= last)
                            continue;
                        if (applyInsert(seq, i, len, k, removeGain, false)) {
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

// Moves seq[i, i + len) between k and k + 1 if that gains more than it costs: the block as it is,
// then reversed; with `chooseWay`, a single cell tries every way in both directions instead (it may
// change its way where it lands).
bool OrderMoves::applyInsert(std::vector<OrderStep>& seq, int i, int len, int k, double removeGain, bool chooseWay) {
    const int n = static_cast<int>(seq.size());
    const int last = i + len - 1;
    const int bi = entry(seq[static_cast<std::size_t>(i)]), bx = exit(seq[static_cast<std::size_t>(last)]);
    const int a = k >= 0 ? exit(seq[static_cast<std::size_t>(k)]) : kNone;
    const int b = k + 1 < n ? entry(seq[static_cast<std::size_t>(k + 1)]) : kNone;
    const double ab = link(a, b);
    const OrderStep moved = seq[static_cast<std::size_t>(i)];
    const bool single = chooseWay && len == 1;
    const int ways = single ? static_cast<int>(m_p.cells[static_cast<std::size_t>(moved.cell)].ways.size()) : 1;
    for (int c = 0; c < 2 * ways; ++c) {
        const int r = c % 2;
        OrderStep as = moved;
        if (single) {
            as.way = c / 2;
            as.reversed = r == 1;
        }
        const int in = single ? entry(as) : (r ? bx : bi), out = single ? exit(as) : (r ? bi : bx);
        const double wayDelta = single ? wayCost(as) - wayCost(moved) : 0.0;
        if (removeGain - wayDelta - (bound(a, in) + bound(out, b) - ab) <= kGainEps)
            continue;
        const double add = link(a, in) + link(out, b) - ab;
        if (removeGain - wayDelta - add <= kGainEps)
            continue;
        std::vector<OrderStep> block(seq.begin() + i, seq.begin() + i + len);
        if (single) {
            block[0] = as;
        } else if (r) {
            std::reverse(block.begin(), block.end());
            for (auto& s : block)
                s.reversed = !s.reversed;
        }
        seq = withBlockMoved(seq, i, len, k, block);
        ++moves;
        return true;
    }
    return false;
}

// Or-opt judged with the best ways of the whole sequence after the move (a move may pay only once
// its neighbours change their way too): for problems of cells, not of thousands of lanes.
bool OrderMoves::orOptWithWays(std::vector<OrderStep>& seq) {
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
                std::vector<OrderStep> cand =
                    withBlockMoved(seq, i, len, k, std::vector<OrderStep>(seq.begin() + i, seq.begin() + i + len));
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
bool OrderMoves::bestWays(std::vector<OrderStep>& seq, bool count) {
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

void OrderMoves::improve(std::vector<OrderStep>& steps, const OrderOptions& options, OrderResult& out) {
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

} // namespace pf::plan::order_search
