// A map from an unordered pair of end points to a value (a cost, an index): open addressing in one
// flat array, for the order search, which looks up link costs for every candidate move, and the
// sweep's router, which keeps every transition it worked out.
#pragma once

#include <cstdint>
#include <vector>

namespace pf::plan {

template <class Value> class PairMap {
public:
    // The key of the pair (u, v), the same for (v, u). u, v >= 0.
    static std::uint64_t key(int u, int v) {
        const int lo = u < v ? u : v, hi = u < v ? v : u;
        return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(lo)) << 32) |
               static_cast<std::uint32_t>(hi);
    }
    // The value kept for the key, or nullptr.
    const Value* find(std::uint64_t k) const {
        if (m_slots.empty())
            return nullptr;
        for (std::size_t i = slot(k);; i = (i + 1) & m_mask) {
            const Slot& s = m_slots[i];
            if (s.key == k)
                return &s.value;
            if (s.key == kEmpty)
                return nullptr;
        }
    }
    // Keeps the value of a key not yet kept.
    void insert(std::uint64_t k, Value value) {
        if (2 * (m_size + 1) > m_slots.size())
            grow();
        for (std::size_t i = slot(k);; i = (i + 1) & m_mask) {
            Slot& s = m_slots[i];
            if (s.key == kEmpty) {
                s.key = k;
                s.value = value;
                ++m_size;
                return;
            }
        }
    }
    std::size_t size() const { return m_size; }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    struct Slot {
        std::uint64_t key = kEmpty;
        Value value{};
    };
    std::size_t slot(std::uint64_t k) const {
        // Fibonacci hashing: the high bits of the product spread consecutive ids over the table.
        return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> m_shift) & m_mask;
    }
    void grow() {
        std::vector<Slot> old = std::move(m_slots);
        std::size_t n = old.empty() ? 1024 : 2 * old.size();
        m_slots.assign(n, Slot{});
        m_mask = n - 1;
        int bits = 0;
        while ((std::size_t{1} << bits) < n)
            ++bits;
        m_shift = 64 - bits;
        m_size = 0;
        for (const Slot& s : old)
            if (s.key != kEmpty)
                insert(s.key, s.value);
    }
    std::vector<Slot> m_slots;
    std::size_t m_mask = 0;
    int m_shift = 64;
    std::size_t m_size = 0;
};

using PairCostCache = PairMap<double>;

} // namespace pf::plan
