#include "core/route/trajectory.h"

#include "core/geo/polygon_ops.h"
#include "core/route/spline.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pf::route {

namespace {

// Waypoints closer than this are one place: a zero-length leg has no centripetal knot spacing.
constexpr double kSamePlaceM = 1e-6;

double wrap180(double deg) {
    double d = std::fmod(deg, 360.0);
    if (d > 180.0)
        d -= 360.0;
    else if (d <= -180.0)
        d += 360.0;
    return d;
}

double wrap360(double deg) {
    double d = std::fmod(deg, 360.0);
    if (d < 0)
        d += 360.0;
    return d >= 360.0 ? 0.0 : d;
}

struct Knot {
    geo::Vec2 pos;
    double yaw; // unwrapped degrees
};

// One point of the unwrapped path in (x, y, yaw).
struct Point3 {
    geo::Vec2 pos;
    double yaw;
    std::size_t leg; // merged leg the sample belongs to (the one ending here)
};

class Builder {
public:
    Builder(std::vector<Knot> knots, const geo::MultiPolygon& keepOut, const TrajectoryOptions& opt)
        : m_k(std::move(knots)), m_keepOut(keepOut), m_opt(opt), m_level(legs(), 0),
          m_straight(legs(), false) {}

    std::size_t legs() const { return m_k.size() - 1; }

    // Builds, checks and refines until every curved leg stays out of the keep-out set.
    Result<std::vector<Point3>> run(std::vector<std::size_t>& unsafeLegs) {
        for (std::size_t l = 0; l < legs(); ++l)
            if (geo::segmentCrossesInterior(m_keepOut, m_k[l].pos, m_k[l + 1].pos))
                unsafeLegs.push_back(l);
        for (;;) {
            auto pts = build();
            if (!pts)
                return pts.error();
            std::vector<bool> bad(legs(), false);
            bool any = false;
            if (!m_keepOut.empty()) {
                // Most samples are nowhere near a zone: a box test spares the exact one.
                const geo::Box zoneBox = geo::bounds(m_keepOut);
                for (std::size_t i = 1; i < pts->size(); ++i) {
                    const Point3& p = (*pts)[i];
                    if (m_straight[p.leg] || bad[p.leg])
                        continue;
                    const geo::Vec2& q = (*pts)[i - 1].pos;
                    const geo::Box seg{q.cwiseMin(p.pos), q.cwiseMax(p.pos)};
                    if (!seg.intersects(zoneBox))
                        continue;
                    if (geo::segmentCrossesInterior(m_keepOut, q, p.pos)) {
                        bad[p.leg] = true;
                        any = true;
                    }
                }
            }
            if (!any)
                return pts;
            for (std::size_t l = 0; l < legs(); ++l) {
                if (!bad[l])
                    continue;
                if (m_level[l] < m_opt.maxRefinements)
                    ++m_level[l];
                else
                    m_straight[l] = true;
            }
        }
    }

    const std::vector<bool>& straight() const { return m_straight; }

private:
    Result<std::vector<Point3>> build() {
        std::vector<Point3> out{{m_k[0].pos, m_k[0].yaw, 0}};
        std::size_t l = 0;
        while (l < legs()) {
            if (m_straight[l]) {
                sampleStraight(l, out);
                ++l;
                continue;
            }
            std::size_t e = l;
            while (e < legs() && !m_straight[e])
                ++e;
            if (auto st = sampleCurve(l, e, out); !st)
                return st.error();
            l = e;
        }
        return out;
    }

    void sampleStraight(std::size_t l, std::vector<Point3>& out) const {
        const Knot& a = m_k[l];
        const Knot& b = m_k[l + 1];
        const double len = (b.pos - a.pos).norm();
        const int m = std::max(1, static_cast<int>(std::ceil(len / m_opt.spacingM - 1e-9)));
        for (int i = 1; i < m; ++i) {
            const double f = static_cast<double>(i) / m;
            out.push_back({a.pos + f * (b.pos - a.pos), a.yaw + f * (b.yaw - a.yaw), l});
        }
        out.push_back({b.pos, b.yaw, l}); // exactly the waypoint
    }

    // Slope (per unit of centripetal parameter) of the straight leg l, used to join curves to it.
    Eigen::Vector3d straightSlope(std::size_t l) const {
        const Knot& a = m_k[l];
        const Knot& b = m_k[l + 1];
        const double span = std::sqrt((b.pos - a.pos).norm());
        return Eigen::Vector3d(b.pos.x() - a.pos.x(), b.pos.y() - a.pos.y(), b.yaw - a.yaw) / span;
    }

    // One spline over the curved legs [first, last), with extra knots on refined legs.
    Status sampleCurve(std::size_t first, std::size_t last, std::vector<Point3>& out) const {
        std::vector<geo::Vec2> pos{m_k[first].pos};
        std::vector<double> yaw{m_k[first].yaw};
        std::vector<std::size_t> legOf; // leg of each knot interval
        for (std::size_t l = first; l < last; ++l) {
            const int parts = 1 << m_level[l];
            for (int i = 1; i <= parts; ++i) {
                const double f = static_cast<double>(i) / parts;
                const bool end = i == parts; // the waypoint itself, not a rounded copy
                pos.push_back(end ? m_k[l + 1].pos
                                  : geo::Vec2(m_k[l].pos + f * (m_k[l + 1].pos - m_k[l].pos)));
                yaw.push_back(end ? m_k[l + 1].yaw
                                  : m_k[l].yaw + f * (m_k[l + 1].yaw - m_k[l].yaw));
                legOf.push_back(l);
            }
        }
        const std::vector<double> t = centripetalKnots(pos);
        const Eigen::Vector3d d0 = first == 0 ? Eigen::Vector3d::Zero() : straightSlope(first - 1);
        const Eigen::Vector3d d1 = last == legs() ? Eigen::Vector3d::Zero() : straightSlope(last);
        std::vector<double> xs, ys;
        xs.reserve(pos.size());
        ys.reserve(pos.size());
        for (const auto& p : pos) {
            xs.push_back(p.x());
            ys.push_back(p.y());
        }
        auto sx = CubicSpline::clamped(t, xs, d0.x(), d1.x());
        auto sy = CubicSpline::clamped(t, ys, d0.y(), d1.y());
        auto sw = CubicSpline::clamped(t, yaw, d0.z(), d1.z());
        if (!sx || !sy || !sw)
            return makeError(ErrorCode::Internal,
                             "could not fit the trajectory spline: " + (!sx   ? sx.error()
                                                                        : !sy ? sy.error()
                                                                              : sw.error())
                                                                           .message);
        auto at = [&](double u) { return geo::Vec2(sx->value(u), sy->value(u)); };
        for (std::size_t k = 0; k + 1 < t.size(); ++k) {
            // Resample by arc length so the spacing holds even where the curve slows towards rest.
            const double chord = (pos[k + 1] - pos[k]).norm();
            const int fine =
                std::clamp(static_cast<int>(std::ceil(8.0 * chord / m_opt.spacingM)), 16, 20000);
            std::vector<double> u(fine + 1), s(fine + 1, 0.0);
            geo::Vec2 prev = pos[k];
            for (int i = 0; i <= fine; ++i) {
                u[i] = t[k] + (t[k + 1] - t[k]) * i / fine;
                const geo::Vec2 p = at(u[i]);
                if (i > 0)
                    s[i] = s[i - 1] + (p - prev).norm();
                prev = p;
            }
            const double len = s.back();
            const int m = std::max(1, static_cast<int>(std::ceil(len / m_opt.spacingM - 1e-9)));
            int j = 0;
            for (int i = 1; i <= m; ++i) {
                if (i == m) {
                    out.push_back({pos[k + 1], yaw[k + 1], legOf[k]});
                    break;
                }
                const double target = len * i / m;
                while (j < fine && s[j + 1] < target)
                    ++j;
                const double seg = s[j + 1] - s[j];
                const double f = seg > 0 ? (target - s[j]) / seg : 0.0;
                const double uu = u[j] + f * (u[j + 1] - u[j]);
                out.push_back({at(uu), sw->value(uu), legOf[k]});
            }
        }
        return {};
    }

    std::vector<Knot> m_k;
    const geo::MultiPolygon& m_keepOut;
    TrajectoryOptions m_opt;
    std::vector<int> m_level;
    std::vector<bool> m_straight;
};

} // namespace

double totalHeadingChangeDeg(const std::vector<double>& headingsDeg) {
    double sum = 0.0;
    for (std::size_t i = 1; i < headingsDeg.size(); ++i)
        sum += std::abs(wrap180(headingsDeg[i] - headingsDeg[i - 1]));
    return sum;
}

Result<Trajectory> buildTrajectory(const std::vector<LocalWaypoint>& waypoints,
                                   const geo::MultiPolygon& keepOut,
                                   const TrajectoryOptions& options) {
    if (!(options.spacingM > 0) || !std::isfinite(options.spacingM))
        return makeError(ErrorCode::InvalidInput,
                         "the trajectory sample spacing must be a positive number of metres");
    if (options.maxRefinements < 0 || options.maxRefinements > 10)
        return makeError(ErrorCode::InvalidInput,
                         "the trajectory refinement count must be between 0 and 10");
    Trajectory out;
    if (waypoints.empty())
        return out;
    for (std::size_t i = 0; i < waypoints.size(); ++i)
        if (!waypoints[i].pos.allFinite() || !std::isfinite(waypoints[i].headingDeg))
            return makeError(ErrorCode::InvalidInput,
                             "waypoint " + std::to_string(i + 1) +
                                 " has a position or heading that is not a number");

    std::vector<double> headings;
    headings.reserve(waypoints.size());
    for (const auto& w : waypoints)
        headings.push_back(w.headingDeg);
    out.headingChangeDeg = totalHeadingChangeDeg(headings);

    // Merge coincident waypoints; the merged knot departs with the last heading of the group.
    std::vector<Knot> knots;
    std::vector<std::size_t> origin; // input index of the last waypoint merged into each knot
    double unwrapped = waypoints[0].headingDeg;
    for (std::size_t i = 0; i < waypoints.size(); ++i) {
        if (i > 0)
            unwrapped += wrap180(waypoints[i].headingDeg - waypoints[i - 1].headingDeg);
        if (!knots.empty() && (waypoints[i].pos - knots.back().pos).norm() < kSamePlaceM) {
            knots.back().yaw = unwrapped;
            origin.back() = i;
            continue;
        }
        knots.push_back({waypoints[i].pos, unwrapped});
        origin.push_back(i);
    }
    out.straightLegs.assign(waypoints.size() - 1, true);
    if (knots.size() == 1) {
        out.samples.push_back({knots[0].pos, wrap360(knots[0].yaw), 0.0});
        return out;
    }

    Builder b(knots, keepOut, options);
    std::vector<std::size_t> unsafe;
    auto pts = b.run(unsafe);
    if (!pts)
        return pts.error();
    // Merged leg l runs from input waypoint origin[l] to the first input waypoint of knot l + 1.
    auto inputLeg = [&](std::size_t l) { return origin[l]; };
    for (std::size_t l = 0; l < b.legs(); ++l)
        out.straightLegs[inputLeg(l)] = b.straight()[l];
    for (std::size_t l : unsafe)
        out.unsafeLegs.push_back(inputLeg(l));

    out.samples.reserve(pts->size());
    double dist = 0.0;
    for (std::size_t i = 0; i < pts->size(); ++i) {
        if (i > 0)
            dist += ((*pts)[i].pos - (*pts)[i - 1].pos).norm();
        out.samples.push_back({(*pts)[i].pos, wrap360((*pts)[i].yaw), dist});
    }
    out.lengthM = dist;
    return out;
}

Result<Trajectory> buildTrajectory(const Route& route, const geo::LocalFrame& frame,
                                   const geo::MultiPolygon& keepOut,
                                   const TrajectoryOptions& options) {
    std::vector<LocalWaypoint> local;
    local.reserve(route.waypoints.size() + 2);
    for (const auto& w : route.waypoints)
        local.push_back({frame.toLocal(w.position), w.headingDeg, w.kind, -1});
    if (route.home && !local.empty()) {
        // Take-off and landing: no extra rotation at home, the vehicle turns on the way.
        const geo::Vec2 h = frame.toLocal(*route.home);
        local.insert(local.begin(), {h, local.front().headingDeg, WaypointKind::Transit, -1});
        local.push_back({h, local.back().headingDeg, WaypointKind::Transit, -1});
    }
    return buildTrajectory(local, keepOut, options);
}

geo::MultiPolygon keepOutZones(const std::vector<geo::GeoPolygon>& noFlyZones,
                               const geo::LocalFrame& frame, double marginM) {
    geo::MultiPolygon local;
    for (const auto& z : noFlyZones)
        local.push_back(frame.toLocal(z));
    if (local.empty())
        return local;
    return marginM > 0 ? geo::buffer(local, marginM, 16) : geo::unite(local);
}

std::vector<geo::LonLat> toGeo(const Trajectory& trajectory, const geo::LocalFrame& frame) {
    std::vector<geo::LonLat> out;
    out.reserve(trajectory.samples.size());
    for (const auto& s : trajectory.samples)
        out.push_back(frame.toGeo(s.pos));
    return out;
}

Result<FlightEstimate> estimateFlight(const Trajectory& trajectory, double speedMps,
                                      double turnRateDegS) {
    if (!(speedMps > 0) || !std::isfinite(speedMps))
        return makeError(ErrorCode::InvalidInput,
                         "the cruise speed must be positive to estimate a flight time");
    if (!(turnRateDegS > 0) || !std::isfinite(turnRateDegS))
        return makeError(ErrorCode::InvalidInput,
                         "the turn rate must be positive to estimate a flight time");
    FlightEstimate e;
    e.lengthM = trajectory.lengthM;
    e.headingChangeDeg = trajectory.headingChangeDeg;
    e.timeS = e.lengthM / speedMps + e.headingChangeDeg / turnRateDegS;
    return e;
}

} // namespace pf::route
