#include "core/fleet/aircraft.h"

#include <cmath>
#include <limits>

namespace pf::fleet {

const char* aircraftKindId(AircraftKind k) {
    switch (k) {
    case AircraftKind::Multirotor:
        return "multirotor";
    case AircraftKind::FixedWing:
        return "fixed_wing";
    case AircraftKind::Vtol:
        return "vtol";
    }
    return "multirotor";
}

std::optional<AircraftKind> aircraftKindFromId(const std::string& id) {
    for (AircraftKind k : {AircraftKind::Multirotor, AircraftKind::FixedWing, AircraftKind::Vtol})
        if (id == aircraftKindId(k))
            return k;
    return std::nullopt;
}

const char* aircraftKindLabel(AircraftKind k) {
    switch (k) {
    case AircraftKind::Multirotor:
        return "multirotor";
    case AircraftKind::FixedWing:
        return "fixed-wing";
    case AircraftKind::Vtol:
        return "VTOL";
    }
    return "multirotor";
}

const char* aircraftKindIdList() {
    return "multirotor, fixed_wing or vtol";
}

double turnRadiusForBankM(double speedMps, double bankDeg) {
    const double t = std::tan(bankDeg * M_PI / 180.0);
    if (!(t > 0))
        return std::numeric_limits<double>::infinity();
    return speedMps * speedMps / (kStandardGravityMps2 * t);
}

double bankForTurnRadiusDeg(double speedMps, double radiusM) {
    if (!(radiusM > 0))
        return 90.0;
    return std::atan(speedMps * speedMps / (kStandardGravityMps2 * radiusM)) * 180.0 / M_PI;
}

double minTurnRadiusM(const PlanePerformance& p, double speedMps) {
    if (p.minTurnRadiusM)
        return *p.minTurnRadiusM;
    return turnRadiusForBankM(speedMps, p.maxBankDeg.value_or(kDefaultBankDeg));
}

double bankAngleDeg(const PlanePerformance& p, double speedMps) {
    if (p.minTurnRadiusM)
        return bankForTurnRadiusDeg(speedMps, *p.minTurnRadiusM);
    return p.maxBankDeg.value_or(kDefaultBankDeg);
}

} // namespace pf::fleet
