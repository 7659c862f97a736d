#include "core/geo/visibility_graph.h"

#include "core/geo/even_odd.h"
#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <queue>
#include <string>

namespace pf::geo {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

std::string where(const Vec2& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.1f, %.1f) m", p.x(), p.y());
    return buf;
}

// True when the segment ab stays inside (or on the boundary of) the polygons: every piece of it
// between two boundary crossings has its midpoint inside.
// aInside, bInside: contains(polys, a) and contains(polys, b), when the caller knows them.
bool segmentInside(const MultiPolygon& polys, const Vec2& a, const Vec2& b, int aInside = -1, int bInside = -1) {
    if (!(aInside >= 0 ? aInside == 1 : contains(polys, a)) || !(bInside >= 0 ? bInside == 1 : contains(polys, b)))
        return false;
    std::vector<double> ts{0.0, 1.0};
    const Vec2 d = b - a;
    auto addRing = [&](const Ring& ring) {
        const std::size_t n = ring.size();
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2& p = ring[i];
            const Vec2 e = ring[(i + 1) % n] - p;
            const double den = cross(d, e);
            if (std::abs(den) < 1e-15)
                continue;
            const Vec2 ap = p - a;
            const double t = cross(ap, e) / den;
            const double u = cross(ap, d) / den;
            if (t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0)
                ts.push_back(t);
        }
    };
    const Vec2 smin = a.cwiseMin(b), smax = a.cwiseMax(b);
    for (const auto& poly : polys) {
        const Box bb = bounds(poly);
        if (bb.max.x() < smin.x() || bb.min.x() > smax.x() || bb.max.y() < smin.y() || bb.min.y() > smax.y())
            continue;
        addRing(poly.outer);
        for (const auto& h : poly.holes)
            addRing(h);
    }
    if (ts.size() == 2)
        return contains(polys, a + 0.5 * d);
    std::sort(ts.begin(), ts.end());
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
        if (ts[i + 1] - ts[i] < 1e-12)
            continue;
        if (!contains(polys, a + 0.5 * (ts[i] + ts[i + 1]) * d))
            return false;
    }
    return true;
}

} // namespace

namespace {

// Convex hull, counter-clockwise (Andrew's monotone chain).
Ring convexHull(std::vector<Vec2> pts) {
    std::sort(pts.begin(), pts.end(), [](const Vec2& a, const Vec2& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3)
        return pts;
    Ring h(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 1]) <= 0)
            --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 1]) <= 0)
            --k;
        h[k++] = pts[i];
    }
    h.resize(k - 1);
    return h;
}

// The polygon {x : n.x <= h(n) + r} over a few outward normals n of the convex hull (h: its support
// function): the hull's own sides when it has few, else eight directions from its longest side, with
// bevels wherever consecutive normals turn by more than a right angle. Every point of its boundary
// lies at least r from the hull. Counter-clockwise.
Ring circumscribed(const Ring& hull, double r) {
    const std::size_t n = hull.size();
    std::vector<double> angles;
    double longest = -1, base = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 d = hull[(i + 1) % n] - hull[i];
        const double a = std::atan2(-d.x(), d.y()); // outward normal (d.y, -d.x) of a CCW ring
        angles.push_back(a);
        if (d.norm() > longest) {
            longest = d.norm();
            base = a;
        }
    }
    if (n > 8) {
        angles.clear();
        for (int k = 0; k < 8; ++k)
            angles.push_back(base + k * M_PI / 4);
    }
    for (auto& a : angles) {
        a = std::fmod(a - base, 2 * M_PI);
        if (a < 0)
            a += 2 * M_PI;
    }
    std::sort(angles.begin(), angles.end());
    std::vector<double> full;
    for (std::size_t i = 0; i < angles.size(); ++i) {
        const double a = angles[i], b = i + 1 < angles.size() ? angles[i + 1] : angles.front() + 2 * M_PI;
        full.push_back(a);
        const int extra = static_cast<int>(std::ceil((b - a) / (M_PI / 2) - 1e-9)) - 1;
        for (int k = 1; k <= extra; ++k)
            full.push_back(a + (b - a) * k / (extra + 1));
    }
    std::vector<Vec2> normals;
    std::vector<double> support;
    for (double a : full) {
        const Vec2 nv(std::cos(a + base), std::sin(a + base));
        double h = -kInf;
        for (const auto& p : hull)
            h = std::max(h, nv.dot(p));
        normals.push_back(nv);
        support.push_back(h + r);
    }
    Ring out;
    for (std::size_t i = 0; i < normals.size(); ++i) {
        const std::size_t j = (i + 1) % normals.size();
        const Vec2 &a = normals[i], &b = normals[j];
        const double det = a.x() * b.y() - a.y() * b.x();
        if (std::abs(det) < 1e-12)
            continue;
        out.emplace_back((support[i] * b.y() - support[j] * a.y()) / det, (a.x() * support[j] - b.x() * support[i]) / det);
    }
    return out;
}

} // namespace

VisibilityGraph::VisibilityGraph(NoFlyField field, VisibilityGraphOptions options)
    : VisibilityGraph(std::move(field), std::move(options), nullptr) {}

VisibilityGraph::VisibilityGraph(NoFlyField field, VisibilityGraphOptions options,
                                 std::shared_ptr<const MultiPolygon> inflatedZones)
    : m_field(std::move(field)), m_keepInside(std::move(options.keepInside)) {
    const int q = std::max(1, options.quadrantSegments);
    std::vector<Node> candidates;
    // A ring whose obstacle lies on the left of its direction: its left turns are the obstacle's convex
    // corners, the only places where a shortest path bends.
    auto addRing = [&](Ring ring, bool obstacleInside, int obstacle) {
        const std::size_t n = ring.size();
        if (n < 3)
            return;
        // Counter-clockwise has the inside on the left.
        if ((signedArea(ring) > 0) != obstacleInside)
            std::reverse(ring.begin(), ring.end());
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2& u = ring[(i + n - 1) % n];
            const Vec2& v = ring[i];
            const Vec2& w = ring[(i + 1) % n];
            if (cross(v - u, w - v) > 1e-12)
                candidates.push_back(Node{v, u, w, obstacle});
        }
    };
    auto addObstacle = [&](const Ring& ring) {
        m_obstacles.push_back(Polygon{ring, {}});
        m_obstacleBoxes.push_back(bounds(ring));
        addRing(ring, true, static_cast<int>(m_obstacles.size()) - 1);
    };
    if (!m_field.empty()) {
        // Chords of a circle of radius r with q segments per quarter stay r cos(pi / 4q) from its centre.
        m_inflatedMargin = m_field.marginM() / std::cos(M_PI / (4.0 * q)) + 0.05;
        if (inflatedZones) {
            m_inflated = *inflatedZones;
        } else {
            MultiPolygon grown;
            for (const auto& z : m_field.zones())
                for (auto& b : buffer(z, m_inflatedMargin, q))
                    grown.push_back(std::move(b));
            m_inflated = unite(grown);
        }
        for (const auto& poly : m_inflated) {
            bool coarse = false;
            if (options.coarseCorners) {
                // The zones inside this grown piece, and how convex the piece is.
                std::vector<Vec2> pts;
                for (const auto& z : m_field.zones())
                    if (!z.outer.empty() && contains(poly, z.outer.front()))
                        pts.insert(pts.end(), z.outer.begin(), z.outer.end());
                const Ring hull = convexHull(pts);
                const Ring grownHull = convexHull(poly.outer);
                if (hull.size() >= 3 && area(Polygon{poly.outer, {}}) >= 0.85 * std::abs(signedArea(grownHull))) {
                    addObstacle(circumscribed(hull, m_inflatedMargin));
                    coarse = true;
                }
            }
            if (!coarse)
                addObstacle(poly.outer);
            for (const auto& h : poly.holes)
                addRing(h, false, -1);
        }
    }
    for (const auto& poly : m_keepInside) {
        addRing(poly.outer, false, -1);
        for (const auto& h : poly.holes)
            addRing(h, true, -1);
    }
    for (auto& c : candidates)
        if (pointIsFree(c.p))
            m_nodes.push_back(c);
    const std::size_t n = m_nodes.size();
    m_edges.assign(n, {});
    // The obstacles each node lies inside (coarse corners overlap): from there any direction may be
    // needed, not only tangents.
    std::vector<std::vector<int>> holding(n);
    for (std::size_t j = 0; j < n; ++j) {
        const std::vector<char> in = obstaclesHolding(m_nodes[j].p);
        for (std::size_t k = 0; k < in.size(); ++k)
            if (in[k])
                holding[j].push_back(static_cast<int>(k));
    }
    auto tangent = [&](const Node& at, std::size_t from) {
        if (tangentAt(at, m_nodes[from].p))
            return true;
        return at.obstacle >= 0 && std::find(holding[from].begin(), holding[from].end(), at.obstacle) != holding[from].end();
    };
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const Vec2& a = m_nodes[i].p;
            const Vec2& b = m_nodes[j].p;
            if (!tangent(m_nodes[i], j) || !tangent(m_nodes[j], i) || !segmentIsFree(a, b))
                continue;
            const double d = (a - b).norm();
            m_edges[i].emplace_back(static_cast<int>(j), d);
            m_edges[j].emplace_back(static_cast<int>(i), d);
        }
    if (options.allPairs && n > 0 && static_cast<int>(n) <= options.maxAllPairsNodes) {
        m_pairDist.assign(n * n, std::numeric_limits<float>::infinity());
        m_pairNext.assign(n * n, -1);
        for (std::size_t j = 0; j < n; ++j) {
            // Dijkstra towards j; next[i][j] is i's predecessor on the way back from j.
            const Tree t = tree(m_nodes[j].p, {static_cast<int>(j)});
            for (std::size_t i = 0; i < n; ++i) {
                m_pairDist[i * n + j] = static_cast<float>(t.dist[i]);
                m_pairNext[i * n + j] = i == j ? static_cast<int>(j) : t.prev[i];
            }
        }
    }
}

bool VisibilityGraph::tangentAt(const Node& n, const Vec2& from, const std::vector<char>* inside) const {
    if (inside && n.obstacle >= 0 && (*inside)[static_cast<std::size_t>(n.obstacle)])
        return true;
    const Vec2 d = n.p - from;
    const double su = cross(d, n.prev - n.p), sw = cross(d, n.next - n.p);
    return su * sw >= 0.0;
}

std::vector<char> VisibilityGraph::obstaclesHolding(const Vec2& p) const {
    std::vector<char> in(m_obstacles.size(), 0);
    for (std::size_t i = 0; i < m_obstacles.size(); ++i) {
        if (!m_obstacleBoxes[i].contains(p))
            continue;
        // on the boundary either answer does (a tangent there is a tangent either way)
        const bool inside = insideEvenOdd(m_obstacles[i].outer, p);
        in[i] = inside;
    }
    return in;
}

bool VisibilityGraph::pointIsFree(const Vec2& p) const {
    return m_field.pointIsSafe(p) && (m_keepInside.empty() || contains(m_keepInside, p));
}

bool VisibilityGraph::segmentIsFree(const Vec2& a, const Vec2& b) const {
    return m_field.segmentIsSafe(a, b) && (m_keepInside.empty() || segmentInside(m_keepInside, a, b));
}

std::size_t VisibilityGraph::edgeCount() const {
    std::size_t e = 0;
    for (const auto& l : m_edges)
        e += l.size();
    return e / 2;
}

std::vector<int> VisibilityGraph::visibleNodes(const Vec2& p) const {
    std::vector<int> out;
    const std::vector<char> inside = obstaclesHolding(p);
    // Every node lies in keepInside (see the constructor); whether p does is asked once.
    int pInside = -1;
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        if (!tangentAt(m_nodes[i], p, &inside) || !m_field.segmentIsSafe(p, m_nodes[i].p))
            continue;
        if (!m_keepInside.empty()) {
            if (pInside < 0)
                pInside = contains(m_keepInside, p) ? 1 : 0;
            if (!segmentInside(m_keepInside, p, m_nodes[i].p, pInside, 1))
                continue;
        }
        out.push_back(static_cast<int>(i));
    }
    return out;
}

VisibilityGraph::Tree VisibilityGraph::tree(const Vec2& source) const { return tree(source, visibleNodes(source)); }

VisibilityGraph::Tree VisibilityGraph::tree(const Vec2& source, const std::vector<int>& sourceVisible) const {
    Tree t;
    t.source = source;
    t.dist.assign(m_nodes.size(), kInf);
    t.prev.assign(m_nodes.size(), -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
    for (int v : sourceVisible) {
        const double d = (m_nodes[static_cast<std::size_t>(v)].p - source).norm();
        if (d < t.dist[static_cast<std::size_t>(v)]) {
            t.dist[static_cast<std::size_t>(v)] = d;
            q.emplace(d, v);
        }
    }
    while (!q.empty()) {
        const double d = q.top().first;
        const int u = q.top().second;
        q.pop();
        if (d > t.dist[static_cast<std::size_t>(u)])
            continue;
        for (const auto& [v, w] : m_edges[static_cast<std::size_t>(u)]) {
            if (d + w < t.dist[static_cast<std::size_t>(v)]) {
                t.dist[static_cast<std::size_t>(v)] = d + w;
                t.prev[static_cast<std::size_t>(v)] = u;
                q.emplace(d + w, v);
            }
        }
    }
    return t;
}

int VisibilityGraph::bestLastNode(const Tree& t, const Vec2& target, const std::vector<int>& targetVisible,
                                  double* len) const {
    int best = -1;
    double bestD = kInf;
    for (int v : targetVisible) {
        const double d = t.dist[static_cast<std::size_t>(v)] + (m_nodes[static_cast<std::size_t>(v)].p - target).norm();
        if (d < bestD) {
            bestD = d;
            best = v;
        }
    }
    *len = bestD;
    return best;
}

double VisibilityGraph::distance(const Tree& t, const Vec2& target, const std::vector<int>& targetVisible) const {
    if (segmentIsFree(t.source, target))
        return (target - t.source).norm();
    double len = kInf;
    bestLastNode(t, target, targetVisible, &len);
    return len;
}

std::vector<Vec2> VisibilityGraph::path(const Tree& t, const Vec2& target, const std::vector<int>& targetVisible) const {
    if (segmentIsFree(t.source, target))
        return {};
    double len = kInf;
    std::vector<Vec2> out;
    for (int v = bestLastNode(t, target, targetVisible, &len); v >= 0; v = t.prev[static_cast<std::size_t>(v)])
        out.push_back(m_nodes[static_cast<std::size_t>(v)].p);
    std::reverse(out.begin(), out.end());
    return out;
}

double VisibilityGraph::bestPair(const Vec2& a, const std::vector<int>& aVisible, const Vec2& b,
                                 const std::vector<int>& bVisible, int* from, int* to) const {
    const std::size_t n = m_nodes.size();
    double best = kInf;
    // The first legs' lengths once, not once per last node (the same values, summed in the same order).
    std::vector<double> head(aVisible.size());
    for (std::size_t k = 0; k < aVisible.size(); ++k)
        head[k] = (m_nodes[static_cast<std::size_t>(aVisible[k])].p - a).norm();
    for (int j : bVisible) {
        const double tail = (m_nodes[static_cast<std::size_t>(j)].p - b).norm();
        for (std::size_t k = 0; k < aVisible.size(); ++k) {
            const int i = aVisible[k];
            const double d = head[k] + m_pairDist[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(j)] + tail;
            if (d < best) {
                best = d;
                *from = i;
                *to = j;
            }
        }
    }
    return best;
}

double VisibilityGraph::distance(const Vec2& a, const std::vector<int>& aVisible, const Vec2& b,
                                 const std::vector<int>& bVisible) const {
    if (segmentIsFree(a, b))
        return (b - a).norm();
    int i = -1, j = -1;
    return bestPair(a, aVisible, b, bVisible, &i, &j);
}

std::vector<Vec2> VisibilityGraph::path(const Vec2& a, const std::vector<int>& aVisible, const Vec2& b,
                                        const std::vector<int>& bVisible) const {
    if (segmentIsFree(a, b))
        return {};
    int i = -1, j = -1;
    if (!std::isfinite(bestPair(a, aVisible, b, bVisible, &i, &j)))
        return {};
    const std::size_t n = m_nodes.size();
    std::vector<Vec2> out;
    for (int k = i; k >= 0; k = m_pairNext[static_cast<std::size_t>(k) * n + static_cast<std::size_t>(j)]) {
        out.push_back(m_nodes[static_cast<std::size_t>(k)].p);
        if (k == j || out.size() > n)
            break;
    }
    return out;
}

bool VisibilityGraph::pathAround(const Tree& t, const Vec2& target, const std::vector<int>& targetVisible,
                                 std::vector<Vec2>& mid) const {
    double len = kInf;
    const int last = bestLastNode(t, target, targetVisible, &len);
    if (!std::isfinite(len))
        return false;
    mid.clear();
    for (int v = last; v >= 0; v = t.prev[static_cast<std::size_t>(v)])
        mid.push_back(m_nodes[static_cast<std::size_t>(v)].p);
    std::reverse(mid.begin(), mid.end());
    return true;
}

bool VisibilityGraph::pathAround(const Vec2& a, const std::vector<int>& aVisible, const Vec2& b,
                                 const std::vector<int>& bVisible, std::vector<Vec2>& mid) const {
    int i = -1, j = -1;
    if (!std::isfinite(bestPair(a, aVisible, b, bVisible, &i, &j)))
        return false;
    const std::size_t n = m_nodes.size();
    mid.clear();
    for (int k = i; k >= 0; k = m_pairNext[static_cast<std::size_t>(k) * n + static_cast<std::size_t>(j)]) {
        mid.push_back(m_nodes[static_cast<std::size_t>(k)].p);
        if (k == j || mid.size() > n)
            break;
    }
    return true;
}

Result<std::vector<Vec2>> VisibilityGraph::shortestPath(const Vec2& a, const Vec2& b) const {
    for (const Vec2* p : {&a, &b})
        if (!pointIsFree(*p))
            return makeError(ErrorCode::NoPath, "The point " + where(*p) +
                                                    (m_field.pointIsSafe(*p) ? " lies outside the area."
                                                                             : " lies within the safety margin of a no-fly zone."));
    if (segmentIsFree(a, b))
        return std::vector<Vec2>{};
    const Tree t = tree(a);
    const std::vector<int> vis = visibleNodes(b);
    double len = kInf;
    bestLastNode(t, b, vis, &len);
    if (!std::isfinite(len))
        return makeError(ErrorCode::NoPath, "No safe way from " + where(a) + " to " + where(b) +
                                                " keeps the safety margin around the no-fly zones" +
                                                (m_keepInside.empty() ? "." : " inside the area."));
    return path(t, b, vis);
}

} // namespace pf::geo
