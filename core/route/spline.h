// Clamped cubic splines over Lee's centripetal parameterisation (paper 004), solved as a
// tridiagonal system.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"

#include <Eigen/Core>

#include <vector>

namespace pf::route {

// Solves a tridiagonal system with the Thomas algorithm. `sub[i]` multiplies x[i-1] in row i
// (sub[0] unused), `diag[i]` x[i], `sup[i]` x[i+1] (last unused). The systems built here are
// strictly diagonally dominant, for which the elimination without pivoting is stable.
Eigen::VectorXd solveTridiagonal(const Eigen::VectorXd& sub, const Eigen::VectorXd& diag,
                                 const Eigen::VectorXd& sup, const Eigen::VectorXd& rhs);

// Lee's centripetal knots: t0 = 0, t(i+1) = t(i) + |P(i+1) - P(i)|^0.5. Coincident points give
// repeated knots; callers merge them first.
std::vector<double> centripetalKnots(const std::vector<geo::Vec2>& points);

// A cubic spline y(t) through (t_i, y_i) with given first derivatives at both ends (clamped). With
// both end slopes 0 the vehicle starts and stops at rest, as paper 004 asks.
class CubicSpline {
public:
    // Needs at least two knots, strictly increasing, and as many values as knots.
    static Result<CubicSpline> clamped(std::vector<double> knots, std::vector<double> values,
                                       double startSlope = 0.0, double endSlope = 0.0);

    double value(double t) const;
    double derivative(double t) const;
    double secondDerivative(double t) const;

    const std::vector<double>& knots() const { return m_t; }
    double startParam() const { return m_t.front(); }
    double endParam() const { return m_t.back(); }

private:
    CubicSpline() = default;
    std::size_t segmentOf(double t) const;
    std::vector<double> m_t;
    std::vector<double> m_y;
    Eigen::VectorXd m_m; // second derivatives at the knots
};

} // namespace pf::route
