// Point in polygon by the even-odd rule alone, for hot loops whose points never lie on a boundary.
#pragma once

#include "core/geo/types.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace pf::geo {

// True if p lies inside the ring by the even-odd rule (a point on the ring may go either way:
// geo::contains answers that case, at the cost of a distance scan).
inline bool insideEvenOdd(const Ring& r, const Vec2& p) {
    bool inside = false;
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
        if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
            p.x() < (r[j].x() - r[i].x()) * (p.y() - r[i].y()) / (r[j].y() - r[i].y()) + r[i].x())
            inside = !inside;
    return inside;
}

// The same over the outer ring and the holes.
inline bool insideEvenOdd(const Polygon& poly, const Vec2& p) {
    bool inside = insideEvenOdd(poly.outer, p);
    for (const auto& h : poly.holes)
        inside = inside != insideEvenOdd(h, p);
    return inside;
}

// insideEvenOdd for many points against one polygon (outer ring and holes): its edges are sorted
// into horizontal slabs, and a point looks only at the edges of its own slab (an edge can change
// the parity at p only when it spans p's height, and then it lies in p's slab). Each edge is tested
// with insideEvenOdd's expression, the same operands in the same order: the same answer bit for
// bit, in time that grows with the edges near p's height rather than with all of them (a subarea
// traced from grid cells has hundreds).
class EvenOddIndex {
public:
    EvenOddIndex() = default;
    explicit EvenOddIndex(const Polygon& poly) {
        std::vector<Edge> all;
        auto addRing = [&](const Ring& r) {
            for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
                all.push_back(Edge{r[i], r[j]});
        };
        addRing(poly.outer);
        for (const auto& h : poly.holes)
            addRing(h);
        if (all.empty())
            return;
        double lo = all.front().i.y(), hi = lo;
        for (const auto& e : all) {
            lo = std::min({lo, e.i.y(), e.j.y()});
            hi = std::max({hi, e.i.y(), e.j.y()});
        }
        m_y0 = lo;
        m_slabs = static_cast<int>(std::clamp<std::size_t>(all.size() / 2, 1, 4096));
        m_inv = hi > lo ? m_slabs / (hi - lo) : 0.0;
        m_start.assign(static_cast<std::size_t>(m_slabs) + 1, 0);
        for (const auto& e : all) {
            const auto [s0, s1] = slabs(e);
            for (int s = s0; s <= s1; ++s)
                ++m_start[static_cast<std::size_t>(s) + 1];
        }
        for (std::size_t s = 1; s < m_start.size(); ++s)
            m_start[s] += m_start[s - 1];
        m_edges.resize(m_start.back());
        std::vector<std::uint32_t> at(m_start.begin(), m_start.end() - 1);
        for (const auto& e : all) {
            const auto [s0, s1] = slabs(e);
            for (int s = s0; s <= s1; ++s)
                m_edges[at[static_cast<std::size_t>(s)]++] = e;
        }
    }

    bool inside(const Vec2& p) const {
        if (m_slabs == 0)
            return false;
        const std::size_t s = static_cast<std::size_t>(slab(p.y()));
        bool in = false;
        for (std::uint32_t k = m_start[s]; k < m_start[s + 1]; ++k) {
            const Edge& e = m_edges[k];
            if ((e.i.y() > p.y()) != (e.j.y() > p.y()) &&
                p.x() < (e.j.x() - e.i.x()) * (p.y() - e.i.y()) / (e.j.y() - e.i.y()) + e.i.x())
                in = !in;
        }
        return in;
    }

private:
    struct Edge {
        Vec2 i, j; // r[i] and r[j] of insideEvenOdd's loop (j the vertex before i)
    };
    // floor((y - y0) * inv) is monotone in y: an edge's slabs run from its lowest point's to its
    // highest's.
    int slab(double y) const {
        const double t = std::floor((y - m_y0) * m_inv);
        return t < 0 ? 0 : (t >= m_slabs - 1 ? m_slabs - 1 : static_cast<int>(t));
    }
    std::pair<int, int> slabs(const Edge& e) const {
        return {slab(std::min(e.i.y(), e.j.y())), slab(std::max(e.i.y(), e.j.y()))};
    }
    double m_y0 = 0.0, m_inv = 0.0;
    int m_slabs = 0;
    std::vector<std::uint32_t> m_start; // edges of slab s: [m_start[s], m_start[s + 1])
    std::vector<Edge> m_edges;
};

} // namespace pf::geo
