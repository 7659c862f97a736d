// The sweep's directions: the candidates (with the Survey's), each decomposed and ranked by the
// quick estimate, the best planned in full, each with its own lanes and its lanes on lines shared
// by all cells. Internal to the sweep planner.
#pragma once

#include "core/plan/sweep/sweep_prepare.h"
#include "core/plan/sweep/sweep_state.h"
#include "core/result.h"

#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

namespace pf::plan::sweep_detail {

struct SweepDirections {
    std::vector<double> anglesDeg;     // to estimate, degrees counter-clockwise from east
    std::vector<double> alwaysPlanned; // the Survey's directions, as angles of the candidates
    std::optional<double> surveyAngle; // the Survey's direction whose photos see the region
};

// The candidate directions (sweep_detail::candidateDirections) and the directions a Survey would
// fly over the region, which are planned in full whatever their estimate.
SweepDirections sweepDirections(const PreparedGround& g);

// Lane heights of a direction's variant (dp.heights, dp.pinned) and its quick estimate in seconds.
double estimateLanes(const PreparedGround& g, DirectionPlan& dp);

// Every direction decomposed and estimated, in the order given; Cancelled, or InvalidGeometry when
// no direction decomposes.
Result<std::vector<DirectionPlan>> estimateDirections(const PreparedGround& g,
                                                      const std::vector<double>& anglesDeg);

// Indices into dirs of the directions planned in full: the `planned` best estimated, then the
// Survey's.
std::vector<std::size_t> directionsToPlan(const std::vector<DirectionPlan>& dirs,
                                          const SweepDirections& sd, int planned);

// What is planned in full: each direction of planRank with its own lanes, followed by its variants
// on shared lines (kept in `variants`) where they may pay.
std::vector<const DirectionPlan*> laneVariants(const PreparedGround& g,
                                               const std::vector<DirectionPlan>& dirs,
                                               const std::vector<std::size_t>& planRank,
                                               std::deque<DirectionPlan>& variants);

} // namespace pf::plan::sweep_detail
