// The cost of a cell order for the order search: cached link costs, lower bounds, a sequence's total.
#pragma once

#include "core/plan/sweep/cell_order.h"
#include "core/plan/sweep/pair_cache.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace pf::plan::order_search {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kGainEps = 1e-7;
constexpr int kNone = -1; // the take-off or landing side of a link

// Every exact link cost is asked of the problem once and kept; the lower bound is used where no exact
// cost is known yet. Inline: the search calls these for every candidate move.
class OrderCost {
public:
    explicit OrderCost(const OrderProblem& p) : m_p(p) {}

    // u == kNone: from the take-off; v == kNone: to the landing.
    double link(int u, int v) {
        if (u == kNone && v == kNone)
            return 0.0;
        if (u == kNone)
            return m_p.start ? m_p.start(v) : 0.0;
        if (v == kNone)
            return m_p.finish ? m_p.finish(u) : 0.0;
        const std::uint64_t key = PairCostCache::key(u, v);
        if (const double* known = m_cache.find(key))
            return *known;
        ++evaluations;
        const double c = m_p.link(u, v);
        m_cache.insert(key, c);
        return c;
    }
    double bound(int u, int v) {
        if (u == kNone || v == kNone)
            return link(u, v);
        if (!m_p.lowerBound)
            return 0.0;
        const double* known = m_cache.find(PairCostCache::key(u, v));
        return known ? *known : m_p.lowerBound(u, v);
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

    std::int64_t evaluations = 0;

protected:
    const OrderProblem& m_p;
    PairCostCache m_cache;
};

} // namespace pf::plan::order_search
