// Aircraft specifications from the catalog.
#pragma once

#include "core/plan/flight_time.h"

#include <string>

namespace pf::fleet {

struct AircraftSpec {
    std::string name;
    double cruiseSpeedMps = 10.0;
    double turnRateDegS = 90.0;
    // Horizontal acceleration for the stop at each turn (plan::FlightTimeModel); optional in the
    // catalog, where makers rarely publish it.
    double accelerationMps2 = plan::kDefaultAccelerationMps2;
    double enduranceMin = 20.0;
    double maxAltitudeM = 120.0;
    std::string defaultCamera; // a catalog camera name
    std::string notes;         // where the figures come from
    friend bool operator==(const AircraftSpec& a, const AircraftSpec& b) {
        return a.name == b.name && a.cruiseSpeedMps == b.cruiseSpeedMps && a.turnRateDegS == b.turnRateDegS &&
               a.accelerationMps2 == b.accelerationMps2 &&
               a.enduranceMin == b.enduranceMin && a.maxAltitudeM == b.maxAltitudeM &&
               a.defaultCamera == b.defaultCamera && a.notes == b.notes;
    }
};

} // namespace pf::fleet
