// How much of the planned area the mosaic covers: the area measured against (the plan's, or one
// aircraft's part of it) and the gaps no photo gives colour to. Internal to buildMosaic.
#pragma once

#include "core/geo/types.h"
#include "core/mosaic/mosaic_types.h"
#include "core/mosaic/output_grid.h"
#include "core/mosaic/seam_map.h"
#include "core/mosaic/utm_projection.h"

#include <string>
#include <vector>

namespace pf::mosaic::detail {

// The plan's area in grid metres, or the part planned for options.planAircraft (with a note saying
// so); empty without a plan.
geo::MultiPolygon coverageArea(const MosaicOptions& options, const UtmProjection& utm,
                               std::vector<std::string>& notes);

// The parts of `area` (grid metres, not empty) no seam covers, of at least 9 pixels and 1 m2,
// largest first; the report gets the area, the covered ratio, the gaps in WGS84 and their total. k:
// the grid's point scale.
std::vector<geo::Polygon> measureGaps(const geo::MultiPolygon& area,
                                      const std::vector<geo::MultiPolygon>& seamPolys,
                                      const SeamMap& seams, const OutputGrid& grid,
                                      const UtmProjection& utm, double k, MosaicReport& report);

} // namespace pf::mosaic::detail
