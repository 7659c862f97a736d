#include "core/mosaic/mosaic_coverage.h"

#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cctype>

namespace pf::mosaic::detail {

namespace {

bool sameName(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

} // namespace

geo::MultiPolygon coverageArea(const MosaicOptions& options, const UtmProjection& utm,
                               std::vector<std::string>& notes) {
    geo::MultiPolygon areaGrid;
    if (!options.plan)
        return areaGrid;
    for (std::size_t ai = 0; ai < options.plan->area.size(); ++ai) {
        const auto& poly = options.plan->area[ai];
        if (!options.planAircraft.empty() && ai < options.plan->areaAircraft.size() &&
            !sameName(options.plan->areaAircraft[ai], options.planAircraft))
            continue;
        geo::Polygon g;
        for (const auto& p : poly.outer)
            g.outer.push_back(utm.toGrid(p));
        for (const auto& h : poly.holes) {
            geo::Ring r;
            for (const auto& p : h)
                r.push_back(utm.toGrid(p));
            g.holes.push_back(r);
        }
        areaGrid.push_back(g);
    }
    if (!options.planAircraft.empty() && !areaGrid.empty())
        notes.push_back("coverage is measured over the part of the area planned for " +
                        options.planAircraft);
    return areaGrid;
}

std::vector<geo::Polygon> measureGaps(const geo::MultiPolygon& area,
                                      const std::vector<geo::MultiPolygon>& seamPolys,
                                      const SeamMap& seams, const OutputGrid& grid,
                                      const UtmProjection& utm, double k, MosaicReport& report) {
    std::vector<geo::Polygon> gapPolys;
    geo::MultiPolygon all;
    for (const auto& mp : seamPolys)
        all.insert(all.end(), mp.begin(), mp.end());
    const geo::MultiPolygon covered = geo::unite(all);
    const double minGap = std::max(1.0, 9.0 * grid.gsd * grid.gsd);
    for (auto& g : geo::difference(area, covered))
        if (geo::area(g) >= minGap)
            gapPolys.push_back(std::move(g));
    std::sort(gapPolys.begin(), gapPolys.end(), [](const geo::Polygon& a, const geo::Polygon& b) {
        return geo::area(a) > geo::area(b);
    });
    report.areaM2 = geo::area(area) / (k * k);
    // Against the whole area: parts of it may lie outside the mosaic's grid (no photo there).
    const double areaPixels = geo::area(area) / (grid.gsd * grid.gsd);
    report.coveredRatio =
        areaPixels > 0 ? std::min(1.0, static_cast<double>(seams.coveredAreaPixels()) / areaPixels)
                       : 0.0;
    for (const auto& g : gapPolys) {
        GapArea gap;
        gap.shape.push_back(polygonToGeo(g, utm));
        gap.areaM2 = geo::area(g) / (k * k);
        const geo::Box b = geo::bounds(g);
        gap.centre = utm.toGeo(0.5 * (b.min + b.max));
        report.gapAreaM2 += gap.areaM2;
        report.gaps.push_back(std::move(gap));
    }
    return gapPolys;
}

} // namespace pf::mosaic::detail
