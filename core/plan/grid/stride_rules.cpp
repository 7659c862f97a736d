// The paper's stride rules: the limits of a cell and the growth of a stride under rules (1)-(3).
#include "core/plan/grid/stride_rules.h"

namespace pf::plan {

using grid::Dir;
using grid::Grid;

namespace detail {

StrideStop growStride(const Grid& g, const std::vector<std::uint8_t>& visited, int c0, int d, std::vector<int>& out,
                      bool full) {
    out.clear();
    if (blocked(g, visited, c0, d))
        return StrideStop::None;
    const int off = dirOffset(g, d);
    const unsigned m0 = limitsOf(g, visited, c0, d);
    int cl = c0 + off;
    out.push_back(cl);
    for (;;) {
        if (blocked(g, visited, cl, d))
            return StrideStop::AreaLimit;
        const int cn = cl + off;
        if (!full && popcount2(limitsOf(g, visited, cl, d)) != 2) {
            const unsigned mn = limitsOf(g, visited, cn, d);
            if (mn == 0)
                return StrideStop::NoLimit;
            if (popcount2(mn) != popcount2(m0))
                return StrideStop::LimitCountDiffers;
            if (mn != m0) // both have one limit, on opposite sides
                return StrideStop::LimitOppositeSide;
        }
        out.push_back(cn);
        cl = cn;
    }
}

} // namespace detail

using detail::growStride;
using detail::limitsOf;

unsigned strideLimits(const Grid& g, const std::vector<std::uint8_t>& visited, int c, Dir d) {
    return limitsOf(g, visited, c, static_cast<int>(d));
}

Stride buildStride(const Grid& g, const std::vector<std::uint8_t>& visited, int c0, Dir d) {
    Stride s;
    s.dir = d;
    s.stop = growStride(g, visited, c0, static_cast<int>(d), s.cells);
    return s;
}

} // namespace pf::plan
