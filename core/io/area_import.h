// Import of areas and no-fly zones from GeoJSON, KML, Shapefile, GeoPackage and GML, and of
// corridor lines from those and GPX (OGR inside).
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
    // The feature's "role" attribute, lower case, where it has one: "area" or "nofly" in the area
    // files that `eval --generate` writes and the sample areas; empty otherwise.
    std::string role;
};

// Reads every polygon of every layer, reprojected to WGS84 from the file's CRS, flattened to 2D.
// Errors name the file and the problem (cannot open, no polygon, unknown CRS, ...).
Result<std::vector<ImportedPolygon>> importPolygons(const std::string& path);

struct ImportedLine {
    std::string name; // feature name or "<layer> #<fid>"
    std::string layer;
    geo::GeoRing line; // WGS84 lon/lat, 2D, in the file's order (multilines are split)
};

// Reads every line (LineString, the parts of a MultiLineString: a GPX track or route too) of every
// layer, as importPolygons reads polygons, from GeoJSON, KML, GPX, Shapefile, GeoPackage or GML.
// Errors name the file and the problem (cannot open, no line, unknown CRS, ...).
Result<std::vector<ImportedLine>> importLines(const std::string& path);

// Registers GDAL/OGR's drivers once (thread-safe; later calls are cheap) and keeps GDAL from printing
// on stderr: its messages become Result errors at the io boundary instead. Every io function calls
// it; other core code that opens GDAL datasets directly calls it first.
void initGdal();

namespace detail {

// While alive, collects the GDAL errors raised on this thread (instead of printing them), so that an
// io function can turn the first one into the message of its Result. Scopes nest.
class GdalErrorScope {
public:
    GdalErrorScope();
    ~GdalErrorScope();
    GdalErrorScope(const GdalErrorScope&) = delete;
    GdalErrorScope& operator=(const GdalErrorScope&) = delete;
    // The first error (CE_Failure or worse) seen, or "" if none.
    const std::string& firstError() const { return m_firstError; }
    void record(const char* message);

private:
    std::string m_firstError;
};

} // namespace detail

} // namespace pf::io
