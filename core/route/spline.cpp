#include "core/route/spline.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pf::route {

Eigen::VectorXd solveTridiagonal(const Eigen::VectorXd& sub, const Eigen::VectorXd& diag,
                                 const Eigen::VectorXd& sup, const Eigen::VectorXd& rhs) {
    const Eigen::Index n = diag.size();
    assert(sub.size() == n && sup.size() == n && rhs.size() == n);
    if (n == 0)
        return {};
    Eigen::VectorXd c(n); // modified super-diagonal
    Eigen::VectorXd d(n); // modified right-hand side
    c[0] = sup[0] / diag[0];
    d[0] = rhs[0] / diag[0];
    for (Eigen::Index i = 1; i < n; ++i) {
        const double denom = diag[i] - sub[i] * c[i - 1];
        c[i] = i + 1 < n ? sup[i] / denom : 0.0;
        d[i] = (rhs[i] - sub[i] * d[i - 1]) / denom;
    }
    Eigen::VectorXd x(n);
    x[n - 1] = d[n - 1];
    for (Eigen::Index i = n - 2; i >= 0; --i)
        x[i] = d[i] - c[i] * x[i + 1];
    return x;
}

std::vector<double> centripetalKnots(const std::vector<geo::Vec2>& points) {
    std::vector<double> t;
    t.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        t.push_back(i == 0 ? 0.0 : t.back() + std::sqrt((points[i] - points[i - 1]).norm()));
    return t;
}

Result<CubicSpline> CubicSpline::clamped(std::vector<double> knots, std::vector<double> values,
                                         double startSlope, double endSlope) {
    if (knots.size() < 2 || knots.size() != values.size())
        return makeError(ErrorCode::InvalidInput,
                         "a spline needs at least two knots and one value per knot (got " +
                             std::to_string(knots.size()) + " knots and " +
                             std::to_string(values.size()) + " values)");
    for (std::size_t i = 1; i < knots.size(); ++i)
        if (!(knots[i] > knots[i - 1]))
            return makeError(ErrorCode::InvalidInput, "spline knots must increase strictly (knot " +
                                                          std::to_string(i) + " does not)");
    const std::size_t n = knots.size() - 1; // number of segments
    const auto N = static_cast<Eigen::Index>(n + 1);
    Eigen::VectorXd sub = Eigen::VectorXd::Zero(N), diag(N), sup = Eigen::VectorXd::Zero(N), rhs(N);
    std::vector<double> h(n), b(n);
    for (std::size_t i = 0; i < n; ++i) {
        h[i] = knots[i + 1] - knots[i];
        b[i] = (values[i + 1] - values[i]) / h[i];
    }
    // Unknowns are the second derivatives M_i. The two end rows impose S'(t0) and S'(tn) instead of
    // the natural M0 = Mn = 0: zero end slopes mean the vehicle is at rest when it starts and
    // stops.
    diag[0] = 2.0 * h[0];
    sup[0] = h[0];
    rhs[0] = 6.0 * (b[0] - startSlope);
    for (std::size_t i = 1; i < n; ++i) {
        const auto r = static_cast<Eigen::Index>(i);
        sub[r] = h[i - 1];
        diag[r] = 2.0 * (h[i - 1] + h[i]);
        sup[r] = h[i];
        rhs[r] = 6.0 * (b[i] - b[i - 1]);
    }
    sub[N - 1] = h[n - 1];
    diag[N - 1] = 2.0 * h[n - 1];
    rhs[N - 1] = 6.0 * (endSlope - b[n - 1]);

    CubicSpline s;
    s.m_m = solveTridiagonal(sub, diag, sup, rhs);
    s.m_t = std::move(knots);
    s.m_y = std::move(values);
    return s;
}

std::size_t CubicSpline::segmentOf(double t) const {
    auto it = std::upper_bound(m_t.begin(), m_t.end(), t);
    if (it == m_t.begin())
        return 0;
    const auto i = static_cast<std::size_t>(it - m_t.begin()) - 1;
    return std::min(i, m_t.size() - 2);
}

double CubicSpline::value(double t) const {
    const std::size_t i = segmentOf(t);
    const double h = m_t[i + 1] - m_t[i];
    const double a = m_t[i + 1] - t, b = t - m_t[i];
    const double mi = m_m[static_cast<Eigen::Index>(i)], mj = m_m[static_cast<Eigen::Index>(i + 1)];
    return mi * a * a * a / (6 * h) + mj * b * b * b / (6 * h) + (m_y[i] - mi * h * h / 6) * a / h +
           (m_y[i + 1] - mj * h * h / 6) * b / h;
}

double CubicSpline::derivative(double t) const {
    const std::size_t i = segmentOf(t);
    const double h = m_t[i + 1] - m_t[i];
    const double a = m_t[i + 1] - t, b = t - m_t[i];
    const double mi = m_m[static_cast<Eigen::Index>(i)], mj = m_m[static_cast<Eigen::Index>(i + 1)];
    return -mi * a * a / (2 * h) + mj * b * b / (2 * h) + (m_y[i + 1] - m_y[i]) / h -
           (mj - mi) * h / 6;
}

double CubicSpline::secondDerivative(double t) const {
    const std::size_t i = segmentOf(t);
    const double h = m_t[i + 1] - m_t[i];
    const double mi = m_m[static_cast<Eigen::Index>(i)], mj = m_m[static_cast<Eigen::Index>(i + 1)];
    return (mi * (m_t[i + 1] - t) + mj * (t - m_t[i])) / h;
}

} // namespace pf::route
