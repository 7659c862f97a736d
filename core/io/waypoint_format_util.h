// Shared helpers of the waypoint readers and writers: locale-proof numbers, text files,
// line-numbered errors, JSON with line numbers, OGR datasets. Internal: include from core/io .cpp
// files only.
#pragma once

#include "core/geo/types.h"
#include "core/io/export_context.h"
#include "core/io/waypoint_formats.h"
#include "core/result.h"
#include "core/route/waypoint.h"

#include <cpl_json.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pf::io::detail {

// Fixed-point text of v with at most `decimals` decimals, trailing zeros removed, always with '.'
// whatever the process locale (a GUI may have set a German one).
std::string formatNumber(double v, int decimals);
// Parses a whole field as a finite number ('.' decimal point, optional sign); nullopt otherwise.
std::optional<double> parseNumber(std::string_view text);

std::string_view trim(std::string_view s);
// Lines without their "\n" or "\r\n"; a UTF-8 byte-order mark is dropped; a final newline does not
// make an extra empty line.
std::vector<std::string_view> splitLines(std::string_view text);
// Fields separated by tabs; when a line has no tab, by runs of spaces (hand-edited files).
std::vector<std::string_view> splitFields(std::string_view line);
std::vector<std::string_view> splitChar(std::string_view line, char sep);

Result<std::string> readTextFile(const std::string& path);
// Writes to a temporary file beside `path` and renames it over `path`, so a failed write never
// leaves half a file behind.
Status writeTextFile(const std::string& path, const std::string& text);

Error lineError(const std::string& source, std::size_t line, const std::string& what);

// Parses JSON; a syntax error names the line and column ("FILE: line 3, column 7: ...").
Result<CPLJSONObject> parseJson(const std::string& text, const std::string& source);

// Lower-case names used in GPX <type>, GeoJSON "kind" and KML: "photo", "turn", "transit".
const char* kindName(route::WaypointKind kind);
std::optional<route::WaypointKind> kindFromName(std::string_view name);
// For formats that only say whether a waypoint takes a photo: waypoints without a photo before the
// first photo or after the last are transit legs, those between photos are turns.
void inferNonPhotoKinds(std::vector<route::Waypoint>& waypoints, const std::vector<bool>& isPhoto);

double normaliseHeading(double deg); // into [0, 360)

// Why a waypoint read from a file cannot be flown ("latitude 91 is out of range", "the longitude is
// not a number"), or empty when its position and altitude are usable.
std::string waypointPositionProblem(double lon, double lat, double altitudeM);

// The file extension of a path, lower case, with the dot (".plan"), or "".
std::string extensionOf(const std::string& path);
// The file name of a path, for messages.
std::string baseName(const std::string& path);

// exportRouteFiles without its aircraft check (checkAircraftFormat): for a caller that made it once
// for a route it writes in several pieces (one file per sortie).
Result<ExportReport> writeRouteFiles(const ExportContext& ctx, std::size_t routeIndex,
                                     WaypointFormat format, const std::string& path,
                                     const ExportOptions& options);

// OGR plumbing: a dataset that is closed (and flushed) when it goes out of scope.
struct DatasetCloser {
    void operator()(GDALDataset* ds) const { GDALClose(ds); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

// Creates a vector dataset with the named driver, replacing any existing file at `path`.
Result<DatasetPtr> createVectorDataset(const char* driver, const std::string& path,
                                       const std::vector<std::string>& options = {});
Result<DatasetPtr> openVectorDataset(const std::string& path, const char* driver);
// Closes (flushes) a dataset being written; errors name the file.
Status closeDataset(DatasetPtr& ds, const std::string& path);
// GDAL's last error message, or `fallback` when GDAL gave none.
std::string lastGdalError(const std::string& fallback);

// A feature that is destroyed when it goes out of scope.
struct FeatureDeleter {
    void operator()(OGRFeature* f) const { OGRFeature::DestroyFeature(f); }
};
using FeaturePtr = std::unique_ptr<OGRFeature, FeatureDeleter>;

// A WGS84 polygon as an OGR polygon in lon/lat order, rings closed.
std::unique_ptr<OGRPolygon> toOgrPolygon(const geo::GeoPolygon& p);

} // namespace pf::io::detail
