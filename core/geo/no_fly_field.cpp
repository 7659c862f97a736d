#include "core/geo/no_fly_field.h"

#include "core/geo/even_odd.h"
#include "core/geo/point_text.h"
#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <queue>
#include <string>

namespace pf::geo {

namespace {

using geo::Vec2;

inline double pointSegDist(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// How much farther than the margin from a segment's line an edge must lie for segmentIsSafe to skip
// its exact test: far above the rounding of the test, far below any distance that matters.
constexpr double kLineSlackM = 1e-4;

inline bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    return false; // touching or collinear cases give distance 0 through pointSegDist below
}

double segSegDist(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    if (segmentsIntersect(a, b, c, d))
        return 0.0;
    return std::min({pointSegDist(a, c, d), pointSegDist(b, c, d), pointSegDist(c, a, b), pointSegDist(d, a, b)});
}

template <class F> void forEachEdge(const geo::Polygon& poly, F f) {
    auto ring = [&](const geo::Ring& r) {
        for (std::size_t i = 0; i < r.size(); ++i)
            f(r[i], r[(i + 1) % r.size()]);
    };
    ring(poly.outer);
    for (const auto& h : poly.holes)
        ring(h);
}

double boxGap(const Vec2& amin, const Vec2& amax, const Vec2& bmin, const Vec2& bmax) {
    const double dx = std::max({0.0, bmin.x() - amax.x(), amin.x() - bmax.x()});
    const double dy = std::max({0.0, bmin.y() - amax.y(), amin.y() - bmax.y()});
    return std::hypot(dx, dy);
}

// True when two boxes are at least `need` apart (and apart at all): what boxGap >= need says, without
// a square root.
inline bool boxesApart(const Vec2& amin, const Vec2& amax, const Vec2& bmin, const Vec2& bmax, double need) {
    const double dx = std::max({0.0, bmin.x() - amax.x(), amin.x() - bmax.x()});
    const double dy = std::max({0.0, bmin.y() - amax.y(), amin.y() - bmax.y()});
    const double g2 = dx * dx + dy * dy;
    return g2 > 0.0 && g2 >= need * need;
}

// Squared distance from p to the segment ab.
inline double pointSegDist2(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).squaredNorm();
}

} // namespace

NoFlyField::NoFlyField(std::vector<geo::Polygon> zones, double marginM)
    : m_zones(std::move(zones)), m_margin(std::max(0.0, marginM)) {
    m_edgeBegin.push_back(0);
    for (const auto& z : m_zones) {
        const auto b = geo::bounds(z);
        m_boxes.emplace_back(b.min, b.max);
        m_circles.emplace_back(0.5 * (b.min + b.max), 0.5 * (b.max - b.min).norm());
        double reach = 0.0;
        forEachEdge(z, [&](const Vec2& c, const Vec2&) { reach = std::max(reach, (c - m_circles.back().first).norm()); });
        m_reach.push_back(reach);
        forEachEdge(z, [&](const Vec2& c, const Vec2& d) { m_edges.push_back(Edge{c, d, c.cwiseMin(d), c.cwiseMax(d)}); });
        m_edgeBegin.push_back(m_edges.size());
    }
}

NoFlyField NoFlyField::forCheck(std::vector<geo::Polygon> zones, double marginM) {
    NoFlyField f(std::move(zones), marginM);
    f.m_slack = 0.0;
    return f;
}

NoFlyField NoFlyField::ofGrownZones(std::vector<geo::Polygon> grown) {
    NoFlyField f(std::move(grown), 0.0);
    f.m_grown = true;
    return f;
}

double NoFlyField::clearance(const Vec2& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m_zones.size(); ++i) {
        if (boxGap(p, p, m_boxes[i].first, m_boxes[i].second) >= best)
            continue;
        if (geo::contains(m_zones[i], p))
            return 0.0;
        best = std::min(best, geo::distanceToBoundary(m_zones[i], p));
    }
    return best;
}

double NoFlyField::clearance(const Vec2& a, const Vec2& b) const {
    double best = std::numeric_limits<double>::infinity();
    const Vec2 smin = a.cwiseMin(b), smax = a.cwiseMax(b);
    for (std::size_t i = 0; i < m_zones.size(); ++i) {
        if (boxGap(smin, smax, m_boxes[i].first, m_boxes[i].second) >= best)
            continue;
        if (geo::contains(m_zones[i], a) || geo::contains(m_zones[i], b))
            return 0.0;
        forEachEdge(m_zones[i], [&](const Vec2& c, const Vec2& d) { best = std::min(best, segSegDist(a, b, c, d)); });
        if (best == 0.0)
            return 0.0;
    }
    return best;
}

bool NoFlyField::pointIsSafe(const Vec2& p) const {
    if (m_grown) {
        for (std::size_t i = 0; i < m_zones.size(); ++i) {
            if (!geo::Box{m_boxes[i].first, m_boxes[i].second}.contains(p))
                continue;
            if (geo::contains(m_zones[i], p) && geo::distanceToBoundary(m_zones[i], p) > kGrownBoundaryM)
                return false;
        }
        return true;
    }
    const double need = std::max(0.0, minClearance());
    for (std::size_t i = 0; i < m_zones.size(); ++i) {
        if (boxesApart(p, p, m_boxes[i].first, m_boxes[i].second, need))
            continue; // the whole zone lies at least `need` away
        // Far enough from the boundary, p is inside exactly when the even-odd rule says so.
        const double d = geo::distanceToBoundary(m_zones[i], p);
        if (!isSafeClearance(d) || geo::insideEvenOdd(m_zones[i], p))
            return false;
    }
    return true;
}

bool NoFlyField::segmentIsSafe(const Vec2& a, const Vec2& b) const {
    const double need = std::max(0.0, minClearance());
    const Vec2 smin = a.cwiseMin(b), smax = a.cwiseMax(b);
    if (m_grown) {
        const geo::Box sb{smin, smax};
        for (std::size_t i = 0; i < m_zones.size(); ++i)
            if (geo::Box{m_boxes[i].first, m_boxes[i].second}.intersects(sb) &&
                geo::segmentCrossesInterior(m_zones[i], a, b))
                return false;
        return true;
    }
    // An edge with both ends on one side of the segment's line, farther from it than `need` by
    // kLineSlackM, is far enough from the segment (every point of the segment lies on that line), so
    // each of the four distances below would pass: the test is skipped. The slack dwarfs the rounding
    // of the cross products (~1e-9 m at 10^6 m from the origin), so the answer stays the exact test's.
    // The cross products are the ones segmentsIntersect computes.
    const Vec2 ab = b - a;
    const double abLength = ab.norm();
    const double lineNeed = (need + kLineSlackM) * abLength;
    for (std::size_t i = 0; i < m_zones.size(); ++i) {
        if (boxesApart(smin, smax, m_boxes[i].first, m_boxes[i].second, need))
            continue;
        // A long diagonal segment's box overlaps many zones' boxes; the distance to a circle around
        // the zone prunes them.
        const double reach = m_circles[i].second + need;
        if (pointSegDist2(m_circles[i].first, a, b) > reach * reach)
            continue;
        // A zone wholly beyond the margin (and the slack) from the segment's line, by its farthest
        // vertex from the centre (round zones fill their box's circle only to 1 / sqrt 2): each edge
        // would pass the line test below, and a, on the line, lies outside the zone.
        const double side = cross(ab, m_circles[i].first - a);
        const double zoneNeed = lineNeed + m_reach[i] * abLength;
        if (side > zoneNeed || side < -zoneNeed)
            continue;
        for (std::size_t k = m_edgeBegin[i]; k < m_edgeBegin[i + 1]; ++k) {
            const Edge& e = m_edges[k];
            // An edge whose box lies at least `need` beyond the segment's box is far enough.
            if (boxesApart(smin, smax, e.lo, e.hi, need))
                continue;
            const double d1 = cross(ab, e.c - a), d2 = cross(ab, e.d - a);
            if ((d1 > lineNeed && d2 > lineNeed) || (d1 < -lineNeed && d2 < -lineNeed))
                continue;
            // isSafeClearance(segSegDist(a, b, c, d)): safe when clear of each of the four end-to-segment
            // distances, so the first one too close settles it.
            if (segmentsIntersect(a, b, e.c, e.d) || !isSafeClearance(pointSegDist(a, e.c, e.d)) ||
                !isSafeClearance(pointSegDist(b, e.c, e.d)) || !isSafeClearance(pointSegDist(e.c, a, b)) ||
                !isSafeClearance(pointSegDist(e.d, a, b)))
                return false;
        }
        // Clear of every edge by the margin: the segment lies wholly inside or wholly outside.
        if (geo::insideEvenOdd(m_zones[i], a))
            return false;
    }
    return true;
}

// ---------------------------------------------------------------------------------------------

SafePathFinder::SafePathFinder(NoFlyField field) : m_field(std::move(field)) {
    if (m_field.empty())
        return;
    // 4 segments per quarter circle: each chord spans 22.5 degrees, so a buffer of
    // margin / cos(11.25 deg) keeps its chords at least `margin` away; 5 cm more absorbs rounding.
    const double r = m_field.marginM() / std::cos(M_PI / 16.0) + 0.05;
    geo::MultiPolygon buffered;
    for (const auto& z : m_field.zones())
        for (auto& b : geo::buffer(z, r, 4))
            buffered.push_back(std::move(b));
    m_inflated = geo::unite(buffered);
    for (const auto& poly : m_inflated) {
        auto add = [&](const geo::Ring& ring) {
            for (const auto& v : ring)
                if (m_field.pointIsSafe(v))
                    m_nodes.push_back(v);
        };
        add(poly.outer);
        for (const auto& h : poly.holes)
            add(h);
    }
    m_edges.assign(m_nodes.size(), {});
    for (std::size_t i = 0; i < m_nodes.size(); ++i)
        for (std::size_t j = i + 1; j < m_nodes.size(); ++j)
            if (m_field.segmentIsSafe(m_nodes[i], m_nodes[j])) {
                const double d = (m_nodes[i] - m_nodes[j]).norm();
                m_edges[i].emplace_back(static_cast<int>(j), d);
                m_edges[j].emplace_back(static_cast<int>(i), d);
            }
}

Vec2 SafePathFinder::nearestSafePoint(const Vec2& p) const {
    if (m_field.pointIsSafe(p))
        return p;
    const Vec2 q = nearestOnBoundary(m_inflated, p);
    if (m_field.pointIsSafe(q))
        return q;
    Vec2 best = q;
    double bestD = std::numeric_limits<double>::infinity();
    for (const auto& n : m_nodes)
        if ((n - p).squaredNorm() < bestD) {
            bestD = (n - p).squaredNorm();
            best = n;
        }
    return best;
}

Result<std::vector<Vec2>> SafePathFinder::detour(const Vec2& a, const Vec2& b) const {
    const std::string margin = fixedText(m_field.marginM());
    if (!m_field.pointIsSafe(a))
        return makeError(ErrorCode::NoPath, "The point " + pointText(a) + " lies within the " + margin +
                                                " m safety margin of a no-fly zone.");
    if (!m_field.pointIsSafe(b))
        return makeError(ErrorCode::NoPath, "The point " + pointText(b) + " lies within the " + margin +
                                                " m safety margin of a no-fly zone.");
    if (m_field.segmentIsSafe(a, b))
        return std::vector<Vec2>{};
    // Dijkstra over the nodes plus a (index n) and b (index n + 1).
    const int n = static_cast<int>(m_nodes.size());
    std::vector<double> dist(static_cast<std::size_t>(n + 2), std::numeric_limits<double>::infinity());
    std::vector<int> prev(static_cast<std::size_t>(n + 2), -1);
    std::vector<char> visibleFromB(static_cast<std::size_t>(n), 0);
    for (int i = 0; i < n; ++i)
        visibleFromB[static_cast<std::size_t>(i)] = m_field.segmentIsSafe(m_nodes[static_cast<std::size_t>(i)], b);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
    dist[static_cast<std::size_t>(n)] = 0;
    q.emplace(0.0, n);
    while (!q.empty()) {
        // Plain variables, not a structured binding: the lambda below captures them, which C++17
        // allows only for variables (clang rejects captured bindings; GCC accepts them as an extension).
        const double d = q.top().first;
        const int u = q.top().second;
        q.pop();
        if (d > dist[static_cast<std::size_t>(u)])
            continue;
        if (u == n + 1)
            break;
        auto relax = [&](int v, double w) {
            if (d + w < dist[static_cast<std::size_t>(v)]) {
                dist[static_cast<std::size_t>(v)] = d + w;
                prev[static_cast<std::size_t>(v)] = u;
                q.emplace(d + w, v);
            }
        };
        if (u == n) {
            for (int i = 0; i < n; ++i)
                if (m_field.segmentIsSafe(a, m_nodes[static_cast<std::size_t>(i)]))
                    relax(i, (a - m_nodes[static_cast<std::size_t>(i)]).norm());
            continue;
        }
        for (const auto& [v, w] : m_edges[static_cast<std::size_t>(u)])
            relax(v, w);
        if (visibleFromB[static_cast<std::size_t>(u)])
            relax(n + 1, (m_nodes[static_cast<std::size_t>(u)] - b).norm());
    }
    if (prev[static_cast<std::size_t>(n + 1)] < 0)
        return makeError(ErrorCode::NoPath, "No safe way from " + pointText(a) + " to " + pointText(b) +
                                                " keeps the " + margin + " m margin around the no-fly zones.");
    std::vector<Vec2> path;
    for (int v = prev[static_cast<std::size_t>(n + 1)]; v != n; v = prev[static_cast<std::size_t>(v)])
        path.push_back(m_nodes[static_cast<std::size_t>(v)]);
    std::reverse(path.begin(), path.end());
    return path;
}

} // namespace pf::geo
