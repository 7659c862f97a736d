// Import of areas and no-fly zones from GeoJSON, KML, Shapefile, GeoPackage and GML (OGR inside).
#pragma once

#include "core/geo/types.h"
#include "core/result.h"

#include <string>
#include <vector>

namespace pf::io {

struct ImportedPolygon {
    std::string name;  // feature name or "<layer> #<fid>"
    std::string layer;
    geo::GeoPolygon polygon; // WGS84 lon/lat, 2D, one per polygon (multipolygons are split)
};

// Reads every polygon of every layer, reprojected to WGS84 from the file's CRS, flattened to 2D.
// Errors name the file and the problem (cannot open, no polygon, unknown CRS, ...).
Result<std::vector<ImportedPolygon>> importPolygons(const std::string& path);

} // namespace pf::io
