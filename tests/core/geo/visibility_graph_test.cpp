#include "core/geo/visibility_graph.h"

#include "core/geo/polygon_ops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pf;
using namespace pf::geo;

namespace {

Polygon square(double x0, double y0, double s) { return Polygon{{Vec2(x0, y0), Vec2(x0 + s, y0), Vec2(x0 + s, y0 + s), Vec2(x0, y0 + s)}, {}}; }

double length(const Vec2& a, const std::vector<Vec2>& mid, const Vec2& b) {
    double len = 0;
    Vec2 p = a;
    for (const auto& q : mid) {
        len += (q - p).norm();
        p = q;
    }
    return len + (b - p).norm();
}

void expectSafe(const VisibilityGraph& g, const Vec2& a, const std::vector<Vec2>& mid, const Vec2& b) {
    Vec2 p = a;
    for (const auto& q : mid) {
        EXPECT_TRUE(g.segmentIsFree(p, q));
        p = q;
    }
    EXPECT_TRUE(g.segmentIsFree(p, b));
}

} // namespace

// Round a square zone: within 3 % of the exact shortest path round its rounded margin (as the safe path
// finder), and with coarse corners bending at no more than two corners.
TEST(VisibilityGraph, ShortAndSafeRoundASquare) {
    const NoFlyField f({square(0, 0, 20)}, 5.0);
    const Vec2 a(-40, 10), b(60, 10);
    const VisibilityGraph fine(f);
    auto p = fine.shortestPath(a, b);
    ASSERT_TRUE(p.ok()) << p.error().message;
    expectSafe(fine, a, *p, b);
    // exact: tangent to the corner circle of radius 5 at (0, 20), its arc, the top, and mirrored
    const Vec2 c(0, 20);
    const double d = (c - a).norm(), tangent = std::sqrt(d * d - 25.0);
    double t = std::atan2(a.y() - c.y(), a.x() - c.x()) - std::acos(5.0 / d);
    while (t < 0)
        t += 2 * M_PI;
    const double exact = 2 * (tangent + 5.0 * (t - M_PI / 2)) + 20;
    EXPECT_GE(length(a, *p, b), exact - 1e-6);
    EXPECT_LE(length(a, *p, b), 1.03 * exact);
    VisibilityGraphOptions o;
    o.quadrantSegments = 2;
    o.coarseCorners = true;
    const VisibilityGraph coarse(f, o);
    auto q = coarse.shortestPath(a, b);
    ASSERT_TRUE(q.ok());
    expectSafe(coarse, a, *q, b);
    EXPECT_LE(q->size(), 2u);
    EXPECT_LE(length(a, *q, b), 1.15 * exact);
    EXPECT_LT(coarse.nodeCount(), fine.nodeCount());
}

// Kept inside an L-shaped area the path bends at its inner corner, never crossing outside.
TEST(VisibilityGraph, KeepInsideBendsAtTheInnerCorner) {
    Polygon l{{Vec2(0, 0), Vec2(100, 0), Vec2(100, 40), Vec2(40, 40), Vec2(40, 100), Vec2(0, 100)}, {}};
    VisibilityGraphOptions o;
    o.keepInside = {l};
    const VisibilityGraph g(NoFlyField{}, o);
    const Vec2 a(90, 20), b(20, 90);
    EXPECT_FALSE(g.segmentIsFree(a, b));
    auto p = g.shortestPath(a, b);
    ASSERT_TRUE(p.ok()) << p.error().message;
    ASSERT_EQ(p->size(), 1u);
    EXPECT_NEAR(((*p)[0] - Vec2(40, 40)).norm(), 0.0, 1e-9);
    auto out = g.shortestPath(Vec2(90, 90), a);
    ASSERT_FALSE(out.ok());
    EXPECT_NE(out.error().message.find("outside the area"), std::string::npos);
}

// The all-pairs table answers as the per-source search does, and every answer is safe.
TEST(VisibilityGraph, AllPairsAgreesWithTheSearch) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> pos(0, 400), side(10, 40);
    std::vector<Polygon> zones;
    for (int k = 0; k < 12; ++k)
        zones.push_back(square(pos(rng), pos(rng), side(rng)));
    VisibilityGraphOptions o;
    o.quadrantSegments = 2;
    o.coarseCorners = true;
    o.allPairs = true;
    const VisibilityGraph g(NoFlyField(zones, 5.0), o);
    ASSERT_TRUE(g.hasAllPairs());
    int compared = 0;
    for (int k = 0; k < 200; ++k) {
        const Vec2 a(pos(rng), pos(rng)), b(pos(rng), pos(rng));
        if (!g.pointIsFree(a) || !g.pointIsFree(b))
            continue;
        const auto va = g.visibleNodes(a), vb = g.visibleNodes(b);
        const double viaTable = g.distance(a, va, b, vb);
        const double viaTree = g.distance(g.tree(a, va), b, vb);
        EXPECT_NEAR(viaTable, viaTree, 1e-3 * viaTree + 1e-6);
        if (std::isfinite(viaTable)) {
            const auto mid = g.path(a, va, b, vb);
            expectSafe(g, a, mid, b);
            EXPECT_NEAR(length(a, mid, b), viaTable, 1e-3 * viaTable + 1e-6);
            ++compared;
        }
    }
    EXPECT_GT(compared, 100);
}

TEST(VisibilityGraph, ErrorsNameThePoint) {
    const VisibilityGraph g(NoFlyField({square(0, 0, 20)}, 5.0));
    auto r = g.shortestPath(Vec2(10, 10), Vec2(50, 50));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::NoPath);
    EXPECT_NE(r.error().message.find("(10.0, 10.0) m"), std::string::npos);
}
