// One call from an area and a fleet to each aircraft's subarea: base grid, partition, time balance.
#pragma once

#include "core/fleet/capability.h"
#include "core/fleet/partition.h"
#include "core/fleet/time_balance.h"
#include "core/geo/types.h"
#include "core/grid/grid.h"
#include "core/result.h"

#include <functional>
#include <optional>
#include <vector>

namespace pf::fleet {

struct AreaSplitOptions {
    double gridAngleDeg = 0.0;         // base grid rotation (the per-aircraft grids choose their own)
    double safetyMarginM = 0.0;        // around the no-fly zones, as for the per-aircraft grids
    double maxBaseCells = 250'000;     // the base cell grows to stay within this many cells
    BalanceOptions balance;            // used when an estimator is given
};

// Flight time of aircraft k over a candidate subarea (local metres); the facade passes its
// single-aircraft planner.
using RegionTimeEstimator = std::function<Result<double>(int aircraft, const geo::MultiPolygon& subarea)>;

// The same given the subarea as cells of the split's base grid (sorted, with the grid to make its
// polygon from: cellsPolygon(base, cells, base.admissible())): for a caller that remembers estimates
// across splits of one area (the base grid is the same for the same area, zones, fleet and options,
// and a balance search asks for the same subareas again, round after round).
using CellsTimeEstimator =
    std::function<Result<double>(int aircraft, const std::vector<int>& sortedCells, const grid::Grid& base)>;

struct AreaSplit {
    double baseCellSizeM = 0.0;
    std::vector<double> shares;             // capability shares (paper 001, section V.A)
    grid::Grid base;                         // the base grid the partition shares out
    Partition partition;
    std::vector<geo::MultiPolygon> subareas; // per aircraft, clipped to the admissible area
    std::optional<BalanceReport> balance;    // when an estimator was given
};

// Splits `area` minus `noFly` between the aircraft of `fleet` (paper 001, section V): capability
// shares, a base grid of the smallest aircraft cell size, flood-fill partition with redistribution,
// then, if `estimate` is given, balancing on the estimated flight times. The subareas are ready for
// per-aircraft grids (buildAircraftGrids) or the single-aircraft planner. Errors name the problem
// (bad aircraft figures, an area too small for the number of aircraft, the grid's own errors).
Result<AreaSplit> splitArea(const geo::Polygon& area, const std::vector<geo::Polygon>& noFly,
                            const std::vector<Capability>& fleet, const AreaSplitOptions& opt = {},
                            const RegionTimeEstimator& estimate = nullptr);
Result<AreaSplit> splitArea(const geo::Polygon& area, const std::vector<geo::Polygon>& noFly,
                            const std::vector<Capability>& fleet, const AreaSplitOptions& opt,
                            const CellsTimeEstimator& estimate);

} // namespace pf::fleet
