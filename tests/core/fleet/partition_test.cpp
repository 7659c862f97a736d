#include "core/fleet/capability.h"
#include "core/fleet/partition.h"
#include "core/fleet/subarea_polygons.h"
#include "core/fleet/time_balance.h"
#include "core/geo/polygon_ops.h"

#include "tests/core/fleet/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace pf;
using namespace pf::fleet;
using pf::fleet::test::activeCount;
using pf::fleet::test::generatedShape;

namespace {

grid::Grid rectangle(int cols, int rows) {
    return grid::Grid::fromMask(cols, rows, std::vector<std::uint8_t>(static_cast<std::size_t>(cols * rows), 1), 10.0);
}

// Every active cell belongs to exactly one aircraft, inactive cells to none, lists match owners.
void expectExactCover(const grid::Grid& g, const Partition& p) {
    std::vector<int> seen(static_cast<std::size_t>(g.cellCount()), -1);
    for (std::size_t k = 0; k < p.cells.size(); ++k)
        for (int c : p.cells[k]) {
            ASSERT_EQ(seen[static_cast<std::size_t>(c)], -1) << "cell " << c << " given twice";
            seen[static_cast<std::size_t>(c)] = static_cast<int>(k);
        }
    for (int c = 0; c < g.cellCount(); ++c) {
        EXPECT_EQ(seen[static_cast<std::size_t>(c)], p.owner[static_cast<std::size_t>(c)]);
        EXPECT_EQ(p.owner[static_cast<std::size_t>(c)] >= 0, g.needsVisit(c)) << "cell " << c;
    }
}

// A mixed fleet drawn from the seed: footprints 15..45 m across, speeds 5..15 m/s.
std::vector<Capability> mixedFleet(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> across(15, 45), speed(5, 15), turn(30, 120);
    std::vector<Capability> fleet;
    for (int k = 0; k < n; ++k) {
        Capability c;
        c.name = "A" + std::to_string(k + 1);
        c.footprint.acrossM = across(rng);
        c.footprint.alongM = 0.6 * c.footprint.acrossM;
        c.time.speedMps = speed(rng);
        c.time.turnRateDegS = turn(rng);
        fleet.push_back(c);
    }
    return fleet;
}

// Analytic flight time of a back-and-forth survey of the cells' bounding box: photographed area
// / across / speed plus one 180-degree turn per track (tracks along the box's long side).
double analyticTime(const grid::Grid& g, const Capability& c, const std::vector<int>& cells) {
    if (cells.empty())
        return 0.0;
    int x0 = g.cols(), x1 = -1, y0 = g.rows(), y1 = -1;
    for (int i : cells) {
        x0 = std::min(x0, i % g.cols());
        x1 = std::max(x1, i % g.cols());
        y0 = std::min(y0, i / g.cols());
        y1 = std::max(y1, i / g.cols());
    }
    const double shortSide = std::min(x1 - x0 + 1, y1 - y0 + 1) * g.cellSize();
    const double tracks = std::ceil(shortSide / c.footprint.acrossM);
    const double length = cells.size() * g.cellSize() * g.cellSize() / c.footprint.acrossM;
    return length / c.time.speedMps + tracks * (180.0 / c.time.turnRateDegS + 2.0 * c.time.stopCostS() +
                                                c.footprint.acrossM / c.time.speedMps);
}

} // namespace

TEST(Partition, EqualSharesOfARectangleAreEqualAndConnected) {
    const auto g = rectangle(10, 10);
    auto p = partitionCells(g, {1.0, 1.0});
    ASSERT_TRUE(p.ok()) << p.error().message;
    expectExactCover(g, *p);
    EXPECT_EQ(p->cells[0].size(), 50u);
    EXPECT_EQ(p->cells[1].size(), 50u);
    EXPECT_TRUE(isConnected(g, p->cells[0]));
    EXPECT_TRUE(isConnected(g, p->cells[1]));
}

TEST(Partition, UnequalSharesFollowLargestRemainder) {
    const auto g = rectangle(7, 3); // 21 cells
    auto p = partitionCells(g, {1.0, 2.0, 4.0});
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->targets, (std::vector<int>{3, 6, 12}));
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(static_cast<int>(p->cells[static_cast<std::size_t>(k)].size()), p->targets[static_cast<std::size_t>(k)]);
        EXPECT_TRUE(isConnected(g, p->cells[static_cast<std::size_t>(k)]));
    }
}

// The invariants on many seeded concave shapes with holes and 2 to 4 mixed aircraft: exact cover,
// connected subareas, sizes on target (redistribution may be blocked by connectivity only rarely).
TEST(Partition, GeneratedShapesConnectedAndOnTarget) {
    int offTarget = 0, subareas = 0;
    for (unsigned seed = 1; seed <= 60; ++seed) {
        const auto g = generatedShape(seed);
        std::mt19937 rng(seed);
        const int n = 2 + static_cast<int>(seed % 3);
        const auto fleet = mixedFleet(rng, n);
        auto shares = capabilityShares(fleet, activeCount(g) * g.cellSize() * g.cellSize());
        ASSERT_TRUE(shares.ok());
        auto p = partitionCells(g, *shares);
        ASSERT_TRUE(p.ok()) << "seed " << seed << ": " << p.error().message;
        expectExactCover(g, *p);
        EXPECT_EQ(p->disconnectedSubareas, 0) << "seed " << seed;
        int sumTargets = 0;
        for (int k = 0; k < n; ++k) {
            const auto& cells = p->cells[static_cast<std::size_t>(k)];
            ASSERT_FALSE(cells.empty()) << "seed " << seed << " aircraft " << k;
            EXPECT_TRUE(isConnected(g, cells)) << "seed " << seed << " aircraft " << k;
            const int target = p->targets[static_cast<std::size_t>(k)];
            sumTargets += target;
            // Targets follow the shares to within one cell.
            EXPECT_NEAR(target, (*shares)[static_cast<std::size_t>(k)] * activeCount(g), 1.0);
            const int diff = std::abs(static_cast<int>(cells.size()) - target);
            EXPECT_LE(diff, std::max(2, target / 20)) << "seed " << seed << " aircraft " << k;
            offTarget += diff != 0;
            ++subareas;
        }
        EXPECT_EQ(sumTargets, activeCount(g));
    }
    EXPECT_LE(offTarget, subareas / 20) << "redistribution left too many subareas off target";
}

TEST(Partition, SeparatePiecesGetOneAircraftEach) {
    // Two 4x4 blocks separated by an empty column.
    std::vector<std::uint8_t> mask(9 * 4, 1);
    for (int y = 0; y < 4; ++y)
        mask[static_cast<std::size_t>(y * 9 + 4)] = 0;
    const auto g = grid::Grid::fromMask(9, 4, mask);
    auto p = partitionCells(g, {1.0, 1.0});
    ASSERT_TRUE(p.ok()) << p.error().message;
    expectExactCover(g, *p);
    EXPECT_EQ(p->disconnectedSubareas, 0);
    EXPECT_EQ(p->cells[0].size(), 16u);
    EXPECT_TRUE(isConnected(g, p->cells[0]));
    EXPECT_TRUE(isConnected(g, p->cells[1]));
}

TEST(Partition, MorePiecesThanAircraftAreReportedAsDisconnected) {
    // Three 2x2 blocks in a row, one aircraft: its subarea is necessarily in three pieces.
    std::vector<std::uint8_t> mask(8 * 2, 1);
    for (int y = 0; y < 2; ++y) {
        mask[static_cast<std::size_t>(y * 8 + 2)] = 0;
        mask[static_cast<std::size_t>(y * 8 + 5)] = 0;
    }
    const auto g = grid::Grid::fromMask(8, 2, mask);
    auto p = partitionCells(g, {1.0, 1.0});
    ASSERT_TRUE(p.ok()) << p.error().message;
    expectExactCover(g, *p);
    EXPECT_EQ(p->disconnectedSubareas, 1);
}

TEST(Partition, BadInputsAreRejectedWithAMessage) {
    const auto g = rectangle(2, 1);
    auto none = partitionCells(g, {});
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().message, "No aircraft to share the area between.");
    auto negative = partitionCells(g, {1.0, -1.0});
    ASSERT_FALSE(negative.ok());
    EXPECT_EQ(negative.error().message, "The share of aircraft 2 is not a positive number.");
    auto tooMany = partitionCells(g, {1.0, 1.0, 1.0});
    ASSERT_FALSE(tooMany.ok());
    EXPECT_EQ(tooMany.error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(tooMany.error().message,
              "The area has only 2 cells to photograph, fewer than the 3 aircraft: use fewer aircraft or a smaller "
              "footprint.");
}

// Balancing on time (beyond the paper) reaches makespan <= 1.10 x ideal on generated shapes with 2
// to 4 mixed aircraft, keeping every subarea connected and every cell assigned.
TEST(BalanceByTime, MakespanWithinTenPercentOfIdeal) {
    int improved = 0;
    for (unsigned seed = 1; seed <= 40; ++seed) {
        const auto g = generatedShape(seed + 100);
        std::mt19937 rng(seed);
        const int n = 2 + static_cast<int>(seed % 3);
        const auto fleet = mixedFleet(rng, n);
        auto shares = capabilityShares(fleet, activeCount(g) * g.cellSize() * g.cellSize());
        ASSERT_TRUE(shares.ok());
        auto p = partitionCells(g, *shares);
        ASSERT_TRUE(p.ok());
        std::vector<double> before;
        for (int k = 0; k < n; ++k)
            before.push_back(analyticTime(g, fleet[static_cast<std::size_t>(k)], p->cells[static_cast<std::size_t>(k)]));
        const double makespanBefore = *std::max_element(before.begin(), before.end());
        auto rep = balanceByTime(g, *p, [&](int k, const std::vector<int>& cells) -> Result<double> {
            return analyticTime(g, fleet[static_cast<std::size_t>(k)], cells);
        });
        ASSERT_TRUE(rep.ok()) << rep.error().message;
        expectExactCover(g, *p);
        for (int k = 0; k < n; ++k) {
            EXPECT_TRUE(isConnected(g, p->cells[static_cast<std::size_t>(k)])) << "seed " << seed << " aircraft " << k;
            EXPECT_NEAR(rep->times[static_cast<std::size_t>(k)],
                        analyticTime(g, fleet[static_cast<std::size_t>(k)], p->cells[static_cast<std::size_t>(k)]), 1e-9);
        }
        EXPECT_LE(rep->makespan, 1.10 * rep->ideal) << "seed " << seed << " with " << n << " aircraft";
        EXPECT_LE(rep->makespan, makespanBefore + 1e-9);
        improved += rep->makespan < makespanBefore - 1e-9;
    }
    EXPECT_GT(improved, 0);
}

TEST(BalanceByTime, EstimatorErrorsArePassedOn) {
    const auto g = rectangle(6, 6);
    auto p = partitionCells(g, {1.0, 1.0});
    ASSERT_TRUE(p.ok());
    auto rep = balanceByTime(g, *p, [](int, const std::vector<int>&) -> Result<double> {
        return makeError(ErrorCode::NoPath, "No safe path to cell 3.");
    });
    ASSERT_FALSE(rep.ok());
    EXPECT_EQ(rep.error().message, "No safe path to cell 3.");
    auto bad = balanceByTime(g, *p, [](int, const std::vector<int>&) -> Result<double> { return -1.0; });
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message, "The flight time estimate of aircraft 1 is not a valid duration.");
}

TEST(SubareaPolygons, TileTheClippedAreaWithoutOverlap) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const auto g = generatedShape(seed, 10.0);
        auto p = partitionCells(g, {1.0, 2.0, 1.5});
        ASSERT_TRUE(p.ok());
        // Clip to a disc-like octagon over the grid: the union must equal grid-cells ∩ clip.
        const double cx = g.cols() * 5.0, cy = g.rows() * 5.0, r = 0.45 * std::min(g.cols(), g.rows()) * 10.0;
        geo::Polygon clip;
        for (int i = 0; i < 8; ++i)
            clip.outer.emplace_back(cx + r * std::cos(i * M_PI / 4), cy + r * std::sin(i * M_PI / 4));
        const auto polys = subareaPolygons(g, *p, {clip});
        ASSERT_EQ(polys.size(), 3u);
        double sum = 0;
        for (const auto& mp : polys)
            sum += geo::area(mp);
        std::vector<int> all;
        for (int c = 0; c < g.cellCount(); ++c)
            if (g.needsVisit(c))
                all.push_back(c);
        const double expected = geo::area(cellsPolygon(g, all, {clip}));
        EXPECT_NEAR(sum, expected, 1e-6 * expected + 1e-6) << "seed " << seed;
        for (std::size_t a = 0; a < polys.size(); ++a)
            for (std::size_t b = a + 1; b < polys.size(); ++b)
                for (const auto& pb : polys[b])
                    EXPECT_NEAR(geo::area(geo::intersection(polys[a], pb)), 0.0, 1e-6) << "seed " << seed;
    }
}

TEST(SubareaPolygons, CellSquaresFollowTheGridRotation) {
    // A 20 m square on a grid rotated by 90 degrees: its columns run north locally.
    const geo::Polygon square{{geo::Vec2(100, 0), geo::Vec2(120, 0), geo::Vec2(120, 20), geo::Vec2(100, 20)}, {}};
    grid::GridOptions opt;
    opt.cellSize = 10.0;
    opt.angleDeg = 90.0;
    auto g = grid::Grid::build(square, {}, opt);
    ASSERT_TRUE(g.ok()) << g.error().message;
    ASSERT_EQ(g->cellCount(), 4);
    // Second column of the first row: one cell "east" in grid terms = north locally.
    EXPECT_NEAR(g->cellCenter(1).x(), 115.0, 1e-9);
    EXPECT_NEAR(g->cellCenter(1).y(), 15.0, 1e-9);
    for (int c = 0; c < g->cellCount(); ++c) {
        const auto poly = cellsPolygon(*g, {c}, {});
        ASSERT_EQ(poly.size(), 1u);
        EXPECT_NEAR(geo::area(poly), 100.0, 1e-6) << "cell " << c;
        for (const auto& corner : g->cellCorners(c)) {
            double nearest = 1e9;
            for (const auto& v : poly.front().outer)
                nearest = std::min(nearest, (v - corner).norm());
            EXPECT_NEAR(nearest, 0.0, 1e-6) << "cell " << c;
        }
    }
}

// The traced union of cells equals GEOS's union of their squares on random sets (checkerboards
// of cells touching at corners, groups closing round a hole diagonally, holes, single cells) on a
// rotated grid: the same ground, one valid polygon per 4-connected group.
TEST(SubareaPolygons, TracedUnionEqualsThePolygonUnionOfTheCells) {
    const geo::Polygon field{{geo::Vec2(0, 0), geo::Vec2(160, 0), geo::Vec2(160, 130), geo::Vec2(0, 130)}, {}};
    grid::GridOptions opt;
    opt.cellSize = 10.0;
    opt.angleDeg = 30.0;
    auto g = grid::Grid::build(field, {}, opt);
    ASSERT_TRUE(g.ok()) << g.error().message;
    std::mt19937 rng(11);
    std::vector<std::vector<int>> sets;
    for (double density : {0.2, 0.4, 0.5, 0.6, 0.8})
        for (int rep = 0; rep < 8; ++rep) {
            std::vector<int> s;
            std::bernoulli_distribution in(density);
            for (int c = 0; c < g->cellCount(); ++c)
                if (in(rng))
                    s.push_back(c);
            sets.push_back(s);
        }
    // A ring of cells whose ends touch diagonally round a one-cell hole, and a checkerboard.
    const int C = g->cols();
    sets.push_back({0 * C + 1, 0 * C + 2, 1 * C + 2, 2 * C + 2, 2 * C + 1, 2 * C + 0, 1 * C + 0});
    std::vector<int> checker;
    for (int c = 0; c < g->cellCount(); ++c)
        if ((c % C + c / C) % 2 == 0)
            checker.push_back(c);
    sets.push_back(checker);
    sets.push_back({5 * C + 5});
    for (std::size_t si = 0; si < sets.size(); ++si) {
        const auto& s = sets[si];
        if (s.empty())
            continue;
        const geo::MultiPolygon traced = cellsUnion(*g, s);
        geo::MultiPolygon squares;
        for (int c : s)
            squares.push_back(geo::Polygon{g->cellCorners(c), {}});
        const geo::MultiPolygon reference = geo::unite(squares);
        ASSERT_FALSE(traced.empty()) << "set " << si;
        for (const auto& p : traced) {
            std::string why;
            EXPECT_TRUE(geo::isValid(p, &why)) << "set " << si << ": " << why;
        }
        EXPECT_NEAR(geo::area(traced), 100.0 * static_cast<double>(s.size()), 1e-6) << "set " << si;
        EXPECT_NEAR(geo::area(geo::difference(reference, traced)), 0.0, 1e-6) << "set " << si;
        EXPECT_NEAR(geo::area(geo::difference(traced, reference)), 0.0, 1e-6) << "set " << si;
        // Polygons: one per 4-connected group of cells.
        std::vector<int> seen(static_cast<std::size_t>(g->cellCount()), 0), inSet(seen.size(), 0);
        for (int c : s)
            inSet[static_cast<std::size_t>(c)] = 1;
        std::size_t groups = 0;
        for (int c : s) {
            if (seen[static_cast<std::size_t>(c)])
                continue;
            ++groups;
            std::vector<int> st{c};
            seen[static_cast<std::size_t>(c)] = 1;
            while (!st.empty()) {
                const int x = st.back();
                st.pop_back();
                const int cx = x % C, cy = x / C;
                for (const auto& [nx, ny] : {std::pair{cx + 1, cy}, {cx - 1, cy}, {cx, cy + 1}, {cx, cy - 1}}) {
                    if (nx < 0 || ny < 0 || nx >= C || ny >= g->rows())
                        continue;
                    const int n = ny * C + nx;
                    if (inSet[static_cast<std::size_t>(n)] && !seen[static_cast<std::size_t>(n)]) {
                        seen[static_cast<std::size_t>(n)] = 1;
                        st.push_back(n);
                    }
                }
            }
        }
        EXPECT_EQ(traced.size(), groups) << "set " << si;
    }
}
