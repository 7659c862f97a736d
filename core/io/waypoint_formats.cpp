#include "core/io/waypoint_formats.h"

#include "core/io/gpx.h"
#include "core/io/kml_export.h"
#include "core/io/litchi_csv.h"
#include "core/io/qgc_plan.h"
#include "core/io/qgc_wpl.h"
#include "core/io/waypoint_format_util.h"
#include "core/io/waypoint_geojson.h"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace pf::io {

const std::vector<WaypointFormatInfo>& waypointFormats() {
    static const std::vector<WaypointFormatInfo> kFormats{
        {WaypointFormat::QgcPlan, "plan", ".plan", "QGroundControl mission (.plan JSON)", true,
         false},
        {WaypointFormat::QgcWpl, "waypoints", ".waypoints",
         "QGC WPL 110 waypoint list (Mission Planner)", true, false},
        {WaypointFormat::Kml, "kml", ".kml", "KML for Google Earth (export only)", false, true},
        {WaypointFormat::Gpx, "gpx", ".gpx", "GPX 1.1 waypoints and routes", true, true},
        {WaypointFormat::GeoJson, "geojson", ".geojson", "GeoJSON features", true, true},
        {WaypointFormat::LitchiCsv, "csv", ".csv", "Litchi mission hub CSV", true, false},
    };
    return kFormats;
}

const WaypointFormatInfo& formatInfo(WaypointFormat format) {
    for (const auto& f : waypointFormats())
        if (f.format == format)
            return f;
    return waypointFormats().front();
}

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

std::string knownNames() {
    std::string s;
    for (const auto& f : waypointFormats())
        s += (s.empty() ? "" : ", ") + std::string(f.name);
    return s;
}

} // namespace

Result<WaypointFormat> formatFromName(const std::string& name) {
    const std::string n = lower(std::string(detail::trim(name)));
    if (n == "json")
        return WaypointFormat::GeoJson;
    if (n == "litchi")
        return WaypointFormat::LitchiCsv;
    for (const auto& f : waypointFormats())
        if (n == f.name)
            return f.format;
    return makeError(ErrorCode::Unsupported,
                     "unknown waypoint format \"" + name + "\" (known: " + knownNames() + ")");
}

Result<WaypointFormat> formatFromPath(const std::string& path) {
    const std::string ext = detail::extensionOf(path);
    if (ext == ".json")
        return WaypointFormat::GeoJson;
    for (const auto& f : waypointFormats())
        if (ext == f.extension)
            return f.format;
    return makeError(ErrorCode::Unsupported,
                     path + ": cannot tell the waypoint format from the extension \"" + ext +
                         "\" (use .plan, .waypoints, .kml, .gpx, .geojson, .json or .csv)");
}

Result<std::vector<WaypointFormat>> formatListFromString(const std::string& commaSeparated) {
    std::vector<WaypointFormat> out;
    for (auto part : detail::splitChar(commaSeparated, ',')) {
        if (detail::trim(part).empty())
            continue;
        auto f = formatFromName(std::string(part));
        if (!f)
            return f.error();
        if (std::find(out.begin(), out.end(), *f) == out.end())
            out.push_back(*f);
    }
    if (out.empty())
        return makeError(ErrorCode::InvalidInput,
                         "no waypoint format given (known: " + knownNames() + ")");
    return out;
}

Status exportRoute(const ExportContext& ctx, std::size_t routeIndex, WaypointFormat format,
                   const std::string& path, const ExportOptions& options) {
    switch (format) {
    case WaypointFormat::QgcPlan:
        return writeQgcPlan(ctx, routeIndex, path, options);
    case WaypointFormat::QgcWpl:
        return writeQgcWpl(ctx, routeIndex, path, options);
    case WaypointFormat::LitchiCsv:
        return writeLitchiCsv(ctx, routeIndex, path);
    case WaypointFormat::Kml:
        return writeKml(ctx, {routeIndex}, path);
    case WaypointFormat::Gpx:
        return writeGpx(ctx, {routeIndex}, path);
    case WaypointFormat::GeoJson:
        return writeWaypointGeoJson(ctx, {routeIndex}, path);
    }
    return makeError(ErrorCode::Internal, "unknown waypoint format");
}

Status exportCombined(const ExportContext& ctx, WaypointFormat format, const std::string& path,
                      const ExportOptions& /*options*/) {
    std::vector<std::size_t> all(ctx.routes.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    switch (format) {
    case WaypointFormat::Kml:
        return writeKml(ctx, all, path);
    case WaypointFormat::Gpx:
        return writeGpx(ctx, all, path);
    case WaypointFormat::GeoJson:
        return writeWaypointGeoJson(ctx, all, path);
    default:
        return makeError(ErrorCode::Unsupported,
                         std::string("a ") + formatInfo(format).description +
                             " file holds one aircraft's mission; write one file per aircraft");
    }
}

std::string routeFileName(const ExportContext& ctx, std::size_t routeIndex, WaypointFormat format) {
    std::string name = ctx.routeLabel(routeIndex);
    for (char& c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'))
            c = '_';
    return name + formatInfo(format).extension;
}

Result<std::vector<std::string>> exportAll(const ExportContext& ctx, WaypointFormat format,
                                           const std::string& dir, const std::string& stem,
                                           const ExportOptions& options) {
    std::vector<std::string> written;
    const std::string base = dir.empty() ? std::string() : dir + "/";
    for (std::size_t i = 0; i < ctx.routes.size(); ++i) {
        const std::string path = base + stem + "-" + routeFileName(ctx, i, format);
        if (auto st = exportRoute(ctx, i, format, path, options); !st)
            return st.error();
        written.push_back(path);
    }
    if (formatInfo(format).combined && ctx.routes.size() > 1) {
        const std::string path = base + stem + formatInfo(format).extension;
        if (auto st = exportCombined(ctx, format, path, options); !st)
            return st.error();
        written.push_back(path);
    }
    return written;
}

Result<ImportedWaypoints> importWaypoints(const std::string& path) {
    auto format = formatFromPath(path);
    if (!format)
        return format.error();
    switch (*format) {
    case WaypointFormat::QgcPlan:
        return readQgcPlan(path);
    case WaypointFormat::QgcWpl:
        return readQgcWpl(path);
    case WaypointFormat::LitchiCsv:
        return readLitchiCsv(path);
    case WaypointFormat::Gpx:
        return readGpx(path);
    case WaypointFormat::GeoJson:
        return readWaypointGeoJson(path);
    case WaypointFormat::Kml:
        return makeError(
            ErrorCode::Unsupported,
            path +
                ": KML is written for viewing only; edit the .plan, .waypoints, .gpx, .geojson or "
                ".csv export instead");
    }
    return makeError(ErrorCode::Internal, "unknown waypoint format");
}

} // namespace pf::io
