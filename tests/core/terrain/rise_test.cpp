// The rise of the ground within a camera's reach (terrain::riseWithin) and its largest value over the
// area (maxRiseWithin) and along one lane (maxRiseAlong), on a small grid with one peak.
#include "core/terrain/terrain_footprint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace pf::terrain {
namespace {

// 101 x 101 nodes 1 m apart over [0, 100]^2 (row 0 at y = 100): flat at 100 m with a 10 m peak
// (a single node) at (20, 50) and no data at (80, 50).
HeightGrid peakGrid() {
    std::vector<float> h(101 * 101, 100.0f);
    h[static_cast<std::size_t>(50) * 101 + 20] = 110.0f;
    h[static_cast<std::size_t>(50) * 101 + 80] = std::numeric_limits<float>::quiet_NaN();
    return HeightGrid(0.0, 100.0, 1.0, 101, 101, std::move(h));
}

TEST(Rise, RiseWithinIsThePeakOverTheGroundWithinTheRadius) {
    const HeightGrid g = peakGrid();
    const HeightGrid r = riseWithin(g, 5.0);
    ASSERT_EQ(r.cols(), g.cols());
    ASSERT_EQ(r.rows(), g.rows());
    EXPECT_FLOAT_EQ(r.node(20, 50), 0.0f);  // the peak itself: nothing higher around
    EXPECT_FLOAT_EQ(r.node(25, 45), 10.0f); // 5 m off in both axes: within the square
    EXPECT_FLOAT_EQ(r.node(26, 50), 0.0f);  // 6 m off
    EXPECT_TRUE(std::isnan(r.node(80, 50))); // no data
    EXPECT_FLOAT_EQ(r.node(81, 50), 0.0f);  // no data is no rise
    EXPECT_DOUBLE_EQ(maxRiseWithin(g, 5.0, [](const geo::Vec2&) { return true; }), 10.0);
    EXPECT_DOUBLE_EQ(maxRiseWithin(g, 5.0, [](const geo::Vec2& p) { return p.x() > 30; }), 0.0);
    EXPECT_DOUBLE_EQ(maxRiseWithin(r, [](const geo::Vec2&) { return true; }), 10.0);
}

TEST(Rise, AlongALaneOnlyTheNodesItPassesCount) {
    const HeightGrid r = riseWithin(peakGrid(), 5.0);
    // A lane north-south through x = 24 passes within 5 m of the peak; one at x = 40 does not.
    EXPECT_DOUBLE_EQ(maxRiseAlong(r, geo::Vec2(24, 5), geo::Vec2(24, 95)), 10.0);
    EXPECT_DOUBLE_EQ(maxRiseAlong(r, geo::Vec2(40, 5), geo::Vec2(40, 95)), 0.0);
    // Between nodes the cell's four nodes count: x = 25.5 touches the nodes at x = 25.
    EXPECT_DOUBLE_EQ(maxRiseAlong(r, geo::Vec2(25.5, 40), geo::Vec2(25.5, 60)), 10.0);
    // A lane that leaves the grid is over unknown ground.
    EXPECT_TRUE(std::isinf(maxRiseAlong(r, geo::Vec2(40, 50), geo::Vec2(140, 50))));
    EXPECT_TRUE(std::isinf(maxRiseAlong(HeightGrid(), geo::Vec2(0, 0), geo::Vec2(1, 1))));
}

} // namespace
} // namespace pf::terrain
