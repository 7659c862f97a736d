#include "core/io/qgc_wpl.h"

#include "core/io/qgc_plan.h"
#include "core/io/waypoint_format_util.h"

#include <array>
#include <cmath>

namespace pf::io {

namespace {

using detail::formatNumber;

void line(std::string& out, int index, int current, int frame, int command,
          const std::array<double, 7>& p) {
    out += std::to_string(index) + '\t' + std::to_string(current) + '\t' + std::to_string(frame) +
           '\t' + std::to_string(command);
    for (int i = 0; i < 4; ++i)
        out += '\t' + formatNumber(p[i], 6);
    out +=
        '\t' + formatNumber(p[4], 9) + '\t' + formatNumber(p[5], 9) + '\t' + formatNumber(p[6], 4);
    out += "\t1\n";
}

} // namespace

Result<std::string> qgcWplText(const ExportContext& ctx, std::size_t routeIndex,
                               const ExportOptions& options) {
    if (routeIndex >= ctx.routes.size())
        return makeError(ErrorCode::InvalidInput,
                         "there is no route " + std::to_string(routeIndex + 1) + " to export");
    const route::Route& r = ctx.routes[routeIndex];
    if (r.waypoints.empty())
        return makeError(ErrorCode::InvalidInput,
                         ctx.routeLabel(routeIndex) + ": the route has no waypoints to export");
    const geo::LonLat home = ctx.homeFor(routeIndex).value_or(r.waypoints.front().position);
    const geo::LonLat landing = ctx.landingFor(routeIndex).value_or(home);
    const int rel = mav::kFrameGlobalRelativeAlt;

    std::string out = "QGC WPL 110\n";
    int n = 0;
    // The home line is what Mission Planner writes: current = 1, frame 0 (its altitude is AMSL; 0
    // here because the ground elevation is not known).
    line(out, n++, 1, mav::kFrameGlobal, mav::kNavWaypoint, {0, 0, 0, 0, home.lat, home.lon, 0});
    const auto& first = r.waypoints.front();
    line(out, n++, 0, rel, mav::kNavTakeoff,
         {0, 0, 0, first.headingDeg, home.lat, home.lon, first.altitudeM});
    for (const auto& w : r.waypoints) {
        line(out, n++, 0, rel, mav::kNavWaypoint,
             {0, 0, 0, detail::normaliseHeading(w.headingDeg), w.position.lat, w.position.lon,
              w.altitudeM});
        if (w.kind != route::WaypointKind::Photo)
            continue;
        if (options.capture == CaptureCommand::ImageStartCapture)
            line(out, n++, 0, rel, mav::kImageStartCapture, {0, 0, 1, 0, 0, 0, 0});
        else
            line(out, n++, 0, rel, mav::kDoDigicamControl, {0, 0, 0, 0, 1, 0, 0});
    }
    if (options.end == MissionEnd::ReturnToLaunch)
        line(out, n++, 0, rel, mav::kNavReturnToLaunch, {0, 0, 0, 0, 0, 0, 0});
    else
        line(out, n++, 0, rel, mav::kNavLand,
             {0, 0, 0, r.waypoints.back().headingDeg, landing.lat, landing.lon, 0});
    return out;
}

Status writeQgcWpl(const ExportContext& ctx, std::size_t routeIndex, const std::string& path,
                   const ExportOptions& options) {
    auto text = qgcWplText(ctx, routeIndex, options);
    if (!text)
        return text.error();
    return detail::writeTextFile(path, *text);
}

Result<ImportedWaypoints> parseQgcWpl(const std::string& text, const std::string& source) {
    using detail::lineError;
    const auto lines = detail::splitLines(text);
    std::size_t firstLine = 0;
    while (firstLine < lines.size() && detail::trim(lines[firstLine]).empty())
        ++firstLine;
    if (firstLine == lines.size())
        return makeError(ErrorCode::ParseError, source + ": the file is empty");
    const std::string_view header = detail::trim(lines[firstLine]);
    if (header.rfind("QGC WPL", 0) != 0)
        return lineError(source, firstLine + 1,
                         "expected the header \"QGC WPL 110\" but found \"" +
                             std::string(header.substr(0, 40)) + "\"");
    if (header != "QGC WPL 110")
        return lineError(source, firstLine + 1,
                         "only version 110 of the QGC WPL format is supported (found \"" +
                             std::string(header) + "\")");

    static const char* const kFieldNames[12] = {
        "index",  "current", "frame",    "command",   "param1",   "param2",
        "param3", "param4",  "latitude", "longitude", "altitude", "autocontinue"};
    ImportedWaypoints out;
    route::Route r;
    std::vector<bool> photo;
    double homeAlt = 0.0;
    bool sawHome = false;
    for (std::size_t li = firstLine + 1; li < lines.size(); ++li) {
        const std::size_t lineNo = li + 1;
        if (detail::trim(lines[li]).empty())
            continue;
        const auto fields = detail::splitFields(lines[li]);
        if (fields.size() != 12)
            return lineError(source, lineNo,
                             "expected 12 tab-separated fields but found " +
                                 std::to_string(fields.size()));
        std::array<double, 12> v{};
        for (std::size_t f = 0; f < 12; ++f) {
            auto num = detail::parseNumber(fields[f]);
            if (!num)
                return lineError(source, lineNo,
                                 std::string(kFieldNames[f]) + " \"" + std::string(fields[f]) +
                                     "\" is not a number");
            v[f] = *num;
        }
        // Index, frame and command are whole numbers; converting a huge value to int would be
        // undefined behaviour, so such a line is refused like any other damaged field.
        for (std::size_t f : {std::size_t{0}, std::size_t{2}, std::size_t{3}}) {
            if (!(std::abs(v[f]) <= 1e9))
                return lineError(source, lineNo,
                                 std::string(kFieldNames[f]) + " \"" + std::string(fields[f]) +
                                     "\" is out of range");
        }
        const int frame = static_cast<int>(v[2]);
        const int command = static_cast<int>(v[3]);
        const double lat = v[8], lon = v[9], alt = v[10];
        if (!sawHome) {
            // The first item is the home position (Mission Planner and QGroundControl both write
            // it).
            sawHome = true;
            if (command == mav::kNavWaypoint && static_cast<int>(v[0]) == 0) {
                if (std::abs(lat) > 90 || std::abs(lon) > 180)
                    return lineError(source, lineNo, "the home position is out of range");
                if (lat != 0.0 || lon != 0.0)
                    out.home = geo::LonLat{lon, lat};
                homeAlt = frame == mav::kFrameGlobal ? alt : 0.0;
                continue;
            }
        }
        if (command == mav::kImageStartCapture || command == mav::kDoDigicamControl) {
            if (!photo.empty())
                photo.back() = true;
            continue;
        }
        if (command != mav::kNavWaypoint)
            continue; // take-off, return and landing are regenerated on export
        if (std::abs(lat) > 90 || std::abs(lon) > 180)
            return lineError(source, lineNo, "latitude or longitude out of range");
        route::Waypoint w;
        w.position = {lon, lat};
        if (frame == mav::kFrameGlobal)
            w.altitudeM = alt - homeAlt;
        else if (frame == mav::kFrameGlobalRelativeAlt || frame == 6)
            w.altitudeM = alt;
        else
            return lineError(source, lineNo,
                             "frame " + std::to_string(frame) +
                                 " is not supported (use 3, altitude relative to home)");
        w.headingDeg = detail::normaliseHeading(v[7]);
        r.waypoints.push_back(w);
        photo.push_back(false);
    }
    detail::inferNonPhotoKinds(r.waypoints, photo);
    r.home = out.home;
    out.routes.push_back(std::move(r));
    return out;
}

Result<ImportedWaypoints> readQgcWpl(const std::string& path) {
    auto text = detail::readTextFile(path);
    if (!text)
        return text.error();
    return parseQgcWpl(*text, path);
}

} // namespace pf::io
