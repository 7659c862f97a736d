// The order search's local moves on a cell order; each applied move strictly lowers the cost.
#pragma once

#include "core/plan/sweep/order_cost.h"

namespace pf::plan::order_search {

class OrderMoves : public OrderCost {
public:
    using OrderCost::OrderCost;

    // Each returns true if it changed `seq` (see the definitions for what each move tries).
    bool twoOpt(std::vector<OrderStep>& seq);
    bool orOpt(std::vector<OrderStep>& seq);
    bool twoOptNear(std::vector<OrderStep>& seq, int budget);
    bool orOptNear(std::vector<OrderStep>& seq, int budget);
    bool orOptWithWays(std::vector<OrderStep>& seq);
    bool bestWays(std::vector<OrderStep>& seq, bool count = true);
    // The ways first, then moves until none pays or the options' rounds are used up.
    void improve(std::vector<OrderStep>& steps, const OrderOptions& options, OrderResult& out);

    int moves = 0;

private:
    void indexPoints(const std::vector<OrderStep>& seq, int from = 0, int to = -1);
    double removalGain(const std::vector<OrderStep>& seq, int i, int len, bool dearOnly);
    bool applyInsert(std::vector<OrderStep>& seq, int i, int len, int k, double removeGain, bool chooseWay);
    int stepOf(int point) const {
        return point >= 0 && point < static_cast<int>(m_stepOf.size()) ? m_stepOf[static_cast<std::size_t>(point)] : -1;
    }
    // A link worth removing: dearer than the caller's focus (a plain turn between lanes is not).
    bool dear(int u, int v) { return link(u, v) > m_focus; }

    std::vector<int> m_stepOf;
    double m_focus = -kInf;
};

} // namespace pf::plan::order_search
