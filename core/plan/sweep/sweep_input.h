// The sweep planner's input checks: the errors planSweep returns for bad options or an unusable
// region, each naming the problem. Internal to the sweep planner.
#pragma once

#include "core/geo/no_fly_field.h"
#include "core/geo/types.h"
#include "core/plan/sweep/sweep_planner.h"
#include "core/result.h"

#include <optional>

namespace pf::plan::sweep_detail {

// InvalidInput for spacings not positive, a negative footprint side or margin, a time model without
// speed or turn rate, a bad direction step / planned directions / margin segments / order rounds;
// InvalidGeometry for an empty, invalid or zero-area region.
Status checkSweepInput(const geo::MultiPolygon& region, const SweepOptions& opt);

// NoPath when the home or the landing point lies within a zone's safety margin (`field`).
Status checkSweepEnds(const geo::NoFlyField& field, const std::optional<geo::Vec2>& home,
                      const std::optional<geo::Vec2>& landing, double safetyMarginM);

} // namespace pf::plan::sweep_detail
