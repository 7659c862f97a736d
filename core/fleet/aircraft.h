// Aircraft specifications from the catalog.
#pragma once

#include "core/plan/flight_time.h"

#include <optional>
#include <string>

namespace pf::fleet {

// The aircraft type a DJI WPML mission declares (wpml:droneInfo): droneEnumValue and
// droneSubEnumValue from the enumeration values of DJI's Cloud API ("Product Support"), e.g. 67/1
// for the Matrice 30T. Only DJI Enterprise aircraft that fly WPML routes have one.
struct DjiDroneType {
    int droneEnum = 0;
    int subEnum = 0;
    friend bool operator==(const DjiDroneType& a, const DjiDroneType& b) {
        return a.droneEnum == b.droneEnum && a.subEnum == b.subEnum;
    }
    friend bool operator!=(const DjiDroneType& a, const DjiDroneType& b) { return !(a == b); }
};

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
    std::optional<DjiDroneType> dji; // the WPML drone type of a DJI Enterprise aircraft
    friend bool operator==(const AircraftSpec& a, const AircraftSpec& b) {
        return a.name == b.name && a.cruiseSpeedMps == b.cruiseSpeedMps &&
               a.turnRateDegS == b.turnRateDegS && a.accelerationMps2 == b.accelerationMps2 &&
               a.enduranceMin == b.enduranceMin && a.maxAltitudeM == b.maxAltitudeM &&
               a.defaultCamera == b.defaultCamera && a.notes == b.notes && a.dji == b.dji;
    }
};

} // namespace pf::fleet
