#include "core/plan/grid/wavefront_planner.h"

#include "core/plan/metrics.h"
#include "tests/core/plan/plan_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace pf::plan {
namespace {

TEST(Wavefront, NavigationFunction) {
    const grid::Grid g = test::drawGrid({
        "...",
        ".#.",
        "...",
    });
    const auto four = navigationFunction(g, g.index(0, 0), false);
    EXPECT_EQ(four[g.index(0, 0)], 1);
    EXPECT_EQ(four[g.index(2, 2)], 5);
    EXPECT_EQ(four[g.index(1, 1)], 0); // not visitable
    const auto eight = navigationFunction(g, g.index(0, 0), true);
    // (0,0) -> (1,0) -> (2,1) -> (2,2): three moves, the diagonal through the hole being impossible.
    EXPECT_EQ(eight[g.index(2, 2)], 4);
    EXPECT_EQ(eight[g.index(1, 0)], 2);
}

TEST(Wavefront, KeepsTheMinimumTimeCandidate) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        const grid::Grid g = test::randomShape(test::Shape::Concave, seed, 16, 12);
        for (bool moore : {false, true}) {
            WavefrontOptions opt;
            opt.moore = moore;
            opt.maxCandidates = 6;
            WavefrontTrace trace;
            auto p = planWavefront(g, {}, opt, &trace);
            ASSERT_TRUE(p.ok());
            std::vector<int> sizes;
            test::freeComponents(g, std::vector<std::uint8_t>(static_cast<std::size_t>(g.cellCount()), 0), &sizes);
            test::expectValidCoverage(g, *p, moore, static_cast<int>(sizes.size()) - 1,
                                      "wavefront seed " + std::to_string(seed));
            ASSERT_FALSE(trace.candidateTimes.empty());
            EXPECT_LE(trace.candidateTimes.size(), 6u);
            const auto minIt = std::min_element(trace.candidateTimes.begin(), trace.candidateTimes.end());
            EXPECT_DOUBLE_EQ(trace.candidateTimes[trace.chosen], *minIt);
            MetricsOptions mo;
            mo.diagonalSteps = moore;
            mo.time = opt.time;
            mo.turnLowerBound = false;
            EXPECT_NEAR(computeMetrics(g, *p, mo).estimatedTimeS, *minIt, 1e-9);
            if (trace.tiePoints > 0) {
                EXPECT_GE(trace.candidateTimes.size(), 2u);
            }
        }
    }
}

TEST(Wavefront, EndsNearTheGoal) {
    std::vector<std::uint8_t> mask(12 * 8, 1);
    const grid::Grid g = grid::Grid::fromMask(12, 8, mask);
    CoverageRequest req;
    req.start = g.index(0, 0);
    req.landing = g.index(11, 7);
    auto p = planWavefront(g, req, {});
    ASSERT_TRUE(p.ok());
    test::expectValidCoverage(g, *p, true, 0, "goal");
    EXPECT_EQ(p->cells.back(), req.landing);
}

TEST(Wavefront, RejectsZeroCandidates) {
    std::vector<std::uint8_t> mask(4, 1);
    const grid::Grid g = grid::Grid::fromMask(2, 2, mask);
    WavefrontOptions opt;
    opt.maxCandidates = 0;
    auto p = planWavefront(g, {}, opt);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().message, "the wavefront planner needs at least one candidate path (got 0)");
}

} // namespace
} // namespace pf::plan
