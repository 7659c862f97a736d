#include "core/plan/flight_time.h"

#include <algorithm>
#include <cmath>

namespace pf::plan {

double FlightTimeModel::stopCostS() const {
    if (!(accelerationMps2 > 0) || !std::isfinite(accelerationMps2))
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

double turnCostS(double thetaDeg, const FlightTimeModel& model) {
    if (!(thetaDeg > kTurnThresholdDeg))
        return model.turnRateDegS > 0 ? thetaDeg / model.turnRateDegS : 0.0;
    return thetaDeg / model.turnRateDegS + model.stopCostS();
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
    if (len == 0.0) {
        m_t.lengthM += std::fabs(dz); // a vertical leg: no direction, no turn
        return;
    }
    const geo::Vec2 dir = d / len;
    if (m_prevDir.squaredNorm() > 0) {
        const double cross = m_prevDir.x() * dir.y() - m_prevDir.y() * dir.x();
        const double theta = std::atan2(std::fabs(cross), m_prevDir.dot(dir)) * 180.0 / M_PI;
        m_t.turnAngleDeg += theta;
        if (theta > kTurnThresholdDeg)
            ++m_t.turns;
    }
    m_t.lengthM += dz == 0.0 ? len : std::hypot(len, dz);
    m_prevDir = dir;
    m_last = p;
}

FlightTime FlightTimeAccumulator::result() const {
    FlightTime t = m_t;
    t.straightS = m_model.speedMps > 0 ? t.lengthM / m_model.speedMps : 0.0;
    t.turnS = m_model.turnRateDegS > 0 ? t.turnAngleDeg / m_model.turnRateDegS : 0.0;
    t.stopS = t.lengthM > 0 ? (t.turns + 1) * m_model.stopCostS() : 0.0;
    t.totalS = t.straightS + t.turnS + t.stopS;
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
