// Buckets of bounding boxes on a square lattice, for neighbourhood queries: each id is kept in every
// lattice square its box touches; a query returns the ids (sorted, each once) whose squares its box
// touches, a superset of those whose boxes intersect it.
#pragma once

#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace pf::geo {

class BoxBuckets {
public:
    explicit BoxBuckets(double size) : m_size(size) {}
    void insert(int id, const Box& b) {
        forCells(b, [&](long long key) { m_map[key].push_back(id); });
    }
    std::vector<int> query(const Box& b) const {
        std::vector<int> out;
        forCells(b, [&](long long key) {
            auto it = m_map.find(key);
            if (it != m_map.end())
                out.insert(out.end(), it->second.begin(), it->second.end());
        });
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }

private:
    template <class F> void forCells(const Box& b, F f) const {
        const long long x0 = static_cast<long long>(std::floor(b.min.x() / m_size));
        const long long x1 = static_cast<long long>(std::floor(b.max.x() / m_size));
        const long long y0 = static_cast<long long>(std::floor(b.min.y() / m_size));
        const long long y1 = static_cast<long long>(std::floor(b.max.y() / m_size));
        for (long long y = y0; y <= y1; ++y)
            for (long long x = x0; x <= x1; ++x)
                f(y * 2'000'003LL + x);
    }
    double m_size;
    std::unordered_map<long long, std::vector<int>> m_map;
};

} // namespace pf::geo
