#include "core/io/qgc_wpl.h"

#include "core/io/mission_items.h"
#include "core/io/waypoint_format_util.h"

#include <array>
#include <cmath>
#include <limits>

namespace pf::io {

namespace {

using detail::formatNumber;

bool isNaNText(std::string_view f) {
    f = detail::trim(f);
    return f.size() == 3 && (f[0] == 'n' || f[0] == 'N') && (f[1] == 'a' || f[1] == 'A') &&
           (f[2] == 'n' || f[2] == 'N');
}

// Params 1-4 may be NaN ("not used"): written "NaN", which Mission Planner and pymavlink read.
std::string param(double v, int decimals) {
    return std::isfinite(v) ? formatNumber(v, decimals) : std::string("NaN");
}

void line(std::string& out, int index, int current, const MissionItem& it) {
    const auto& p = it.params;
    out += std::to_string(index) + '\t' + std::to_string(current) + '\t' +
           std::to_string(it.frame) + '\t' + std::to_string(it.command);
    for (int i = 0; i < 4; ++i)
        out += '\t' + param(p[i], 6);
    out +=
        '\t' + formatNumber(p[4], 9) + '\t' + formatNumber(p[5], 9) + '\t' + formatNumber(p[6], 4);
    out += "\t1\n";
}

} // namespace

Result<std::string> qgcWplText(const ExportContext& ctx, std::size_t routeIndex,
                               const ExportOptions& options) {
    auto items = missionItems(ctx, routeIndex, options);
    if (!items)
        return items.error();
    std::string out = "QGC WPL 110\n";
    // The home line is what Mission Planner writes: current = 1, frame 0 (altitude above sea level).
    line(out, 0, 1, homeItem(ctx, routeIndex, options));
    int n = 1;
    // Exactly the items an upload sends: commands without a position in frame 2 (MAV_FRAME_MISSION).
    for (const auto& it : *items)
        line(out, n++, 0, it);
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
    std::vector<MissionItem> items;
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
            if (!num && f >= 4 && f <= 7 && isNaNText(fields[f]))
                num = std::numeric_limits<double>::quiet_NaN(); // an unused param
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
        MissionItem it;
        it.command = command;
        it.frame = frame;
        it.params = {v[4], v[5], v[6], v[7], lat, lon, alt};
        if (command == mav::kNavWaypoint) {
            if (std::abs(lat) > 90 || std::abs(lon) > 180)
                return lineError(source, lineNo, "latitude or longitude out of range");
            if (frame == mav::kFrameGlobal)
                it.params[6] = alt - homeAlt;
            else if (frame == mav::kFrameGlobalTerrainAlt)
                return lineError(source, lineNo,
                                 "frame 10 (altitude above terrain) cannot be read back without the terrain model: "
                                 "export with altitudes above sea level or relative to home");
            else if (frame != mav::kFrameGlobalRelativeAlt && frame != 6)
                return lineError(source, lineNo,
                                 "frame " + std::to_string(frame) +
                                     " is not supported (use 3, altitude relative to home)");
            it.frame = mav::kFrameGlobalRelativeAlt;
        }
        items.push_back(it);
    }
    auto read = routeFromItems(items);
    if (!read)
        return makeError(read.error().code, source + ": " + read.error().message);
    route::Route r = std::move(*read);
    r.home = out.home;
    out.routes.push_back(std::move(r));
    out.kinds.push_back(kindFromItems(items));
    out.cameraTiltDeg = cameraTiltFromItems(items);
    return out;
}

Result<ImportedWaypoints> readQgcWpl(const std::string& path) {
    auto text = detail::readTextFile(path);
    if (!text)
        return text.error();
    return parseQgcWpl(*text, path);
}

} // namespace pf::io
