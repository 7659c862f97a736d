#include "core/plan/sweep/decomposition.h"
#include "core/plan/sweep/sweep_lanes.h"

#include "core/geo/polygon_ops.h"
#include "tests/core/plan/sweep_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pf;
using namespace pf::plan;
using geo::Vec2;

namespace {

// The free space a sweep decomposes: the area minus its zones grown by a 5 m margin.
geo::MultiPolygon freeSpace(const sweeptest::Area& a) {
    geo::MultiPolygon grown;
    for (const auto& z : a.zones)
        for (auto& g : geo::buffer(z, 5.5, 2))
            grown.push_back(g);
    return grown.empty() ? a.region : geo::difference(a.region, geo::unite(grown));
}

geo::Polygon world(const Decomposition& d, const geo::Ring& frameRing) {
    geo::Polygon p;
    for (const auto& q : frameRing)
        p.outer.push_back(d.frame.toWorld(q));
    return p;
}

// Crossings of the horizontal line at y with the ring (frame): a monotone cell has exactly two.
int crossings(const geo::Ring& r, double y) {
    int n = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const Vec2 &a = r[i], &b = r[(i + 1) % r.size()];
        if ((a.y() > y) != (b.y() > y))
            ++n;
    }
    return n;
}

// The cells tile the free space: their areas add up to its area, their union is it (no overlap, no gap).
void expectExactCover(const geo::MultiPolygon& space, const std::vector<geo::Polygon>& cells, const std::string& what) {
    const double a = geo::area(space);
    double sum = 0;
    for (const auto& c : cells)
        sum += geo::area(c);
    EXPECT_NEAR(sum, a, 1e-6 * a + 1e-6) << what << ": cell areas do not add up to the free space";
    const geo::MultiPolygon u = geo::unite(geo::MultiPolygon(cells.begin(), cells.end()));
    EXPECT_NEAR(geo::area(u), sum, 1e-5 * a + 1e-6) << what << ": cells overlap";
    EXPECT_LT(geo::area(geo::difference(space, u)), 1e-5 * a + 1e-6) << what << ": cells leave a gap";
}

} // namespace

TEST(SweepFrame, RoundTrip) {
    const SweepFrame f{0.7};
    const Vec2 p(123.4, -56.7);
    const Vec2 q = f.toFrame(p);
    EXPECT_NEAR((f.toWorld(q) - p).norm(), 0.0, 1e-9);
    // the lane direction becomes the frame's x axis
    const Vec2 u(std::cos(0.7), std::sin(0.7));
    EXPECT_NEAR(f.toFrame(u).y(), 0.0, 1e-12);
    EXPECT_NEAR(f.toFrame(u).x(), 1.0, 1e-12);
}

// A square with a square hole: below, beside (two cells) and above the hole; merging joins the one
// below, one beside and the one above into a C-shaped cell (still one interval per line), the other
// side stays alone.
TEST(Decomposition, SquareWithAHole) {
    geo::Polygon p = sweeptest::rect(0, 0, 100, 100);
    p.holes.push_back({Vec2(40, 30), Vec2(40, 60), Vec2(70, 60), Vec2(70, 30)});
    auto d = decompose({p}, SweepFrame{0.0});
    ASSERT_TRUE(d.ok()) << d.error().message;
    ASSERT_EQ(d->cells.size(), 4u);
    std::vector<geo::Polygon> cells;
    for (const auto& c : d->cells)
        cells.push_back(world(*d, c.ring()));
    expectExactCover({p}, cells, "square with a hole");
    // the cell below the hole ends at its bottom, with the hole's bottom edge lying flat on its top
    int below = -1;
    for (std::size_t i = 0; i < d->cells.size(); ++i)
        if (d->cells[i].ylo == 0.0)
            below = static_cast<int>(i);
    ASSERT_GE(below, 0);
    EXPECT_DOUBLE_EQ(d->cells[static_cast<std::size_t>(below)].yhi, 30.0);
    EXPECT_EQ(d->cells[static_cast<std::size_t>(below)].above.size(), 2u);
    ASSERT_EQ(d->cells[static_cast<std::size_t>(below)].topContacts.size(), 1u);
    EXPECT_DOUBLE_EQ(d->cells[static_cast<std::size_t>(below)].topContacts[0].first, 40.0);
    EXPECT_DOUBLE_EQ(d->cells[static_cast<std::size_t>(below)].topContacts[0].second, 70.0);
    const auto merged = mergeCells(*d);
    ASSERT_EQ(merged.size(), 2u);
    std::vector<geo::Polygon> mcells;
    for (const auto& m : merged)
        mcells.push_back(world(*d, mergedRing(*d, m)));
    expectExactCover({p}, mcells, "merged");
}

// Edges parallel to the lanes (a rectilinear site swept along its sides) and every other direction.
TEST(Decomposition, RectilinearSitesAlongTheirSides) {
    geo::Polygon u; // a U
    u.outer = {Vec2(0, 0), Vec2(300, 0), Vec2(300, 200), Vec2(200, 200), Vec2(200, 80), Vec2(100, 80), Vec2(100, 200), Vec2(0, 200)};
    for (double deg : {0.0, 90.0, 45.0, 13.0}) {
        auto d = decompose({u}, SweepFrame{deg * M_PI / 180});
        ASSERT_TRUE(d.ok()) << deg << ": " << d.error().message;
        std::vector<geo::Polygon> cells;
        for (const auto& c : d->cells)
            cells.push_back(world(*d, c.ring()));
        expectExactCover({u}, cells, "U at " + std::to_string(deg));
    }
    // along its sides the U is a bottom cell and two arms; merged, one arm joins the bottom
    auto d = decompose({u}, SweepFrame{0.0});
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->cells.size(), 3u);
    EXPECT_EQ(mergeCells(*d).size(), 2u);
}

// The test: on many seeded areas (rectangles, rectilinear and polygonal sites, 0-20 zones with
// close pairs, U shapes and pockets) and several directions, the cells cover the free polygon exactly,
// each meets every line along the lanes in one interval, and so do the merged cells.
TEST(Decomposition, CellsCoverGeneratedAreasExactly) {
    int checked = 0;
    for (unsigned seed = 1; seed <= 24; ++seed) {
        const auto area = sweeptest::generateArea(seed, static_cast<int>(seed % 21));
        const geo::MultiPolygon space = freeSpace(area);
        for (double deg : {0.0, 33.0, 90.0, 137.0}) {
            const std::string what = area.name + " at " + std::to_string(static_cast<int>(deg)) + " deg";
            auto d = decompose(space, SweepFrame{deg * M_PI / 180});
            ASSERT_TRUE(d.ok()) << what << ": " << d.error().message;
            std::vector<geo::Polygon> cells;
            for (const auto& c : d->cells) {
                cells.push_back(world(*d, c.ring()));
                EXPECT_GT(c.yhi, c.ylo) << what;
                for (int k = 1; k < 8; ++k) {
                    const double y = c.ylo + (c.yhi - c.ylo) * k / 8.0;
                    EXPECT_EQ(crossings(c.ring(), y), 2) << what << ": a cell meets a lane's line more than once";
                    EXPECT_LE(c.xLeft(y), c.xRight(y) + 1e-9) << what;
                }
            }
            expectExactCover(space, cells, what);
            const auto merged = mergeCells(*d);
            EXPECT_LE(merged.size(), d->cells.size());
            std::vector<geo::Polygon> mcells;
            for (const auto& m : merged) {
                const geo::Ring r = mergedRing(*d, m);
                mcells.push_back(world(*d, r));
                // consecutive parts share a cut
                for (std::size_t i = 1; i < m.parts.size(); ++i)
                    EXPECT_DOUBLE_EQ(d->cells[static_cast<std::size_t>(m.parts[i - 1])].yhi,
                                     d->cells[static_cast<std::size_t>(m.parts[i])].ylo)
                        << what;
                const double ylo = d->cells[static_cast<std::size_t>(m.parts.front())].ylo;
                const double yhi = d->cells[static_cast<std::size_t>(m.parts.back())].yhi;
                for (int k = 1; k < 16; ++k) {
                    const double y = ylo + (yhi - ylo) * (k + 0.37) / 17.0;
                    EXPECT_EQ(crossings(r, y), 2) << what << ": a merged cell meets a lane's line more than once";
                }
            }
            expectExactCover(space, mcells, what + " merged");
            ++checked;
        }
    }
    EXPECT_EQ(checked, 96);
}

namespace {

// What placeSharedLines is asked to minimise in the planner: flying a line's length at 10 m/s plus
// 3 U-turns of 8 s for every lane it becomes.
double lineCostS(double lengthM, int runs) {
    return lengthM / 10.0 + 3.0 * 8.0 * runs;
}

// The lines' promises: increasing, at most a spacing apart, the outer ones within half a spacing of
// the free space's bottom and top.
void expectLinesReachEverywhere(const Decomposition& d, const std::vector<double>& ys, double s,
                                const std::string& what) {
    ASSERT_FALSE(ys.empty()) << what;
    double ymin = 1e300, ymax = -1e300;
    for (const auto& c : d.cells) {
        ymin = std::min(ymin, c.ylo);
        ymax = std::max(ymax, c.yhi);
    }
    EXPECT_LE(ys.front(), ymin + 0.5 * s) << what;
    EXPECT_GE(ys.back(), ymax - 0.5 * s) << what;
    for (std::size_t i = 1; i < ys.size(); ++i) {
        EXPECT_GT(ys[i], ys[i - 1]) << what;
        EXPECT_LE(ys[i] - ys[i - 1], s + 1e-9)
            << what << ": a gap wider than the spacing between lines " << i - 1 << " and " << i;
    }
}

// How many cells the line at y crosses (the lanes it becomes).
int runsAt(const Decomposition& d, double y) {
    int n = 0;
    for (const auto& c : d.cells)
        if (c.ylo < y && y < c.yhi)
            ++n;
    return n;
}

} // namespace

// A zone lower than a spacing lies between two placed lines (one just under it, one just over it):
// no line is cut in two by it, and no more lines are flown than the evenly spaced ones need.
TEST(SharedLines, ThreadAZoneLowerThanASpacing) {
    const double s = 27.7;
    geo::Polygon p = sweeptest::rect(0, 0, 300, 200);
    p.holes.push_back({Vec2(100, 91), Vec2(100, 111), Vec2(130, 111), Vec2(130, 91)});
    auto d = decompose({p}, SweepFrame{0.0});
    ASSERT_TRUE(d.ok()) << d.error().message;
    const std::vector<double> ys = placeSharedLines(*d, s, lineCostS);
    expectLinesReachEverywhere(*d, ys, s, "rectangle with a zone");
    for (double y : ys) {
        EXPECT_FALSE(y > 91.0 && y < 111.0) << "the line at " << y << " m is cut by the zone";
        EXPECT_EQ(runsAt(*d, y), 1) << y;
    }
    // the evenly spaced lines from the bottom need as many lines (the top one beyond the area), and
    // one of them is cut by the zone
    const std::vector<double> even = latticeLines(0.5 * s - 0.02, s, 0.0, 200.0);
    int evenNeeded = 0, evenCut = 0;
    for (double y : even)
        if (y >= 0.5 * s - 0.03 && y - s < 200.0 - 0.5 * s) {
            ++evenNeeded;
            evenCut += runsAt(*d, y) > 1 ? 1 : 0;
        }
    EXPECT_LE(static_cast<int>(ys.size()), evenNeeded);
    EXPECT_EQ(evenCut, 1) << "the evenly spaced lines should cross the zone in this layout";
}

// A zone higher than a spacing cuts lines whatever their placement: the placed lines then cut no
// more of them than needed (the zone's height over the spacing, rounded up, at most one more).
TEST(SharedLines, ATallZoneCutsTheFewestLines) {
    const double s = 27.7;
    geo::Polygon p = sweeptest::rect(0, 0, 300, 200);
    p.holes.push_back({Vec2(100, 60), Vec2(100, 130), Vec2(130, 130), Vec2(130, 60)});
    auto d = decompose({p}, SweepFrame{0.0});
    ASSERT_TRUE(d.ok()) << d.error().message;
    const std::vector<double> ys = placeSharedLines(*d, s, lineCostS);
    expectLinesReachEverywhere(*d, ys, s, "rectangle with a tall zone");
    int cut = 0;
    for (double y : ys)
        cut += runsAt(*d, y) > 1 ? 1 : 0;
    EXPECT_EQ(cut, static_cast<int>(std::floor(70.0 / s)))
        << "70 m of zone between lines at most s apart";
}

// On generated areas and directions the placed lines keep their promises and are deterministic.
TEST(SharedLines, ReachTheWholeFreeSpaceOnGeneratedAreas) {
    const double s = 27.7;
    for (unsigned seed = 1; seed <= 16; ++seed) {
        const auto area = sweeptest::generateArea(seed, static_cast<int>(seed % 21));
        const geo::MultiPolygon space = freeSpace(area);
        for (double deg : {0.0, 61.0, 137.0}) {
            const std::string what =
                area.name + " at " + std::to_string(static_cast<int>(deg)) + " deg";
            auto d = decompose(space, SweepFrame{deg * M_PI / 180});
            ASSERT_TRUE(d.ok()) << what << ": " << d.error().message;
            const std::vector<double> ys = placeSharedLines(*d, s, lineCostS);
            expectLinesReachEverywhere(*d, ys, s, what);
            EXPECT_EQ(ys, placeSharedLines(*d, s, lineCostS)) << what;
        }
    }
}
