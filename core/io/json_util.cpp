#include "core/io/json_util.h"

#include <charconv>
#include <string>

namespace pf::io::detail {

CPLJSONObject jsonNumber(double v) {
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf - 3, v);
    std::string text(buf, res.ptr);
    if (text.find_first_of(".eEn") == std::string::npos)
        text += ".0"; // stays a double: large integral values would not fit json-c's int64
    CPLJSONDocument doc;
    doc.LoadMemory("[" + text + "]"); // a bare number at the end of input is "incomplete" to json-c
    return doc.GetRoot().ToArray()[0];
}

CPLJSONObject cameraToJson(const sensor::Camera& c) {
    CPLJSONObject o;
    o.Add("name", c.name);
    if (c.sensorWidthMm != 0.0 || c.sensorHeightMm != 0.0 || c.focalLengthMm != 0.0) {
        o.Add("sensor_width_mm", jsonNumber(c.sensorWidthMm));
        o.Add("sensor_height_mm", jsonNumber(c.sensorHeightMm));
        o.Add("focal_length_mm", jsonNumber(c.focalLengthMm));
    }
    if (c.hfovDeg != 0.0 || c.vfovDeg != 0.0) {
        o.Add("hfov_deg", jsonNumber(c.hfovDeg));
        o.Add("vfov_deg", jsonNumber(c.vfovDeg));
    }
    o.Add("image_width_px", c.imageWidthPx);
    o.Add("image_height_px", c.imageHeightPx);
    return o;
}

CPLJSONObject planeToJson(const fleet::PlanePerformance& p) {
    CPLJSONObject o;
    if (p.minTurnRadiusM)
        o.Add("turn_radius_m", jsonNumber(*p.minTurnRadiusM));
    if (p.maxBankDeg)
        o.Add("bank_deg", jsonNumber(*p.maxBankDeg));
    o.Add("climb_rate_mps", jsonNumber(p.climbRateMps));
    o.Add("sink_rate_mps", jsonNumber(p.sinkRateMps));
    o.Add("run_in_m", jsonNumber(p.runInM));
    if (p.stallSpeedMps)
        o.Add("stall_speed_mps", jsonNumber(*p.stallSpeedMps));
    return o;
}

} // namespace pf::io::detail
