// Aircraft specifications from the catalog: the kind of aircraft and the figures its flight model
// needs.
#pragma once

#include "core/plan/flight_time.h"

#include <optional>
#include <string>

namespace pf::fleet {

// How an aircraft flies a survey. A multirotor stops and turns on the spot; a fixed-wing flies at
// its cruise speed and turns on arcs of at least its minimum turn radius; a VTOL aircraft takes off
// and lands vertically and flies the survey as a fixed-wing.
enum class AircraftKind { Multirotor, FixedWing, Vtol };

// "multirotor", "fixed_wing", "vtol": the names in the catalog and the mission file.
const char* aircraftKindId(AircraftKind k);
std::optional<AircraftKind> aircraftKindFromId(const std::string& id);
// "multirotor", "fixed-wing", "VTOL": the words for people.
const char* aircraftKindLabel(AircraftKind k);
// "multirotor, fixed_wing or vtol", for messages.
const char* aircraftKindIdList();
// Whether the survey is flown as a plane (fixed-wing, and VTOL in cruise).
inline bool fliesAsPlane(AircraftKind k) {
    return k != AircraftKind::Multirotor;
}

constexpr double kStandardGravityMps2 = 9.80665;
// Defaults for a plane whose entry gives none, from the autopilots' default parameters: the bank
// limit of ArduPlane (ROLL_LIMIT_DEG 45) and its TECS climb and sink rates (TECS_CLMB_MAX 5 m/s,
// TECS_SINK_MAX 5 m/s; PX4's FW_T_CLMB_MAX and FW_T_SINK_MAX are the same). The run-in is about
// ArduPlane's L1 distance at 12 m/s with its default tuning (NAVL1_PERIOD 17 s x NAVL1_DAMPING 0.75
// x 12 m/s / pi = 49 m), the distance over which its track settles after a turn.
constexpr double kDefaultBankDeg = 45.0;
constexpr double kDefaultClimbRateMps = 5.0;
constexpr double kDefaultSinkRateMps = 5.0;
constexpr double kDefaultRunInM = 50.0;
// A plane's cruise speed must be at least this multiple of its stall speed: banking by phi raises
// the stall speed by 1 / sqrt(cos phi), 1.19 at 45 degrees (ArduPlane's default bank limit), so a
// plane slower than this cannot fly its survey turns.
constexpr double kStallMargin = 1.2;

// What a plane (fixed-wing, or VTOL in cruise) needs beyond speed and endurance. The minimum turn
// radius is given either directly or by the bank limit phi at the cruise speed V: R = V^2 / (g tan
// phi). When both are set the radius wins (the bank is then derived from it); with neither,
// kDefaultBankDeg.
struct PlanePerformance {
    std::optional<double> minTurnRadiusM;
    std::optional<double> maxBankDeg;
    double climbRateMps = kDefaultClimbRateMps;
    double sinkRateMps = kDefaultSinkRateMps;
    double runInM = kDefaultRunInM; // straight flight before a lane's first photo
    std::optional<double> stallSpeedMps;
    friend bool operator==(const PlanePerformance& a, const PlanePerformance& b) {
        return a.minTurnRadiusM == b.minTurnRadiusM && a.maxBankDeg == b.maxBankDeg &&
               a.climbRateMps == b.climbRateMps && a.sinkRateMps == b.sinkRateMps &&
               a.runInM == b.runInM && a.stallSpeedMps == b.stallSpeedMps;
    }
    friend bool operator!=(const PlanePerformance& a, const PlanePerformance& b) {
        return !(a == b);
    }
};

// R = V^2 / (g tan phi) and back; 0 and 90 degrees give infinite and 0 radii.
double turnRadiusForBankM(double speedMps, double bankDeg);
double bankForTurnRadiusDeg(double speedMps, double radiusM);
// The plane's minimum turn radius and bank at `speedMps` (see PlanePerformance).
double minTurnRadiusM(const PlanePerformance& p, double speedMps);
double bankAngleDeg(const PlanePerformance& p, double speedMps);

struct AircraftSpec {
    std::string name;
    AircraftKind kind = AircraftKind::Multirotor;
    double cruiseSpeedMps = 10.0;
    // A multirotor's yaw rate in turns; for a plane the rate of its tightest turn, V / R (the
    // catalog may leave it out for a plane: loadCatalog derives it).
    double turnRateDegS = 90.0;
    // Horizontal acceleration for the stop at each turn (plan::FlightTimeModel); optional in the
    // catalog, where makers rarely publish it.
    double accelerationMps2 = plan::kDefaultAccelerationMps2;
    double enduranceMin = 20.0;
    double maxAltitudeM = 120.0;
    PlanePerformance plane;    // used when the kind flies as a plane
    std::string defaultCamera; // a catalog camera name
    std::string notes;         // where the figures come from
    friend bool operator==(const AircraftSpec& a, const AircraftSpec& b) {
        return a.name == b.name && a.kind == b.kind && a.cruiseSpeedMps == b.cruiseSpeedMps &&
               a.turnRateDegS == b.turnRateDegS && a.accelerationMps2 == b.accelerationMps2 &&
               a.enduranceMin == b.enduranceMin && a.maxAltitudeM == b.maxAltitudeM &&
               a.plane == b.plane && a.defaultCamera == b.defaultCamera && a.notes == b.notes;
    }
};

} // namespace pf::fleet
