#include "core/plan/sweep/sweep_input.h"

#include "core/geo/polygon_ops.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace pf::plan::sweep_detail {

namespace {

std::string fmt(double v, int decimals = 1) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

} // namespace

Status checkSweepInput(const geo::MultiPolygon& region, const SweepOptions& opt) {
    auto bad = [](const std::string& m) { return makeError(ErrorCode::InvalidInput, m); };
    if (!(opt.trackSpacingM > 0) || !std::isfinite(opt.trackSpacingM))
        return bad("The sweep's track spacing must be a positive distance (got " + fmt(opt.trackSpacingM, 3) + " m).");
    if (!(opt.photoSpacingM > 0) || !std::isfinite(opt.photoSpacingM))
        return bad("The sweep's photo spacing must be a positive distance (got " + fmt(opt.photoSpacingM, 3) + " m).");
    if (!(opt.realAcrossM >= 0) || !(opt.realAlongM >= 0) || !std::isfinite(opt.realAcrossM) || !std::isfinite(opt.realAlongM))
        return bad("The photo footprint's sides must not be negative.");
    if (!(opt.safetyMarginM >= 0) || !std::isfinite(opt.safetyMarginM))
        return bad("The safety margin must not be negative (got " + fmt(opt.safetyMarginM) + " m).");
    if (!(opt.time.speedMps > 0) || !(opt.time.turnRateDegS > 0))
        return bad("The flight-time model needs a positive speed and turn rate.");
    if (!(opt.coarseStepDeg > 0) || opt.plannedDirections < 1 || opt.quadrantSegments < 1 || opt.maxOrderRounds < 0)
        return bad("The sweep's direction step, planned directions and margin segments must be positive.");
    if (region.empty())
        return makeError(ErrorCode::InvalidGeometry, "The area to sweep is empty.");
    for (std::size_t i = 0; i < region.size(); ++i) {
        std::string why;
        if (!geo::isValid(region[i], &why))
            return makeError(ErrorCode::InvalidGeometry, "The area to sweep (part " + std::to_string(i + 1) +
                                                             ") is not a valid polygon: " + why);
    }
    if (!(geo::area(region) > 0))
        return makeError(ErrorCode::InvalidGeometry, "The area to sweep has no area.");
    return {};
}

Status checkSweepEnds(const geo::NoFlyField& field, const std::optional<geo::Vec2>& home,
                      const std::optional<geo::Vec2>& landing, double safetyMarginM) {
    for (const auto* p : {&home, &landing})
        if (*p && !field.pointIsSafe(**p))
            return makeError(ErrorCode::NoPath,
                             std::string(p == &home ? "The home point" : "The landing point") +
                                 " (" + fmt((*p)->x()) + ", " + fmt((*p)->y()) +
                                 ") m lies within the " + fmt(safetyMarginM) +
                                 " m safety margin of a no-fly zone.");
    return {};
}

} // namespace pf::plan::sweep_detail
