#include "core/io/wpml/wpml_enums.h"

namespace pf::io::wpml {

// DJI Cloud API documentation, "DJI WPML > Common Elements" (wpml:droneInfo: "89 (M350 RTK), 60
// (M300 RTK), 67 (M30/M30T), 77 (M3E/M3T/M3M), 91 (M3D/M3TD)", the sub-types "0 (M30), 1 (M30T)",
// "0 (M3E), 1 (M3T), 2 (M3M)", "0 (M3D), 1 (M3TD)") and "Product Support" ("Enumeration Values of
// Aircraft, RC and Dock"), which from Cloud API v1.14 also lists the DJI Matrice 4E/4T as type 99,
// sub-types 0 and 1.
// Pages: https://developer.dji.com/doc/cloud-api-tutorial/en/api-reference/dji-wpml/common-element.html
// and https://developer.dji.com/doc/cloud-api-tutorial/en/overview/product-support.html (the
// "Product Table": 0-89-0 Matrice 350 RTK, 0-60-0 Matrice 300 RTK, 0-67-0 / 0-67-1 Matrice 30 /
// 30T, 0-77-0 / 1 / 2 Mavic 3E / 3T / 3M, 0-91-0 / 1 Matrice 3D / 3TD). The Matrice 4E/4T rows
// (99) are on the current page only; the WPML element tables name M4E/M4T as supported aircraft.
const std::vector<DroneType>& droneTypes() {
    static const std::vector<DroneType> kTypes{
        {89, 0, "DJI Matrice 350 RTK"},
        {60, 0, "DJI Matrice 300 RTK"},
        {67, 0, "DJI Matrice 30"},
        {67, 1, "DJI Matrice 30T"},
        {77, 0, "DJI Mavic 3 Enterprise"},
        {77, 1, "DJI Mavic 3 Thermal"},
        {77, 2, "DJI Mavic 3 Multispectral"},
        {91, 0, "DJI Matrice 3D"},
        {91, 1, "DJI Matrice 3TD"},
        {99, 0, "DJI Matrice 4E"},
        {99, 1, "DJI Matrice 4T"},
    };
    return kTypes;
}

// "Common Elements", wpml:payloadEnumValue: "42 (H20), 43 (H20T), 52 (M30), 53 (M30T), 61 (H20N),
// 66 (Mavic 3E Camera), 67 (Mavic 3T Camera), 68 (Mavic 3M Camera), 80 (Matrice 3D Camera), 81
// (Matrice 3TD Camera), 65534 (PSDK Payload Device), 82 (H30), 83 (H30T)"; the payload type is the
// "type" of the camera's "type-subtype-gimbalindex" in "Product Support", which lists the Matrice
// 4E/4T cameras as 88 and 89; the Zenmuse P1 is type 50 in DJI's Cloud API device types (the
// Cloud API SDK's DeviceTypeEnum, P1(50)) and in the Payload SDK's E_DjiCameraType
// (DJI_CAMERA_TYPE_P1 = 50), whose camera numbers are the Cloud API's (H20 42, H20T 43, H20N 61,
// M30 52, M30T 53, M3E 66, M3T 67).
// The lens (wpml:imageFormat: "wide", "zoom", "ir", "narrow_band", "visible"): the wide camera of
// the multi-camera payloads, "visible" for the single-sensor P1 and the Mavic 3M's RGB camera.
const std::vector<PayloadType>& payloadTypes() {
    static const std::vector<PayloadType> kTypes{
        {42, "Zenmuse H20", "wide"},        {43, "Zenmuse H20T", "wide"},
        {50, "Zenmuse P1", "visible"},      {52, "Matrice 30 camera", "wide"},
        {53, "Matrice 30T camera", "wide"}, {61, "Zenmuse H20N", "wide"},
        {66, "Mavic 3E camera", "wide"},    {67, "Mavic 3T camera", "wide"},
        {68, "Mavic 3M camera", "visible"}, {80, "Matrice 3D camera", "wide"},
        {81, "Matrice 3TD camera", "wide"}, {82, "Zenmuse H30", "wide"},
        {83, "Zenmuse H30T", "wide"},       {88, "Matrice 4E camera", "wide"},
        {89, "Matrice 4T camera", "wide"},  {65534, "PSDK payload", "visible"},
    };
    return kTypes;
}

const DroneType* findDroneType(int droneEnum, int subEnum) {
    for (const auto& d : droneTypes())
        if (d.droneEnum == droneEnum && d.subEnum == subEnum)
            return &d;
    return nullptr;
}

const PayloadType* findPayloadType(int payloadEnum) {
    for (const auto& p : payloadTypes())
        if (p.payloadEnum == payloadEnum)
            return &p;
    return nullptr;
}

} // namespace pf::io::wpml
