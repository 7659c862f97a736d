// Export of a mission grid as a GeoJSON FeatureCollection of WGS84 cell polygons with their state.
#pragma once

#include "core/geo/local_frame.h"
#include "core/grid/grid.h"
#include "core/result.h"

#include <string>

namespace pf::io {

struct GridExportOptions {
    // Outside cells (not part of the coverage problem) are left out unless asked for: on a large
    // rotated grid they can outnumber the others.
    bool includeOutside = false;
};

// One Feature per cell: a Polygon (the cell's four corners, counter-clockwise, WGS84 lon/lat) with
// properties
//   index (row * cols + col), col, row,
//   state: "free" | "shifted" | "unflyable" | "outside",
//   contour: true for a visitable cell on the area's contour (Grid::onContour),
//   flight_lon, flight_lat: the flight position (null for unflyable and outside cells).
// The collection carries a "photoflight_grid" member with cell_size_m, angle_deg, cols, rows,
// visit_count and the local frame's PROJ string.
std::string gridToGeoJson(const grid::Grid& g, const geo::LocalFrame& frame, const GridExportOptions& opt = {});

// Writes gridToGeoJson() to `path` (replacing it). Errors name the file.
Status writeGridGeoJson(const grid::Grid& g, const geo::LocalFrame& frame, const std::string& path,
                        const GridExportOptions& opt = {});

} // namespace pf::io
