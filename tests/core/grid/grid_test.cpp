// Tests of the grid decomposition: hand-checked small cases and invariants on many seeded random shapes.
#include "core/grid/grid.h"

#include "core/geo/polygon_ops.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace pf;
using namespace pf::grid;
using geo::Vec2;

namespace {

geo::Polygon rect(double x0, double y0, double x1, double y1) {
    return geo::Polygon{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}, {}};
}

// A random star-shaped (usually concave) polygon around c: one vertex per angular sector, so that no
// gap between consecutive angles reaches 180 degrees and the polygon stays simple.
geo::Polygon randomStar(std::mt19937& rng, Vec2 c, double rMin, double rMax, int nMin, int nMax) {
    std::uniform_int_distribution<int> nd(nMin, nMax);
    std::uniform_real_distribution<double> jd(0, 0.8), rd(rMin, rMax);
    const int n = nd(rng);
    geo::Polygon p;
    for (int k = 0; k < n; ++k) {
        const double a = (k + jd(rng)) * 2 * M_PI / n;
        const double r = rd(rng);
        p.outer.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
    }
    return p;
}

bool strictlyInside(const geo::MultiPolygon& mp, const Vec2& p, double tol) {
    for (const auto& poly : mp)
        if (geo::contains(poly, p) && geo::distanceToBoundary(poly, p) > tol)
            return true;
    return false;
}

double distanceToZones(const std::vector<geo::Polygon>& zones, const Vec2& p) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& z : zones)
        d = std::min(d, geo::distanceTo(z, p));
    return d;
}

} // namespace

TEST(Grid, SquareAreaAlignedCells) {
    auto g = Grid::build(rect(0, 0, 100, 50), {}, GridOptions{10.0, 0.0, 0.0});
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_EQ(g->cols(), 10);
    EXPECT_EQ(g->rows(), 5);
    EXPECT_EQ(g->visitCount(), 50);
    EXPECT_TRUE(g->origin().isApprox(Vec2(0, 0)));
    const int i = g->index(3, 2);
    EXPECT_TRUE(g->cellCenter(i).isApprox(Vec2(35, 25)));
    EXPECT_EQ(g->state(i), CellState::Free);
    EXPECT_FALSE(g->onContour(i));
    EXPECT_TRUE(g->onContour(g->index(0, 2)));
    EXPECT_TRUE(g->onContour(g->index(9, 4)));
    for (Dir d : kDirs)
        EXPECT_TRUE(g->canMove(i, d));
    EXPECT_FALSE(g->canMove(g->index(0, 0), Dir::West));
    EXPECT_EQ(g->neighbour(g->index(0, 0), Dir::South), -1);
    EXPECT_EQ(g->neighbour(i, Dir::North), g->index(3, 3));
    EXPECT_EQ(g->cellAt(Vec2(35.5, 21)), i);
    EXPECT_FALSE(g->cellAt(Vec2(-1, 5)).has_value());
}

TEST(Grid, PartialCellsBelongToTheProblemButSliversDoNot) {
    // 95 m wide: the last column is half covered; a polygon edge along a cell edge adds no cells.
    auto g = Grid::build(rect(0, 0, 95, 20), {}, GridOptions{10.0, 0.0, 0.0});
    ASSERT_TRUE(g.ok());
    EXPECT_EQ(g->cols(), 10);
    EXPECT_EQ(g->rows(), 2);
    EXPECT_EQ(g->visitCount(), 20);
    // A cell that the area touches along one edge only is Outside.
    geo::Polygon l{{Vec2(0, 0), Vec2(20, 0), Vec2(20, 10), Vec2(10, 10), Vec2(10, 20), Vec2(0, 20)}, {}};
    auto gl = Grid::build(l, {}, GridOptions{10.0, 0.0, 0.0});
    ASSERT_TRUE(gl.ok());
    EXPECT_EQ(gl->visitCount(), 3);
    EXPECT_EQ(gl->state(gl->index(1, 1)), CellState::Outside);
}

TEST(Grid, RotationConvention) {
    // A 100 x 20 rectangle rotated by 30 degrees, gridded at 30 degrees, gives a 10 x 2 grid.
    const double a = 30 * M_PI / 180;
    geo::Polygon p;
    for (Vec2 v : {Vec2(0, 0), Vec2(100, 0), Vec2(100, 20), Vec2(0, 20)})
        p.outer.push_back(Vec2(std::cos(a) * v.x() - std::sin(a) * v.y(), std::sin(a) * v.x() + std::cos(a) * v.y()) +
                          Vec2(500, -300));
    auto g = Grid::build(p, {}, GridOptions{10.0, 30.0, 0.0});
    ASSERT_TRUE(g.ok());
    EXPECT_EQ(g->cols(), 10);
    EXPECT_EQ(g->rows(), 2);
    EXPECT_EQ(g->visitCount(), 20);
    EXPECT_TRUE(g->origin().isApprox(Vec2(500, -300), 1e-9));
    // Column +1 moves 10 m along the rotated x axis (30 degrees counter-clockwise from east).
    const Vec2 step = g->cellCenter(g->index(1, 0)) - g->cellCenter(g->index(0, 0));
    EXPECT_NEAR(step.x(), 10 * std::cos(a), 1e-9);
    EXPECT_NEAR(step.y(), 10 * std::sin(a), 1e-9);
    const auto corners = g->cellCorners(g->index(4, 1));
    ASSERT_EQ(corners.size(), 4u);
    EXPECT_NEAR(geo::signedArea(corners), 100.0, 1e-9); // counter-clockwise
    for (int i = 0; i < g->cellCount(); ++i)
        EXPECT_EQ(g->cellAt(g->cellCenter(i)), i);
}

TEST(Grid, NoFlyZoneMakesShiftedAndUnflyableCells) {
    // 100 x 100 area, 10 m cells; a no-fly zone [40, 60] x [40, 60] with 2 m margin.
    auto g = Grid::build(rect(0, 0, 100, 100), {rect(40, 40, 60, 60)}, GridOptions{10.0, 0.0, 2.0});
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_EQ(g->state(g->index(4, 4)), CellState::Outside); // entirely inside the zone
    // Cell (3, 4) [30,40]x[40,50]: centre (35, 45) is 5 m from the zone: free.
    EXPECT_EQ(g->state(g->index(3, 4)), CellState::Free);
    EXPECT_FALSE(g->onContour(g->index(2, 4)));
    EXPECT_TRUE(g->onContour(g->index(3, 4))); // next to the zone
    // With a 6 m margin the same centre is unsafe; the nearest safe point is (34, 45), less the 2 % the
    // buffer adds so that its rounded corners keep the full margin, nudged by 1 mm.
    auto g6 = Grid::build(rect(0, 0, 100, 100), {rect(40, 40, 60, 60)}, GridOptions{10.0, 0.0, 6.0});
    ASSERT_TRUE(g6.ok());
    const int s = g6->index(3, 4);
    EXPECT_EQ(g6->state(s), CellState::Shifted);
    EXPECT_NEAR(g6->flightPosition(s).x(), 40.0 - 6.0 / std::cos(M_PI / 16) - 1e-3, 1e-6);
    EXPECT_NEAR(g6->flightPosition(s).y(), 45.0, 1e-6);
    EXPECT_TRUE(g6->pointIsSafe(g6->flightPosition(s)));
    EXPECT_FALSE(g6->pointIsSafe(g6->cellCenter(s)));
    // A 12 m margin swallows the whole of cell (3, 4).
    auto g12 = Grid::build(rect(0, 0, 100, 100), {rect(40, 40, 60, 60)}, GridOptions{10.0, 0.0, 12.0});
    ASSERT_TRUE(g12.ok());
    EXPECT_EQ(g12->state(g12->index(3, 4)), CellState::Unflyable);
    EXPECT_FALSE(g12->needsVisit(g12->index(3, 4)));
    EXPECT_EQ(g12->state(g12->index(1, 4)), CellState::Free);
}

TEST(Grid, MovesAroundAThinWallAreForbidden) {
    // A thin no-fly wall along x = 50 between y = 0 and y = 80 separates columns 4 and 5 below y = 80.
    auto g = Grid::build(rect(0, 0, 100, 100), {rect(49.9, -5, 50.1, 80)}, GridOptions{10.0, 0.0, 0.0});
    ASSERT_TRUE(g.ok());
    EXPECT_EQ(g->state(g->index(4, 2)), CellState::Free);
    EXPECT_EQ(g->state(g->index(5, 2)), CellState::Free);
    EXPECT_FALSE(g->canMove(g->index(4, 2), Dir::East));
    EXPECT_FALSE(g->canMove(g->index(5, 2), Dir::West));
    EXPECT_TRUE(g->canMove(g->index(4, 9), Dir::East));
    // The contour is about visitable neighbours, not about allowed moves.
    EXPECT_FALSE(g->onContour(g->index(4, 2)));
    EXPECT_FALSE(g->segmentIsSafe(Vec2(45, 25), Vec2(55, 25)));
    EXPECT_TRUE(g->segmentIsSafe(Vec2(45, 95), Vec2(55, 95)));
}

TEST(Grid, MultiPolygonAreaAndHoles) {
    geo::Polygon withHole = rect(0, 0, 60, 60);
    withHole.holes.push_back(rect(20, 20, 40, 40).outer);
    geo::MultiPolygon mp{withHole, rect(100, 0, 120, 20)};
    auto g = Grid::build(mp, {}, GridOptions{10.0, 0.0, 0.0});
    ASSERT_TRUE(g.ok());
    EXPECT_EQ(g->visitCount(), 36 - 4 + 4);
    auto c = g->cellAt(Vec2(30, 30));
    ASSERT_TRUE(c);
    EXPECT_EQ(g->state(*c), CellState::Outside);
    EXPECT_NEAR(geo::area(g->admissible()), 3200.0 + 400.0, 1e-6);

    // Overlapping subareas count once (an even-odd fill would leave their overlap out).
    auto overlapping = Grid::build(geo::MultiPolygon{rect(0, 0, 40, 20), rect(20, 0, 60, 20)}, {},
                                   GridOptions{10.0, 0.0, 0.0});
    ASSERT_TRUE(overlapping.ok());
    EXPECT_EQ(overlapping->visitCount(), 12);

    // An invalid area is not mistaken for one covered by no-fly zones.
    const geo::Polygon bow{{Vec2(0, 0), Vec2(50, 50), Vec2(50, 0), Vec2(0, 50)}, {}};
    auto bad = Grid::build(bow, {rect(0, 20, 5, 25)}, GridOptions{10.0, 0.0, 0.0});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message.rfind("the area is not a valid polygon (", 0), 0u) << bad.error().message;
}

TEST(Grid, ErrorsNameTheProblem) {
    auto bad = Grid::build(rect(0, 0, 100, 100), {}, GridOptions{0.0, 0.0, 0.0});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(bad.error().message.find("cell size must be a positive"), std::string::npos);

    auto margin = Grid::build(rect(0, 0, 100, 100), {}, GridOptions{10.0, 0.0, -1.0});
    ASSERT_FALSE(margin.ok());
    EXPECT_NE(margin.error().message.find("safety margin"), std::string::npos);

    auto covered = Grid::build(rect(0, 0, 100, 100), {rect(-10, -10, 110, 110)}, GridOptions{10.0, 0.0, 0.0});
    ASSERT_FALSE(covered.ok());
    EXPECT_EQ(covered.error().code, ErrorCode::InvalidGeometry);
    EXPECT_NE(covered.error().message.find("cover the whole area"), std::string::npos);

    GridOptions opt{1.0, 0.0, 0.0};
    opt.maxCells = 1000;
    auto big = Grid::build(rect(0, 0, 100, 100), {}, opt);
    ASSERT_FALSE(big.ok());
    EXPECT_EQ(big.error().code, ErrorCode::TooLarge);
    EXPECT_NE(big.error().message.find("100 x 100 = 10,000 cells, more than the budget of 1,000"), std::string::npos)
        << big.error().message;
    EXPECT_NE(big.error().message.find("a cell size of at least 3.23 m would fit"), std::string::npos)
        << big.error().message;
}

// Ground prepared once serves every angle and cell size: each grid equals the one built from the
// area and zones directly (states, flight positions bit for bit, moves, pockets, zones).
TEST(Grid, PreparedGroundGivesTheSameGrids) {
    const geo::MultiPolygon area{geo::Polygon{
        {Vec2(0, 0), Vec2(120, 0), Vec2(120, 50), Vec2(60, 50), Vec2(60, 100), Vec2(0, 100)}, {}}};
    // Two zones 4 m apart (their 5 m margins merge: a pocket) and a rotated one.
    const std::vector<geo::Polygon> zones{
        rect(20, 20, 30, 40), rect(34, 20, 44, 40),
        geo::Polygon{{Vec2(80, 10), Vec2(95, 18), Vec2(90, 28), Vec2(75, 20)}, {}}};
    auto ground = GridGround::prepare(area, zones, 5.0);
    ASSERT_TRUE(ground.ok()) << ground.error().message;
    EXPECT_DOUBLE_EQ(ground->safetyMarginM(), 5.0);
    for (double angle : {0.0, 17.5, 45.0, 90.0, 133.0})
        for (double cell : {4.0, 7.3}) {
            const GridOptions opt{cell, angle, 5.0};
            auto direct = Grid::build(area, zones, opt);
            auto shared = Grid::build(*ground, opt);
            ASSERT_TRUE(direct.ok() && shared.ok());
            ASSERT_EQ(direct->cols(), shared->cols());
            ASSERT_EQ(direct->rows(), shared->rows());
            EXPECT_EQ(direct->origin(), shared->origin());
            EXPECT_EQ(direct->visitCount(), shared->visitCount());
            int shifted = 0;
            for (int i = 0; i < direct->cellCount(); ++i) {
                ASSERT_EQ(direct->state(i), shared->state(i)) << "angle " << angle << " cell " << i;
                shifted += direct->state(i) == CellState::Shifted;
                if (direct->needsVisit(i)) {
                    EXPECT_EQ(direct->flightPosition(i), shared->flightPosition(i));
                    for (Dir d : kDirs)
                        EXPECT_EQ(direct->canMove(i, d), shared->canMove(i, d));
                }
            }
            EXPECT_GT(shifted, 0);
            EXPECT_EQ(direct->pockets().size(), shared->pockets().size());
            EXPECT_DOUBLE_EQ(geo::area(direct->pockets()), geo::area(shared->pockets()));
            EXPECT_DOUBLE_EQ(geo::area(direct->bufferedNoFly()),
                             geo::area(shared->bufferedNoFly()));
        }
    EXPECT_GT(geo::area(ground->admissible()), 0.0);
    // Another margin than the ground's is refused, not silently planned with the wrong one.
    auto wrong = Grid::build(*ground, GridOptions{4.0, 0.0, 2.0});
    ASSERT_FALSE(wrong.ok());
    EXPECT_NE(wrong.error().message.find("another safety margin"), std::string::npos);
    // The area's errors come from prepare, the options' from the build.
    auto covered =
        GridGround::prepare(geo::MultiPolygon{rect(0, 0, 10, 10)}, {rect(-1, -1, 11, 11)}, 0.0);
    ASSERT_FALSE(covered.ok());
    EXPECT_NE(covered.error().message.find("cover the whole area"), std::string::npos);
    auto badCell = Grid::build(*ground, GridOptions{0.0, 0.0, 5.0});
    ASSERT_FALSE(badCell.ok());
    EXPECT_NE(badCell.error().message.find("cell size must be a positive"), std::string::npos);
}

// A shifted cell flies at the nearest point of its square outside the buffered zones: checked
// against the square minus the zones computed by GEOS (its boundary scanned for the point nearest
// the centre), before the 1 mm nudge; an unflyable cell touching the zones has no free ground left
// of its square.
TEST(Grid, ShiftedPositionIsTheNearestFreePointOfItsCell) {
    std::mt19937 rng(11);
    int shifted = 0, unflyable = 0;
    for (int shape = 0; shape < 8; ++shape) {
        const geo::Polygon area = rect(0, 0, 150, 120);
        std::vector<geo::Polygon> zones;
        for (int z = 0; z < 4; ++z)
            zones.push_back(randomStar(rng, Vec2(25 + 33 * z, 30 + 20 * (shape % 3) + 10 * z % 40),
                                       4, 14, 5, 9));
        const double angle = 13.0 * shape;
        auto g = Grid::build(area, zones, GridOptions{6.0, angle, 3.0});
        ASSERT_TRUE(g.ok()) << g.error().message;
        for (int i = 0; i < g->cellCount(); ++i) {
            const CellState st = g->state(i);
            if (st != CellState::Shifted && st != CellState::Unflyable)
                continue;
            const geo::MultiPolygon free = geo::difference(
                geo::MultiPolygon{geo::Polygon{g->cellCorners(i), {}}}, g->bufferedNoFly());
            if (st == CellState::Unflyable) {
                ++unflyable;
                EXPECT_LT(geo::area(free), 1e-6) << "cell " << i;
                continue;
            }
            ++shifted;
            const Vec2 c = g->cellCenter(i);
            double best = std::numeric_limits<double>::infinity();
            for (const auto& poly : free)
                for (std::size_t k = 0; k < poly.outer.size(); ++k) {
                    const Vec2 a = poly.outer[k], b = poly.outer[(k + 1) % poly.outer.size()];
                    const Vec2 ab = b - a;
                    const double t = std::clamp((c - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
                    best = std::min(best, (a + t * ab - c).norm());
                }
            ASSERT_TRUE(std::isfinite(best)) << "cell " << i;
            // The flight position is that point, nudged 1 mm further from the zone when the cell
            // allows.
            EXPECT_NEAR((g->flightPosition(i) - c).norm(), best, 1.5e-3) << "cell " << i;
            EXPECT_TRUE(g->pointIsSafe(g->flightPosition(i)));
        }
    }
    EXPECT_GT(shifted, 50);
}

TEST(Grid, CellSizeToFitIsTheSmallestThatFits) {
    const geo::MultiPolygon region{rect(0, 0, 1000, 300)};
    for (std::size_t budget : {10u, 1000u, 12345u}) {
        const double s = Grid::cellSizeToFit(region, 1.0, 20.0, budget);
        EXPECT_LE(Grid::sizeFor(region, s, 20.0).cells(), static_cast<double>(budget));
        EXPECT_GT(Grid::sizeFor(region, s * 0.97, 20.0).cells(), static_cast<double>(budget));
    }
    EXPECT_EQ(Grid::cellSizeToFit(region, 50.0, 0.0, 1000), 50.0);
}

TEST(Grid, FromMask) {
    // 3 x 2:  row 1: . X X   row 0: X X .
    const Grid g = Grid::fromMask(3, 2, {1, 1, 0, 0, 1, 1}, 2.0);
    EXPECT_EQ(g.visitCount(), 4);
    EXPECT_TRUE(g.canMove(g.index(0, 0), Dir::East));
    EXPECT_TRUE(g.canMove(g.index(1, 0), Dir::North));
    EXPECT_FALSE(g.canMove(g.index(1, 0), Dir::East));
    EXPECT_EQ(g.state(g.index(0, 1)), CellState::Outside);
    EXPECT_TRUE(g.cellCenter(g.index(2, 1)).isApprox(Vec2(5, 3)));
    EXPECT_EQ(g.nearestVisitable(Vec2(5.5, 0.5)), g.index(1, 0));
    EXPECT_TRUE(g.onContour(g.index(1, 1)));
    EXPECT_GE(g.memoryBytes(), 12u);
}

TEST(Grid, NearestVisitableMatchesBruteForce) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-80, 180);
    auto g = Grid::build(randomStar(rng, Vec2(50, 50), 30, 90, 8, 14), {}, GridOptions{7.0, 25.0, 0.0});
    ASSERT_TRUE(g.ok());
    for (int k = 0; k < 200; ++k) {
        const Vec2 p(u(rng), u(rng));
        double best = std::numeric_limits<double>::infinity();
        for (int i = 0; i < g->cellCount(); ++i)
            if (g->needsVisit(i))
                best = std::min(best, (g->flightPosition(i) - p).norm());
        const int n = g->nearestVisitable(p);
        ASSERT_GE(n, 0);
        EXPECT_NEAR((g->flightPosition(n) - p).norm(), best, 1e-9);
    }
}

// The grid's promises, checked against exact geometry on many seeded random shapes: random concave
// areas (some with a hole), random no-fly zones inside, across and outside the area, random angles,
// cell sizes and safety margins.
TEST(Grid, InvariantsOnRandomShapes) {
    int shifted = 0, unflyable = 0, forbidden = 0;
    for (unsigned seed = 1; seed <= 40; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> unit(0, 1);
        geo::Polygon area = randomStar(rng, Vec2(0, 0), 80, 220, 6, 18);
        if (seed % 5 == 0)
            area.holes.push_back(rect(-15, -15, 15, 15).outer);
        std::vector<geo::Polygon> zones;
        const int nz = static_cast<int>(unit(rng) * 6);
        for (int k = 0; k < nz; ++k)
            zones.push_back(randomStar(rng, Vec2(400 * unit(rng) - 200, 400 * unit(rng) - 200), 8, 40, 4, 10));
        GridOptions opt;
        opt.cellSize = 12 + 18 * unit(rng);
        opt.angleDeg = 180 * unit(rng);
        opt.safetyMarginM = seed % 4 == 0 ? 0.0 : 10 * unit(rng);
        auto gr = Grid::build(area, zones, opt);
        if (!gr.ok()) { // only when the zones swallow the area, which these sizes make impossible
            ADD_FAILURE() << gr.error().message;
            continue;
        }
        const Grid& g = *gr;
        const geo::MultiPolygon admissible =
            zones.empty() ? geo::MultiPolygon{area} : geo::difference(area, geo::MultiPolygon(zones.begin(), zones.end()));
        const double cellArea = opt.cellSize * opt.cellSize;
        // The full safety margin is kept from the un-buffered zones (up to rounding).
        const double marginFloor = opt.safetyMarginM - 1e-6;

        int visit = 0;
        for (int i = 0; i < g.cellCount(); ++i) {
            const auto corners = g.cellCorners(i);
            const geo::Polygon cell{corners, {}};
            const double inside = geo::area(geo::intersection(admissible, cell));
            const CellState st = g.state(i);
            // States agree with exact geometry (a band around the sliver threshold is not decided).
            if (inside > 2e-6 * cellArea) {
                EXPECT_NE(st, CellState::Outside) << "cell " << i << " overlaps the admissible area by " << inside;
            }
            if (inside < 0.5e-6 * cellArea) {
                EXPECT_EQ(st, CellState::Outside) << "cell " << i;
            }
            if (st == CellState::Outside)
                continue;
            const double flyable = geo::area(geo::difference(cell, g.bufferedNoFly()));
            if (st == CellState::Free) {
                EXPECT_FALSE(strictlyInside(g.bufferedNoFly(), g.cellCenter(i), 1e-6));
                EXPECT_TRUE(g.flightPosition(i).isApprox(g.cellCenter(i)));
            } else if (st == CellState::Shifted) {
                ++shifted;
                EXPECT_TRUE(strictlyInside(g.bufferedNoFly(), g.cellCenter(i), 0.0));
                const Vec2 u = g.flightPosition(i) - g.origin();
                const double a = g.angleDeg() * M_PI / 180;
                const double gx = (std::cos(a) * u.x() + std::sin(a) * u.y()) / opt.cellSize - g.col(i);
                const double gy = (-std::sin(a) * u.x() + std::cos(a) * u.y()) / opt.cellSize - g.row(i);
                EXPECT_TRUE(gx > -1e-9 && gx < 1 + 1e-9 && gy > -1e-9 && gy < 1 + 1e-9)
                    << "a shifted position stays in its cell";
                EXPECT_GT(flyable, 0.0);
            } else {
                ++unflyable;
                EXPECT_LT(flyable, 1e-6 * cellArea);
            }
            if (!g.needsVisit(i))
                continue;
            ++visit;
            const Vec2 fp = g.flightPosition(i);
            EXPECT_TRUE(g.pointIsSafe(fp));
            EXPECT_FALSE(strictlyInside(g.bufferedNoFly(), fp, 1e-6));
            EXPECT_GE(distanceToZones(zones, fp), marginFloor);
            // Moves: symmetric, only between visitable neighbours, and exactly the safe segments.
            for (Dir d : kDirs) {
                const int j = g.neighbour(i, d);
                if (j < 0 || !g.needsVisit(j)) {
                    EXPECT_FALSE(g.canMove(i, d));
                    continue;
                }
                EXPECT_EQ(g.canMove(i, d), g.canMove(j, opposite(d)));
                const Vec2 q = g.flightPosition(j);
                const bool safe = !geo::segmentCrossesInterior(g.bufferedNoFly(), fp, q);
                EXPECT_EQ(g.canMove(i, d), safe) << "cells " << i << " -> " << j;
                if (!g.canMove(i, d)) {
                    ++forbidden;
                    continue;
                }
                for (int k = 0; k <= 20; ++k)
                    EXPECT_GE(distanceToZones(zones, fp + (q - fp) * (k / 20.0)), marginFloor);
            }
            // Contour: a visitable cell with a non-visitable or missing 4-neighbour.
            bool contour = false;
            for (Dir d : kDirs) {
                const int j = g.neighbour(i, d);
                contour = contour || j < 0 || !g.needsVisit(j);
            }
            EXPECT_EQ(g.onContour(i), contour);
        }
        EXPECT_EQ(g.visitCount(), visit);

        // Coverage: every sampled point of the admissible area lies in a cell that is part of the problem.
        const geo::Box box = geo::bounds(area);
        for (int k = 0; k < 4000; ++k) {
            const Vec2 p(box.min.x() + unit(rng) * (box.max.x() - box.min.x()),
                         box.min.y() + unit(rng) * (box.max.y() - box.min.y()));
            if (!geo::contains(admissible, p) || geo::distanceToBoundary(area, p) < 1e-6)
                continue;
            const auto c = g.cellAt(p);
            ASSERT_TRUE(c.has_value()) << "point " << p.transpose() << " outside the grid";
            EXPECT_NE(g.state(*c), CellState::Outside) << "point " << p.transpose();
        }
    }
    // The shapes exercise every branch.
    EXPECT_GT(shifted, 0);
    EXPECT_GT(unflyable, 0);
    EXPECT_GT(forbidden, 0);
}
