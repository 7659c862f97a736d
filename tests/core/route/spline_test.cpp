#include "core/route/spline.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pf::route;

TEST(Tridiagonal, MatchesDenseSolveOnRandomDominantSystems) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        const int n = 1 + trial % 17;
        Eigen::VectorXd sub = Eigen::VectorXd::Zero(n), sup = Eigen::VectorXd::Zero(n), diag(n),
                        rhs(n);
        Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
        for (int i = 0; i < n; ++i) {
            if (i > 0)
                sub[i] = u(rng);
            if (i + 1 < n)
                sup[i] = u(rng);
            diag[i] = 2.5 + u(rng); // strictly dominant: |diag| > |sub| + |sup|
            rhs[i] = 10 * u(rng);
            A(i, i) = diag[i];
            if (i > 0)
                A(i, i - 1) = sub[i];
            if (i + 1 < n)
                A(i, i + 1) = sup[i];
        }
        const Eigen::VectorXd x = solveTridiagonal(sub, diag, sup, rhs);
        const Eigen::VectorXd ref = A.fullPivLu().solve(rhs);
        EXPECT_LT((x - ref).norm(), 1e-10 * (1 + ref.norm())) << "n = " << n;
    }
}

TEST(CentripetalKnots, SquareRootOfChordLengths) {
    const auto t = centripetalKnots({{0, 0}, {4, 0}, {4, 9}, {4, 9}});
    ASSERT_EQ(t.size(), 4u);
    EXPECT_DOUBLE_EQ(t[0], 0.0);
    EXPECT_DOUBLE_EQ(t[1], 2.0); // sqrt(4)
    EXPECT_DOUBLE_EQ(t[2], 5.0); // + sqrt(9)
    EXPECT_DOUBLE_EQ(t[3], 5.0); // coincident points repeat the knot
}

TEST(CubicSpline, InterpolatesIsAtRestAtBothEndsAndIsC2) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> step(0.2, 5.0), val(-50, 50);
    for (int trial = 0; trial < 40; ++trial) {
        const int n = 2 + trial % 12;
        std::vector<double> t{0.0}, y{val(rng)};
        for (int i = 1; i < n; ++i) {
            t.push_back(t.back() + step(rng));
            y.push_back(val(rng));
        }
        auto s = CubicSpline::clamped(t, y);
        ASSERT_TRUE(s.ok());
        for (int i = 0; i < n; ++i)
            EXPECT_NEAR(s->value(t[i]), y[i], 1e-9);
        EXPECT_NEAR(s->derivative(t.front()), 0.0, 1e-9);
        EXPECT_NEAR(s->derivative(t.back()), 0.0, 1e-9);
        const double eps = 1e-9;
        auto close = [](double a, double b) {
            return std::abs(a - b) <= 1e-5 * (1.0 + std::abs(a));
        };
        for (int i = 1; i + 1 < n; ++i) {
            // Left and right limits agree in value, slope and curvature at every interior knot.
            EXPECT_TRUE(close(s->value(t[i] - eps), s->value(t[i] + eps)));
            EXPECT_TRUE(close(s->derivative(t[i] - eps), s->derivative(t[i] + eps)));
            EXPECT_TRUE(close(s->secondDerivative(t[i] - eps), s->secondDerivative(t[i] + eps)))
                << s->secondDerivative(t[i] - eps) << " vs " << s->secondDerivative(t[i] + eps);
        }
    }
}

TEST(CubicSpline, ReproducesACubicWithMatchingEndSlopes) {
    auto f = [](double t) { return t * t * t - 2 * t * t + t + 1; };
    auto df = [](double t) { return 3 * t * t - 4 * t + 1; };
    const std::vector<double> t{-1.0, -0.3, 0.5, 1.7, 2.0, 3.2};
    std::vector<double> y;
    for (double k : t)
        y.push_back(f(k));
    auto s = CubicSpline::clamped(t, y, df(t.front()), df(t.back()));
    ASSERT_TRUE(s.ok());
    for (double k = -1.0; k <= 3.2; k += 0.05) {
        EXPECT_NEAR(s->value(k), f(k), 1e-9);
        EXPECT_NEAR(s->derivative(k), df(k), 1e-8);
    }
}

TEST(CubicSpline, TwoKnotsAtRestIsTheSmoothStep) {
    // With zero end slopes the single segment is y0 + (y1 - y0)(3u^2 - 2u^3).
    auto s = CubicSpline::clamped({0.0, 2.0}, {1.0, 5.0});
    ASSERT_TRUE(s.ok());
    for (double u = 0; u <= 1.0; u += 0.125)
        EXPECT_NEAR(s->value(2 * u), 1.0 + 4.0 * (3 * u * u - 2 * u * u * u), 1e-12);
}

TEST(CubicSpline, RejectsBadKnots) {
    auto a = CubicSpline::clamped({0.0}, {1.0});
    ASSERT_FALSE(a.ok());
    EXPECT_EQ(
        a.error().message,
        "a spline needs at least two knots and one value per knot (got 1 knots and 1 values)");
    auto b = CubicSpline::clamped({0.0, 1.0, 1.0}, {1.0, 2.0, 3.0});
    ASSERT_FALSE(b.ok());
    EXPECT_EQ(b.error().message, "spline knots must increase strictly (knot 2 does not)");
    auto c = CubicSpline::clamped({0.0, 1.0}, {1.0, 2.0, 3.0});
    EXPECT_FALSE(c.ok());
}
