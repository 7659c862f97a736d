#include "core/plan/flight_time.h"

#include <algorithm>
#include <cmath>

namespace pf::plan {

double FlightTimeModel::stopCostS() const {
    if (fixedWing() || !(accelerationMps2 > 0) || !std::isfinite(accelerationMps2))
        return 0.0;
    return speedMps / accelerationMps2;
}

double turnAngleDeg(const geo::Vec2& a, const geo::Vec2& b, const geo::Vec2& c) {
    const geo::Vec2 u = b - a, v = c - b;
    const double nu = u.norm(), nv = v.norm();
    if (nu == 0.0 || nv == 0.0)
        return 0.0;
    const double cross = u.x() * v.y() - u.y() * v.x();
    const double dot = u.dot(v);
    return std::atan2(std::fabs(cross), dot) * 180.0 / M_PI;
}

bool isStopCorner(double thetaDeg, const FlightTimeModel& model) {
    return !model.fixedWing() && thetaDeg > kStopCornerDeg;
}

double cornerSpeedMps(double thetaDeg, const FlightTimeModel& model) {
    const double v = model.speedMps;
    if (model.fixedWing() || !(thetaDeg > kTurnThresholdDeg))
        return v;
    if (isStopCorner(thetaDeg, model))
        return 0.0;
    // The circle tangent to both legs cornerCutM from the waypoint: r = d / tan(theta / 2).
    const double r = model.cornerCutM / std::tan(thetaDeg * M_PI / 360.0);
    const double omega = model.turnRateDegS * M_PI / 180.0;
    double vc = v;
    if (std::isfinite(model.accelerationMps2))
        vc = std::min(vc, std::sqrt(std::max(0.0, model.accelerationMps2 * r)));
    if (omega > 0)
        vc = std::min(vc, omega * r);
    return std::max(0.0, vc);
}

double turnCostS(double thetaDeg, const FlightTimeModel& model) {
    // Up to kTurnThresholdDeg a heading change is a straight line (a lane's photos up to rounding).
    if (model.fixedWing() || !(thetaDeg > kTurnThresholdDeg))
        return 0.0;
    if (isStopCorner(thetaDeg, model))
        return (model.turnRateDegS > 0 ? thetaDeg / model.turnRateDegS : 0.0) + model.stopCostS() +
               model.stopHoldS;
    const double a = model.accelerationMps2, v = model.speedMps;
    if (!(a > 0) || !std::isfinite(a) || !(v > 0))
        return 0.0;
    const double dv = v - cornerSpeedMps(thetaDeg, model);
    return dv * dv / (a * v);
}

void FlightTimeAccumulator::add(const geo::Vec2& p) { add(p, m_lastZ); }

void FlightTimeAccumulator::add(const geo::Vec2& p, double altitudeM) {
    const double dz = altitudeM - m_lastZ;
    m_lastZ = altitudeM;
    if (m_points++ == 0) {
        m_last = p;
        return;
    }
    const geo::Vec2 d = p - m_last;
    const double len = d.norm();
    const double len3 = dz == 0.0 ? len : std::hypot(len, dz);
    m_t.lengthM += len3;
    // A plane cannot climb faster than its climb rate: the leg then takes dz / rate, longer than
    // its length at V (counted in result()); the excess is added here.
    if (m_model.fixedWing() && dz != 0.0 && m_model.speedMps > 0) {
        const double rate = dz > 0 ? m_model.climbRateMps : m_model.sinkRateMps;
        if (rate > 0)
            m_t.straightS += std::max(0.0, std::fabs(dz) / rate - len3 / m_model.speedMps);
    }
    if (len == 0.0)
        return; // a vertical leg: no direction, no corner
    const geo::Vec2 dir = d / len;
    if (m_prevDir.squaredNorm() > 0) {
        const double cross = m_prevDir.x() * dir.y() - m_prevDir.y() * dir.x();
        const double theta = std::atan2(std::fabs(cross), m_prevDir.dot(dir)) * 180.0 / M_PI;
        m_t.turnAngleDeg += theta;
        // A plane's arc is sampled as many vertices turning one after the other: one turn.
        const bool turning = theta > kTurnThresholdDeg;
        if (turning && !(m_model.fixedWing() && m_turning))
            ++m_t.turns;
        m_turning = turning;
        if (isStopCorner(theta, m_model)) {
            ++m_t.stops;
            m_t.turnS += m_model.turnRateDegS > 0 ? theta / m_model.turnRateDegS : 0.0;
        } else {
            m_t.cornerS += turnCostS(theta, m_model);
        }
    }
    m_prevDir = dir;
    m_last = p;
}

FlightTime FlightTimeAccumulator::result() const {
    FlightTime t = m_t;
    t.straightS += m_model.speedMps > 0 ? t.lengthM / m_model.speedMps : 0.0;
    const double stop = m_model.stopCostS();
    t.stopS = m_model.fixedWing()
                  ? 0.0
                  : t.stops * (stop + m_model.stopHoldS) + (t.lengthM > 0 ? stop : 0.0);
    t.totalS = t.straightS + t.cornerS + t.turnS + t.stopS;
    return t;
}

FlightTime flightTime(const std::vector<geo::Vec2>& polyline, const FlightTimeModel& model) {
    FlightTimeAccumulator acc(model);
    for (const auto& p : polyline)
        acc.add(p);
    return acc.result();
}

FlightTime flightTime(const std::vector<geo::Vec2>& polyline, const std::vector<double>& altitudesM,
                      const FlightTimeModel& model) {
    if (altitudesM.size() != polyline.size())
        return flightTime(polyline, model);
    FlightTimeAccumulator acc(model);
    for (std::size_t i = 0; i < polyline.size(); ++i)
        acc.add(polyline[i], altitudesM[i]);
    return acc.result();
}

} // namespace pf::plan
