// Shortest safe paths among the no-fly zones, optionally kept inside an area: a reduced visibility graph.
#pragma once

#include "core/geo/no_fly_field.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/types.h"
#include "core/result.h"

#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

namespace pf::geo {

struct VisibilityGraphOptions {
    // The zones are grown by the margin as polygons with this many segments per quarter circle, a
    // little larger than the margin so that their edges keep it; their convex corners are the graph's
    // nodes. Fewer segments: fewer corners on a path (each one a turn for the aircraft) and slightly
    // longer paths. >= 1.
    int quadrantSegments = 4;
    // When not empty, paths stay inside these polygons (their boundary included), e.g. the survey area.
    MultiPolygon keepInside;
    // Replace each nearly convex group of grown zones by a polygon of few corners around it (its convex
    // hull's sides, bevelled where sharper than a right angle; an octagon for round ones): paths bend
    // at a few corners instead of hugging a many-sided margin, each bend a turn for the aircraft.
    // Outside the grown zones is safe, so these corners are too.
    bool coarseCorners = false;
    // Precompute the shortest paths between all nodes (when there are at most maxAllPairsNodes): a
    // path between two points is then a look-up over their visible nodes, for planners asking many.
    bool allPairs = false;
    int maxAllPairsNodes = 600;
};

// The nodes are the convex corners of the grown zones (and the reflex corners of keepInside), the
// edges the free segments tangent to the obstacles at both ends (only those can be part of a shortest
// path): far fewer than all pairs, so building it stays fast with tens of zones. "Free" is the
// NoFlyField's exact safety (and containment in keepInside), the same test every stage uses.
class VisibilityGraph {
public:
    VisibilityGraph() = default;
    explicit VisibilityGraph(NoFlyField field, VisibilityGraphOptions options = {});
    // The same with the zones already grown by the margin and united exactly as this graph would do
    // it (another graph's inflatedZones() over the same field and quadrantSegments): spares the union.
    VisibilityGraph(NoFlyField field, VisibilityGraphOptions options, std::shared_ptr<const MultiPolygon> inflatedZones);

    const NoFlyField& field() const { return m_field; }
    // The zones grown by the graph's inflated margin (their union): what the nodes lie on.
    const MultiPolygon& inflatedZones() const { return m_inflated; }
    // The inflated margin: margin / cos(pi / (4 quadrantSegments)) + 5 cm.
    double inflatedMarginM() const { return m_inflatedMargin; }

    bool pointIsFree(const Vec2& p) const;
    bool segmentIsFree(const Vec2& a, const Vec2& b) const;

    // The nodes a shortest path from p may go to first: free segments from p tangent at the node.
    std::vector<int> visibleNodes(const Vec2& p) const;

    // Distances from one source to every node (Dijkstra), for many targets from one place.
    struct Tree {
        Vec2 source{0, 0};
        std::vector<double> dist; // per node; infinity when unreachable
        std::vector<int> prev;    // per node: previous node, -1 for the source
    };
    Tree tree(const Vec2& source) const;
    Tree tree(const Vec2& source, const std::vector<int>& sourceVisible) const;

    // Length of the shortest free path from the tree's source to target (infinity when none), and the
    // path's points strictly between them. targetVisible is visibleNodes(target), cached by the caller.
    double distance(const Tree& t, const Vec2& target, const std::vector<int>& targetVisible) const;
    std::vector<Vec2> path(const Tree& t, const Vec2& target, const std::vector<int>& targetVisible) const;

    // Between two points through the all-pairs table (false when it was not built): the length, and
    // the points strictly between them. aVisible, bVisible: visibleNodes(a), visibleNodes(b).
    bool hasAllPairs() const { return !m_pairDist.empty(); }
    double distance(const Vec2& a, const std::vector<int>& aVisible, const Vec2& b, const std::vector<int>& bVisible) const;
    std::vector<Vec2> path(const Vec2& a, const std::vector<int>& aVisible, const Vec2& b,
                           const std::vector<int>& bVisible) const;

    // distance() and path() in one for a segment ab already known not to be free: false when no way
    // exists, else the points strictly between a and b in `mid`.
    bool pathAround(const Tree& t, const Vec2& target, const std::vector<int>& targetVisible, std::vector<Vec2>& mid) const;
    bool pathAround(const Vec2& a, const std::vector<int>& aVisible, const Vec2& b, const std::vector<int>& bVisible,
                    std::vector<Vec2>& mid) const;

    // One query: the points strictly between a and b of the shortest free path (empty when the segment
    // is free). Errors: a or b not free, or no free way.
    Result<std::vector<Vec2>> shortestPath(const Vec2& a, const Vec2& b) const;

    std::size_t nodeCount() const { return m_nodes.size(); }
    std::size_t edgeCount() const;
    const Vec2& node(int i) const { return m_nodes[static_cast<std::size_t>(i)].p; }

private:
    struct Node {
        Vec2 p{0, 0};
        Vec2 prev{0, 0}, next{0, 0}; // ring neighbours, obstacle on the left of prev->p->next
        int obstacle = -1;           // index into m_obstacles
    };
    // A segment from `from` can bend round n only if it is tangent to n's obstacle there; from a point
    // inside that obstacle (coarse corners overlap the free space) any direction may be needed.
    bool tangentAt(const Node& n, const Vec2& from, const std::vector<char>* inside = nullptr) const;
    std::vector<char> obstaclesHolding(const Vec2& p) const;
    int bestLastNode(const Tree& t, const Vec2& target, const std::vector<int>& targetVisible, double* len) const;

    NoFlyField m_field;
    MultiPolygon m_keepInside;
    MultiPolygon m_inflated;
    double m_inflatedMargin = 0.0;
    std::vector<Polygon> m_obstacles; // the rings the nodes lie on (obstacle inside), for containment
    std::vector<Box> m_obstacleBoxes;
    std::vector<Node> m_nodes;
    std::vector<std::vector<std::pair<int, double>>> m_edges;
    std::vector<float> m_pairDist; // n x n, infinity when unreachable
    std::vector<int> m_pairNext;   // n x n: the node after i on the way from i to j
    double bestPair(const Vec2& a, const std::vector<int>& aVisible, const Vec2& b, const std::vector<int>& bVisible,
                    int* from, int* to) const;
};

} // namespace pf::geo
