// The sweep's transitions: safe ways between lane ends (and home and landing) on visibility graphs
// of the grown zones, timed by the one flight-time model and cached per pair, and the nearest lane
// ends of each end for the order search's neighbour lists. Internal to the sweep planner.
#pragma once

#include "core/geo/no_fly_field.h"
#include "core/geo/types.h"
#include "core/geo/visibility_graph.h"
#include "core/plan/flight_time.h"
#include "core/plan/sweep/pair_cache.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace pf::plan::sweep_detail {

using geo::Vec2;

// The cost of a transition no safe path makes: large enough that the order never chooses one.
constexpr double kNoWayS = 1e7;

// The angle between two directions, degrees in [0, 180]; 0 when either is zero.
double angleDeg(const Vec2& u, const Vec2& v);
// The same with the directions' lengths known (u.norm(), v.norm()).
double angleDeg(const Vec2& u, double nu, const Vec2& v, double nv);

// Time of a transition by the one model: straight legs from a through mid to b, a turn at every
// vertex. `arrive` is the direction the aircraft arrives at a with, `leave` the one it leaves b with
// (zero: at rest there, no turn).
double transitionTime(const FlightTimeModel& m, const Vec2& a, const Vec2& arrive, const std::vector<Vec2>& mid,
                      const Vec2& b, const Vec2& leave);

// A place a lane starts or ends at: a lane starting here flies along `in`, one ending here arrives
// along -in. Home and landing have in = 0 (at rest).
struct EndPoint {
    Vec2 p{0, 0};
    Vec2 in{0, 0};
};

struct Route {
    std::vector<Vec2> mid; // from the lower id to the higher
    double timeS = 0.0;
    bool ok = true;
    bool leavesArea = false;
};

// A visibility graph built the first time a transition needs it (the detailed ones seldom are).
class LazyGraph {
public:
    explicit LazyGraph(const geo::VisibilityGraph& built) : m_built(&built) {}
    // inflatedZones: see geo::VisibilityGraph (optional).
    LazyGraph(const geo::NoFlyField& field, geo::VisibilityGraphOptions options,
              std::shared_ptr<const geo::MultiPolygon> inflatedZones = nullptr)
        : m_field(field), m_options(std::move(options)), m_inflatedZones(std::move(inflatedZones)) {}
    const geo::VisibilityGraph& get() const {
        if (m_built)
            return *m_built;
        if (!m_own)
            m_own = std::make_unique<geo::VisibilityGraph>(m_field, m_options, m_inflatedZones);
        return *m_own;
    }

private:
    const geo::VisibilityGraph* m_built = nullptr;
    geo::NoFlyField m_field;
    geo::VisibilityGraphOptions m_options;
    std::shared_ptr<const geo::MultiPolygon> m_inflatedZones;
    mutable std::unique_ptr<geo::VisibilityGraph> m_own;
};

// The graphs a transition may take, in order of preference: over the area (when kept inside), with
// coarse corners (few turns), then the detailed margins (a lane end in a narrow notch between two
// merged margins sees no coarse corner), then outside the area when no way over it exists.
struct RouteGraph {
    const LazyGraph* graph = nullptr;
    bool leavesArea = false;
};

// Safe transitions between end points: straight when free, else the first graph's shortest path that
// exists. Trees and visible nodes are cached per end point and graph, routes per pair.
class Router {
public:
    Router(const FlightTimeModel& model, std::vector<RouteGraph> graphs)
        : m_model(model), m_graphs(std::move(graphs)), m_caches(m_graphs.size()) {}

    int add(const EndPoint& e) {
        m_pts.push_back(e);
        m_inNorm.push_back(e.in.norm());
        return static_cast<int>(m_pts.size()) - 1;
    }
    const EndPoint& point(int i) const { return m_pts[static_cast<std::size_t>(i)]; }
    std::size_t size() const { return m_pts.size(); }

    // From u (arriving along -in_u) to v (leaving along in_v); mid in that order.
    Route route(int u, int v) {
        Route r = cached(u, v);
        if (u > v)
            std::reverse(r.mid.begin(), r.mid.end());
        return r;
    }
    // route(u, v).timeS without copying the way: what the order search asks for every link (from
    // the pair map's slot, without touching the route).
    double timeS(int u, int v) { return entry(u, v).timeS; }

    double lowerBound(int u, int v) const {
        const auto& a = point(u);
        const auto& b = point(v);
        // |-in| is |in|: the lengths kept at add() spare the order search two roots per bound.
        return (a.p - b.p).norm() / m_model.speedMps +
               angleDeg(-a.in, m_inNorm[static_cast<std::size_t>(u)], b.in, m_inNorm[static_cast<std::size_t>(v)]) /
                   m_model.turnRateDegS;
    }

private:
    struct Entry {
        double timeS = 0.0;
        std::size_t at = 0; // index into m_routes
    };
    const Entry& entry(int u, int v) {
        const std::uint64_t key = PairMap<Entry>::key(u, v);
        if (const Entry* e = m_routeAt.find(key))
            return *e;
        m_routes.push_back(compute(std::min(u, v), std::max(u, v)));
        m_routeAt.insert(key, Entry{m_routes.back().timeS, m_routes.size() - 1});
        return *m_routeAt.find(key);
    }
    const Route& cached(int u, int v) { return m_routes[entry(u, v).at]; }
    // Per end point id (the ids are dense): its visible nodes and its tree, once computed.
    struct Cache {
        std::vector<std::unique_ptr<const std::vector<int>>> visible;
        std::vector<std::unique_ptr<const geo::VisibilityGraph::Tree>> trees;
    };
    const std::vector<int>& visible(const geo::VisibilityGraph& g, Cache& c, int i) {
        const auto k = static_cast<std::size_t>(i);
        if (k >= c.visible.size())
            c.visible.resize(m_pts.size());
        if (!c.visible[k])
            c.visible[k] = std::make_unique<const std::vector<int>>(g.visibleNodes(point(i).p));
        return *c.visible[k];
    }
    const geo::VisibilityGraph::Tree& tree(const geo::VisibilityGraph& g, Cache& c, int i) {
        const auto k = static_cast<std::size_t>(i);
        if (k >= c.trees.size())
            c.trees.resize(m_pts.size());
        if (!c.trees[k])
            c.trees[k] = std::make_unique<const geo::VisibilityGraph::Tree>(g.tree(point(i).p, visible(g, c, i)));
        return *c.trees[k];
    }
    // The shortest free way on graph g, or false. An end point that sees no node has no way round
    // (the straight segment is not free): the other end's nodes are not needed then.
    bool via(const geo::VisibilityGraph& g, Cache& c, int u, int v, std::vector<Vec2>& mid) {
        const Vec2 &a = point(u).p, &b = point(v).p;
        if (g.segmentIsFree(a, b)) {
            mid.clear();
            return true;
        }
        const std::vector<int>& fromU = visible(g, c, u);
        if (fromU.empty())
            return false;
        const std::vector<int>& toV = visible(g, c, v);
        if (toV.empty())
            return false;
        if (g.hasAllPairs())
            return g.pathAround(a, fromU, b, toV, mid);
        // Search from the end point with the larger tree cache hit chance: the lower id (cells' order).
        const auto& t = tree(g, c, u);
        return g.pathAround(t, b, toV, mid);
    }
    Route compute(int u, int v) {
        Route r;
        const auto &a = point(u), &b = point(v);
        for (std::size_t k = 0; k < m_graphs.size(); ++k) {
            if (via(m_graphs[k].graph->get(), m_caches[k], u, v, r.mid)) {
                r.leavesArea = m_graphs[k].leavesArea;
                r.timeS = transitionTime(m_model, a.p, -a.in, r.mid, b.p, b.in);
                return r;
            }
        }
        r.ok = false;
        r.mid.clear();
        r.timeS = kNoWayS;
        return r;
    }

    FlightTimeModel m_model;
    std::vector<RouteGraph> m_graphs;
    std::vector<Cache> m_caches;
    std::vector<EndPoint> m_pts;
    std::vector<double> m_inNorm; // per end point: in.norm()
    std::vector<Route> m_routes;           // in the order first asked
    PairMap<Entry> m_routeAt;              // pair of end points -> its time and index into m_routes
};

// For each of `pts` (end point ids of the router), the k nearest others of `pts`, on a grid of cell h.
std::vector<std::vector<int>> nearestEndPoints(const Router& router, const std::vector<int>& pts, int k, double h);

} // namespace pf::plan::sweep_detail
