// The DJI aircraft and payload types a WPML mission names (wpml:droneInfo, wpml:payloadInfo), as
// DJI documents them: what the .kmz reader names a route after and what the export checks.
#pragma once

#include <string>
#include <vector>

namespace pf::io::wpml {

struct DroneType {
    int droneEnum;
    int subEnum;
    const char* name; // as the catalog names the aircraft: "DJI Matrice 30T"
};

struct PayloadType {
    int payloadEnum;
    const char* name;
    const char*
        lens; // the lens a nadir survey photo is stored from (wpml:imageFormat, payloadLensIndex)
};

const std::vector<DroneType>& droneTypes();
const std::vector<PayloadType>& payloadTypes();

// The documented drone type, or nullptr. A drone whose documentation needs no sub-type (M300 RTK,
// M350 RTK) matches sub-type 0 only.
const DroneType* findDroneType(int droneEnum, int subEnum);
const PayloadType* findPayloadType(int payloadEnum);

} // namespace pf::io::wpml
