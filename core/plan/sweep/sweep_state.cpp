#include "core/plan/sweep/sweep_state.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pf::plan::sweep_detail {

std::vector<OrderStep> rowOrders(const OrderProblem& lanes, const std::vector<std::pair<int, int>>& laneRef,
                                 const std::vector<PlannedCell>& cells, const SweepFrame& frame, double spacing) {
    struct Key {
        double y, x;
        int id;
    };
    std::vector<Key> keys;
    keys.reserve(laneRef.size());
    for (std::size_t id = 0; id < laneRef.size(); ++id) {
        const auto& [ci, j] = laneRef[id];
        const CellLane& l = cells[static_cast<std::size_t>(ci)].lanes[static_cast<std::size_t>(j)];
        keys.push_back(Key{l.y, frame.toFrame(0.5 * (l.span.first + l.span.last)).x(), static_cast<int>(id)});
    }
    if (keys.empty())
        return {};
    std::stable_sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.y < b.y; });
    std::vector<std::vector<Key>> rows;
    for (const auto& k : keys) {
        if (rows.empty() || k.y - rows.back().front().y >= 0.5 * spacing)
            rows.emplace_back();
        rows.back().push_back(k);
    }
    for (auto& r : rows)
        std::stable_sort(r.begin(), r.end(), [](const Key& a, const Key& b) { return a.x < b.x; });
    std::vector<OrderStep> best;
    double bestCost = std::numeric_limits<double>::infinity();
    for (int variant = 0; variant < 4; ++variant) {
        const bool upwards = variant < 2, firstLtr = variant % 2 == 0;
        std::vector<OrderStep> seq;
        seq.reserve(keys.size());
        for (std::size_t k = 0; k < rows.size(); ++k) {
            const auto& row = rows[upwards ? k : rows.size() - 1 - k];
            const bool ltr = (k % 2 == 0) == firstLtr;
            for (std::size_t i = 0; i < row.size(); ++i)
                seq.push_back(OrderStep{row[ltr ? i : row.size() - 1 - i].id, 0, !ltr});
        }
        const double c = orderCost(lanes, seq);
        if (c < bestCost) {
            bestCost = c;
            best = std::move(seq);
        }
    }
    return best;
}

} // namespace pf::plan::sweep_detail
