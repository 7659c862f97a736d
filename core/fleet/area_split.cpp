#include "core/fleet/area_split.h"

#include "core/fleet/subarea_polygons.h"

#include "core/geo/polygon_ops.h"
#include "core/grid/grid.h"

#include <algorithm>

namespace pf::fleet {

Result<AreaSplit> splitArea(const geo::Polygon& area, const std::vector<geo::Polygon>& noFly,
                            const std::vector<Capability>& fleet, const AreaSplitOptions& opt,
                            const RegionTimeEstimator& estimate) {
    CellsTimeEstimator byCells;
    if (estimate)
        byCells = [&](int k, const std::vector<int>& cells, const grid::Grid& base) {
            return estimate(k, cellsPolygon(base, cells, base.admissible()));
        };
    return splitArea(area, noFly, fleet, opt, byCells);
}

Result<AreaSplit> splitArea(const geo::Polygon& area, const std::vector<geo::Polygon>& noFly,
                            const std::vector<Capability>& fleet, const AreaSplitOptions& opt,
                            const CellsTimeEstimator& estimate) {
    const double areaM2 = geo::area(area);
    AreaSplit out;
    auto shares = capabilityShares(fleet, areaM2);
    if (!shares)
        return shares.error();
    out.shares = *shares;
    std::vector<double> sizes;
    for (const auto& c : fleet)
        sizes.push_back(aircraftCellSize(c.footprint));
    auto base = baseCellSize(sizes, areaM2, opt.maxBaseCells);
    if (!base)
        return base.error();
    out.baseCellSizeM = *base;
    grid::GridOptions go;
    go.cellSize = *base;
    go.angleDeg = opt.gridAngleDeg;
    go.safetyMarginM = opt.safetyMarginM;
    auto g = grid::Grid::build(area, noFly, go);
    if (!g)
        return g.error();
    out.base = std::move(g).value();
    auto p = partitionCells(out.base, out.shares);
    if (!p)
        return p.error();
    out.partition = std::move(p).value();
    const geo::MultiPolygon& admissible = out.base.admissible();
    if (estimate) {
        auto rep = balanceByTime(out.base, out.partition,
                                 [&](int k, const std::vector<int>& cells) -> Result<double> {
                                     std::vector<int> sorted = cells;
                                     std::sort(sorted.begin(), sorted.end());
                                     return estimate(k, sorted, out.base);
                                 },
                                 opt.balance);
        if (!rep)
            return rep.error();
        out.balance = *rep;
    }
    out.subareas = subareaPolygons(out.base, out.partition, admissible);
    return out;
}

} // namespace pf::fleet
