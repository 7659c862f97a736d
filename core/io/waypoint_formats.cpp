#include "core/io/waypoint_formats.h"

#include "core/io/gpx.h"
#include "core/io/kml_export.h"
#include "core/io/litchi_csv.h"
#include "core/io/mission_export.h"
#include "core/io/qgc_plan.h"
#include "core/io/qgc_wpl.h"
#include "core/io/trigger_lanes.h"
#include "core/io/waypoint_format_util.h"
#include "core/io/waypoint_geojson.h"
#include "core/io/wpml_kmz.h"
#include "core/mission/route_check.h"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace pf::io {

const std::vector<WaypointFormatInfo>& waypointFormats() {
    static const std::vector<WaypointFormatInfo> kFormats{
        {WaypointFormat::QgcPlan, "plan", ".plan", "QGroundControl mission (.plan JSON)", true,
         false, 0.1, 0},
        {WaypointFormat::QgcWpl, "waypoints", ".waypoints",
         "QGC WPL 110 waypoint list (Mission Planner)", true, false, 0.1, 0},
        {WaypointFormat::Kml, "kml", ".kml", "KML for Google Earth (export only)", false, true, 0.1,
         0, false},
        {WaypointFormat::Gpx, "gpx", ".gpx", "GPX 1.1 waypoints and routes", true, true, 0.1, 0,
         false},
        {WaypointFormat::GeoJson, "geojson", ".geojson", "GeoJSON features", true, true, 0.1, 0,
         false},
        {WaypointFormat::LitchiCsv, "csv", ".csv", "Litchi mission hub CSV", true, false, 0.6, 99},
        // DJI WPML ("waylines.wpml", "Common Elements"): wpml:index and wpml:actionGroupId are
        // documented in [0, 65535]. A wayline of 65535 waypoints has at most 65536 action groups
        // (the gimbal's and one per photo waypoint), so both fit; a longer route is split. The
        // pages give no other count limit (no mission storage limit as the MAVLink autopilots
        // have) and no minimum spacing: 0.6 m is DJI's waypoint-mission minimum that the Litchi
        // export keeps too.
        {WaypointFormat::WpmlKmz, "kmz", ".kmz", "DJI Pilot 2 / FlightHub 2", true, false, 0.6,
         65535},
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
    if (n == "wpml" || n == "dji")
        return WaypointFormat::WpmlKmz;
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
                         "\" (use .plan, .waypoints, .kml, .gpx, .geojson, .json, .csv or .kmz)");
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

namespace {

// ctx with the given routes' waypoints merged where closer than the format's minimum.
ExportContext mergedContext(const ExportContext& ctx, const std::vector<std::size_t>& routes,
                            WaypointFormat format, std::vector<std::string>* notes) {
    ExportContext out = ctx;
    const double minM = formatInfo(format).minSpacingM;
    for (std::size_t i : routes) {
        if (i >= out.routes.size())
            continue;
        std::size_t merged = 0;
        route::Route candidate = out.routes[i];
        candidate.waypoints = mergeCloseWaypoints(out.routes[i].waypoints, minM, &merged);
        if (merged == 0)
            continue;
        // A merge moves a waypoint by less than the format's minimum, which can cut a detour's corner
        // into a no-fly margin the route as checked kept: then the route is written as it is.
        if (!ctx.mission.noFlyZones.empty()) {
            const mission::RouteLimits limits = mission::routeLimits(ctx.mission, out.routes[i]);
            if (mission::checkRoute(candidate, limits).noFly > mission::checkRoute(out.routes[i], limits).noFly) {
                if (notes)
                    notes->push_back(ctx.routeLabel(i) + ": " + std::to_string(merged) + " waypoint" +
                                     (merged == 1 ? "" : "s") + " closer than " + detail::formatNumber(minM, 1) +
                                     " m to the previous one kept as planned: merging them would put a leg into "
                                     "a no-fly zone's safety margin (" + formatInfo(format).description +
                                     " may refuse waypoints that close)");
                continue;
            }
        }
        out.routes[i] = std::move(candidate);
        if (notes)
            notes->push_back(ctx.routeLabel(i) + ": " + std::to_string(merged) + " waypoint" +
                             (merged == 1 ? "" : "s") + " closer than " +
                             detail::formatNumber(minM, 1) + " m to the previous one merged into it (" +
                             formatInfo(format).description + ")");
    }
    return out;
}

Status writeOne(const ExportContext& ctx, std::size_t routeIndex, WaypointFormat format,
                const std::string& path, const ExportOptions& options) {
    switch (format) {
    case WaypointFormat::QgcPlan:
        return writeQgcPlan(ctx, routeIndex, path, options);
    case WaypointFormat::QgcWpl:
        return writeQgcWpl(ctx, routeIndex, path, options);
    case WaypointFormat::LitchiCsv:
        if (auto e = planeFormatError(ctx, routeIndex, "Litchi"); !e.empty())
            return makeError(ErrorCode::InvalidInput, e);
        return writeLitchiCsv(ctx, routeIndex, path);
    case WaypointFormat::Kml:
        return writeKml(ctx, {routeIndex}, path);
    case WaypointFormat::Gpx:
        return writeGpx(ctx, {routeIndex}, path);
    case WaypointFormat::GeoJson:
        return writeWaypointGeoJson(ctx, {routeIndex}, path);
    case WaypointFormat::WpmlKmz:
        return writeWpmlKmz(ctx, routeIndex, path, options);
    }
    return makeError(ErrorCode::Internal, "unknown waypoint format");
}

std::string partPath(const std::string& path, std::size_t part) {
    const std::string ext = detail::extensionOf(path);
    return path.substr(0, path.size() - ext.size()) + "-part" + std::to_string(part) + ext;
}

} // namespace

Result<AircraftFormatCheck> checkAircraftFormat(const ExportContext& ctx, std::size_t routeIndex,
                                                WaypointFormat format,
                                                const ExportOptions& options) {
    AircraftFormatCheck check;
    const std::string problem = aircraftFormatProblem(ctx, routeIndex, format);
    if (problem.empty())
        return check;
    if (!options.forceAircraft)
        return makeError(ErrorCode::Unsupported, problem);
    // A .kmz names the DJI drone and payload types it is for: there is none to name.
    check.leaveOut = format == WaypointFormat::WpmlKmz;
    check.note = problem + (check.leaveOut ? "; no " + std::string(formatInfo(format).extension) +
                                                 " written for it"
                                           : std::string("; written anyway, as asked"));
    return check;
}

Result<ExportReport> exportRouteFiles(const ExportContext& ctx, std::size_t routeIndex,
                                      WaypointFormat format, const std::string& path,
                                      const ExportOptions& options) {
    if (routeIndex >= ctx.routes.size())
        return makeError(ErrorCode::InvalidInput,
                         "there is no route " + std::to_string(routeIndex + 1) + " to export");
    auto check = checkAircraftFormat(ctx, routeIndex, format, options);
    if (!check)
        return check.error();
    ExportReport report;
    if (!check->note.empty())
        report.notes.push_back(check->note);
    if (check->leaveOut)
        return report;
    auto written = detail::writeRouteFiles(ctx, routeIndex, format, path, options);
    if (!written)
        return written.error();
    report.files = std::move(written->files);
    report.notes.insert(report.notes.end(), written->notes.begin(), written->notes.end());
    return report;
}

namespace detail {

Result<ExportReport> writeRouteFiles(const ExportContext& ctx, std::size_t routeIndex,
                                     WaypointFormat format, const std::string& path,
                                     const ExportOptions& options) {
    if (routeIndex >= ctx.routes.size())
        return makeError(ErrorCode::InvalidInput,
                         "there is no route " + std::to_string(routeIndex + 1) + " to export");
    ExportReport report;
    ExportContext m = mergedContext(ctx, {routeIndex}, format, &report.notes);
    const std::size_t limit = formatInfo(format).maxWaypoints;
    const auto& all = m.routes[routeIndex].waypoints;
    if (limit < 2 || all.size() <= limit) {
        if (auto st = writeOne(m, routeIndex, format, path, options); !st)
            return st.error();
        report.files.push_back(path);
        return report;
    }
    // Consecutive parts share one waypoint: each mission starts where the previous one ended
    // (the shared waypoint takes its photo only in the first of them).
    const std::vector<route::Waypoint> waypoints = all;
    std::size_t part = 0;
    for (std::size_t start = 0; start + 1 < waypoints.size(); start += limit - 1) {
        const std::size_t end = std::min(waypoints.size(), start + limit);
        auto& r = m.routes[routeIndex];
        r.waypoints.assign(waypoints.begin() + static_cast<long>(start),
                           waypoints.begin() + static_cast<long>(end));
        if (start > 0 && r.waypoints.front().kind == route::WaypointKind::Photo)
            r.waypoints.front().kind = route::WaypointKind::Turn;
        const std::string p = partPath(path, ++part);
        if (auto st = writeOne(m, routeIndex, format, p, options); !st)
            return st.error();
        report.files.push_back(p);
    }
    report.notes.push_back(ctx.routeLabel(routeIndex) + ": " + formatInfo(format).description +
                           " takes at most " + std::to_string(limit) + " waypoints; the " +
                           std::to_string(waypoints.size()) + " waypoints are written as " +
                           std::to_string(part) + " missions (" + detail::baseName(report.files.front()) +
                           " to " + detail::baseName(report.files.back()) +
                           ") to fly one after the other, each starting where the previous one ended");
    return report;
}

} // namespace detail

Status exportRoute(const ExportContext& ctx, std::size_t routeIndex, WaypointFormat format,
                   const std::string& path, const ExportOptions& options) {
    auto r = exportRouteFiles(ctx, routeIndex, format, path, options);
    if (!r)
        return r.error();
    return {};
}

Status exportCombined(const ExportContext& original, WaypointFormat format, const std::string& path,
                      const ExportOptions& /*options*/) {
    std::vector<std::size_t> all(original.routes.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    const ExportContext ctx = mergedContext(original, all, format, nullptr);
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

std::string aircraftFormatProblem(const ExportContext& ctx, std::size_t routeIndex,
                                  WaypointFormat format) {
    const mission::AircraftConfig* a = ctx.aircraftFor(routeIndex);
    const std::string label = ctx.routeLabel(routeIndex);
    const std::string named = !a || a->model == label ? label : label + " (" + a->model + ")";
    switch (format) {
    case WaypointFormat::WpmlKmz:
        return wpmlAircraftProblem(ctx, routeIndex);
    case WaypointFormat::LitchiCsv:
        if (a && a->dji)
            return named +
                   " is a DJI Enterprise aircraft: Litchi does not "
                   "fly the Enterprise series; export the DJI Pilot 2 / FlightHub 2 .kmz for it";
        return {};
    case WaypointFormat::QgcPlan:
    case WaypointFormat::QgcWpl:
        if (a && a->dji)
            return named +
                   " is a DJI Enterprise aircraft: it flies DJI's "
                   "own flight controller, not ArduPilot or PX4, and cannot fly a MAVLink mission "
                   "(" +
                   formatInfo(format).extension +
                   "); export the DJI Pilot 2 / FlightHub 2 .kmz for it";
        return {};
    case WaypointFormat::Kml:
    case WaypointFormat::Gpx:
    case WaypointFormat::GeoJson:
        return {};
    }
    return {};
}

std::string fileNameSafe(const std::string& name) {
    std::string out;
    for (char c : name) {
        const bool safe =
            std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
        // "DJI Mavic 3 Enterprise #1" -> "DJI_Mavic_3_Enterprise_1": one '_' for a run.
        if (safe && c != '_')
            out += c;
        else if (!out.empty() && out.back() != '_')
            out += '_';
    }
    while (!out.empty() && out.back() == '_')
        out.pop_back();
    return out.empty() ? "aircraft" : out;
}

std::string routeFileStem(const ExportContext& ctx, std::size_t routeIndex) {
    const std::string stem = fileNameSafe(ctx.routeLabel(routeIndex));
    // Two names that read alike in a file name ("Falcon 8 #1", "Falcon 8 1") must not write one
    // file.
    int same = 0;
    for (std::size_t k = 0; k < routeIndex && k < ctx.routes.size(); ++k)
        same += fileNameSafe(ctx.routeLabel(k)) == stem ? 1 : 0;
    return same == 0 ? stem : stem + "_" + std::to_string(same + 1);
}

std::string routeFileName(const ExportContext& ctx, std::size_t routeIndex, WaypointFormat format) {
    return routeFileStem(ctx, routeIndex) + formatInfo(format).extension;
}

Result<std::vector<std::string>> exportAll(const ExportContext& ctx, WaypointFormat format,
                                           const std::string& dir, const std::string& stem,
                                           const ExportOptions& options,
                                           std::vector<std::string>* notes) {
    MissionExportRequest request;
    request.folder = dir;
    request.stem = stem;
    request.options = options;
    request.kmlTrajectories = false; // the context's own, if any
    auto r = exportFormat(ctx, format, request);
    if (!r)
        return r.error();
    if (notes) {
        notes->insert(notes->end(), r->notes.begin(), r->notes.end());
        notes->insert(notes->end(), r->warnings.begin(), r->warnings.end());
    }
    return r->files;
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
    case WaypointFormat::WpmlKmz:
        return readWpmlKmz(path);
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
