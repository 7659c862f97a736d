// The sweep's candidate directions and the quick estimate of each: its lanes' flight time from their
// heights alone, before any lane is built or any transition routed, to rank them. Internal to the
// sweep planner.
#pragma once

#include "core/plan/flight_time.h"
#include "core/plan/sweep/decomposition.h"
#include "core/plan/sweep/sweep_planner.h"

#include <vector>

namespace pf::plan::sweep_detail {

// Whether two directions (degrees) are the same lane direction: within half a degree, modulo 180.
bool sameDirection(double aDeg, double bDeg);

// The directions to estimate, degrees counter-clockwise from east in [0, 180), none twice (within
// half a degree): opt.anglesDeg when given, else the directions of the opt.edgeDirections longest
// edges of the region and of the zones, then every opt.coarseStepDeg.
std::vector<double> candidateDirections(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                                        const SweepOptions& opt);

// Seconds: each lane's width at its height less a trigger distance at the speed, a U-turn (two 90°
// turns and a spacing flown) between consecutive lanes of a merged cell, and the cells joined nearest
// neighbour first over their first and last lanes' middles with two 90° turns each. `heights`: per
// merged cell, its lanes' heights in the frame (plan::allLaneHeights).
double quickEstimateS(const Decomposition& d, const std::vector<MergedCell>& merged,
                      const std::vector<std::vector<double>>& heights, double photoSpacingM,
                      const FlightTimeModel& time, double trackSpacingM);

} // namespace pf::plan::sweep_detail
