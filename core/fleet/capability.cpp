#include "core/fleet/capability.h"

#include <algorithm>
#include <cmath>

namespace pf::fleet {

double areaRateM2PerS(const Capability& c, double trackLengthM) {
    const double w = c.footprint.acrossM;
    const double v = c.time.speedMps;
    if (!(w > 0) || !(v > 0) || !(c.time.turnRateDegS > 0) || !(trackLengthM > 0))
        return 0.0;
    const double trackTime = trackLengthM / v;
    const double turnTime = 180.0 / c.time.turnRateDegS + 2.0 * c.time.stopCostS() + w / v;
    return w * trackLengthM / (trackTime + turnTime);
}

Result<std::vector<double>> capabilityShares(const std::vector<Capability>& fleet, double areaM2) {
    if (fleet.empty())
        return makeError(ErrorCode::InvalidInput, "No aircraft to share the area between.");
    if (!(areaM2 > 0))
        return makeError(ErrorCode::InvalidInput, "The area to share has no surface.");
    const double track = std::sqrt(areaM2);
    std::vector<double> rates;
    double sum = 0;
    for (const auto& c : fleet) {
        // Named as every message names an aircraft (mission/aircraft_naming.h: aircraftLabel).
        const std::string who = c.name.empty() ? std::string("The aircraft") : c.name;
        if (!(c.footprint.acrossM > 0) || !(c.footprint.alongM > 0))
            return makeError(ErrorCode::InvalidInput,
                             who + " has no usable camera footprint (check altitude and overlap).");
        if (!(c.time.speedMps > 0))
            return makeError(ErrorCode::InvalidInput,
                             who + " has a cruise speed that is not positive.");
        if (!(c.time.turnRateDegS > 0))
            return makeError(ErrorCode::InvalidInput,
                             who + " has a turn rate that is not positive.");
        rates.push_back(areaRateM2PerS(c, track));
        sum += rates.back();
    }
    for (auto& r : rates)
        r /= sum;
    return rates;
}

double aircraftCellSize(const sensor::EffectiveFootprint& fp) { return std::max(fp.acrossM, fp.alongM); }

Result<double> baseCellSize(const std::vector<double>& sizes, double areaM2, double maxCells) {
    if (sizes.empty())
        return makeError(ErrorCode::InvalidInput, "No aircraft cell sizes to derive the base grid from.");
    for (double s : sizes)
        if (!(s > 0) || !std::isfinite(s))
            return makeError(ErrorCode::InvalidInput, "An aircraft cell size is not a positive number of metres.");
    double s = *std::min_element(sizes.begin(), sizes.end());
    if (areaM2 > 0 && maxCells > 0 && areaM2 / (s * s) > maxCells)
        s = std::sqrt(areaM2 / maxCells);
    return s;
}

} // namespace pf::fleet
