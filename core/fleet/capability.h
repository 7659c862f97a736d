// Each aircraft's share of a shared area from its capability, and the base grid's cell size.
#pragma once

#include "core/plan/flight_time.h"
#include "core/result.h"
#include "core/sensor/camera.h"

#include <string>
#include <vector>

namespace pf::fleet {

// What the workload split needs to know about one aircraft.
struct Capability {
    std::string name;
    sensor::EffectiveFootprint footprint; // across (track spacing) and along (photo spacing)
    plan::FlightTimeModel time;           // speed, turn rate and the stop at each turn
};

// Estimated area rate in m^2/s of a back-and-forth survey with tracks of length `trackLengthM`:
//
//   rate = across * trackLength / (trackLength / v + 180 / turnRate + 2 * stop + across / v)
//
// A track of length L sweeps across * L square metres in L / v seconds; at its end the aircraft
// turns 180 degrees (modelled as two stop-and-turn manoeuvres at `turnRate`, i.e. 180 / turnRate
// seconds in total, each with the stop of plan::FlightTimeModel) and moves `across` metres sideways
// to the next track. The discount is what
// makes a fast aircraft with a narrow footprint less valuable on a small area than its
// across * v product suggests. Returns 0 for unusable figures.
double areaRateM2PerS(const Capability& c, double trackLengthM);

// Each aircraft's fraction of the area (sums to 1), proportional to areaRateM2PerS with a track
// length of sqrt(areaM2) (the side of a square of the area: a rough estimate, refined later by
// balancing on planned flight times). Errors name the aircraft whose figures are unusable.
Result<std::vector<double>> capabilityShares(const std::vector<Capability>& fleet, double areaM2);

// The square cell side of one aircraft's grid: the longest side of its effective footprint
// (paper 001, section IV; same rule as sensor::cellSizeFor).
double aircraftCellSize(const sensor::EffectiveFootprint& fp);

// The base grid's cell side for partitioning a fleet (paper 001, section V.B; the paper's formula
// is lost in our copy, so this is our choice): the SMALLEST of the aircraft cell sizes.
//  - The partition boundary is then as fine as the finest aircraft's own grid, so no aircraft's
//    share is rounded to cells coarser than it can resolve, and shares can be balanced to within
//    one small cell.
//  - The per-aircraft grid covers every one of its cells overlapping its subarea, so the band of
//    double coverage along a shared boundary is at most one of that aircraft's cells whatever the
//    base size: a finer base costs no extra flight.
//  - The base grid then has no more cells than the finest aircraft's own grid, which is built
//    anyway, so the cost stays bounded by what single-aircraft planning already accepts.
// If the resulting base grid over `areaM2` would exceed `maxCells`, the size grows to fit.
// Errors when the list is empty or a size is not positive.
Result<double> baseCellSize(const std::vector<double>& aircraftCellSizes, double areaM2,
                            double maxCells = 250'000);

} // namespace pf::fleet
