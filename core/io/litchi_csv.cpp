#include "core/io/litchi_csv.h"

#include "core/io/mission_items.h"
#include "core/io/waypoint_format_util.h"
#include "core/plan/flight_time.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace pf::io {

namespace {

constexpr int kActions = 15;
constexpr int kStay = 0;      // Litchi action type "stay for" (parameter: milliseconds)
constexpr int kTakePhoto = 1; // Litchi action type "take photo"

std::vector<std::string> columns() {
    std::vector<std::string> c{"latitude",     "longitude",   "altitude(m)", "heading(deg)",
                               "curvesize(m)", "rotationdir", "gimbalmode",  "gimbalpitchangle"};
    for (int i = 1; i <= kActions; ++i) {
        c.push_back("actiontype" + std::to_string(i));
        c.push_back("actionparam" + std::to_string(i));
    }
    for (const char* s :
         {"altitudemode", "speed(m/s)", "poi_latitude", "poi_longitude", "poi_altitude(m)",
          "poi_altitudemode", "photo_timeinterval", "photo_distinterval"})
        c.push_back(s);
    return c;
}

} // namespace

std::string litchiCsvHeader() {
    std::string h;
    for (const auto& c : columns())
        h += (h.empty() ? "" : ",") + c;
    return h;
}

Result<std::string> litchiCsvText(const ExportContext& ctx, std::size_t routeIndex) {
    using detail::formatNumber;
    if (routeIndex >= ctx.routes.size())
        return makeError(ErrorCode::InvalidInput,
                         "there is no route " + std::to_string(routeIndex + 1) + " to export");
    const route::Route& r = ctx.routes[routeIndex];
    if (r.waypoints.empty())
        return makeError(ErrorCode::InvalidInput,
                         ctx.routeLabel(routeIndex) + ": the route has no waypoints to export");
    // Stops and corners flown through as the flight-time model counted them (plan::isStopCorner,
    // the rule of every export). Litchi's curve size "defines the sharpness of the curve at this
    // waypoint" in missions flown with curved turns (the path mode is a mission setting the CSV
    // does not hold: choose "Curved turns"): a corner flown through gets the model's corner cut, a
    // stop curve size 0 and a "stay for" action (type 0, milliseconds) of the model's hold before
    // its photo.
    const plan::FlightTimeModel model = ctx.aircraftFor(routeIndex)
                                            ? mission::flightModel(*ctx.aircraftFor(routeIndex))
                                            : plan::FlightTimeModel{};
    const geo::LonLat home = ctx.homeFor(routeIndex).value_or(r.waypoints.front().position);
    const std::vector<double> corners =
        cornerAnglesDeg(r.waypoints, home, ctx.landingFor(routeIndex).value_or(home));
    const double pitch = ctx.gimbalPitchDeg(routeIndex);
    std::string out = litchiCsvHeader() + "\n";
    for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
        const auto& w = r.waypoints[i];
        const bool stop = plan::isStopCorner(corners[i], model);
        const double curve = !stop && corners[i] > plan::kTurnThresholdDeg ? model.cornerCutM : 0.0;
        out += formatNumber(w.position.lat, 9) + ',' + formatNumber(w.position.lon, 9) + ',' +
               formatNumber(w.altitudeM, 4) + ',' +
               formatNumber(detail::normaliseHeading(w.headingDeg), 4) + ',' +
               formatNumber(curve, 3);
        // Rotation direction, gimbal mode interpolate, the pitch (-90 straight down; oblique photos:
        // -90 + the tilt).
        out += ",0,2," + formatNumber(pitch, 2);
        std::vector<std::pair<int, double>> actions;
        if (stop)
            actions.emplace_back(kStay, model.stopHoldS * 1000.0);
        if (w.kind == route::WaypointKind::Photo)
            actions.emplace_back(kTakePhoto, 0.0);
        for (std::size_t a = 0; a < static_cast<std::size_t>(kActions); ++a)
            out += a < actions.size() ? "," + std::to_string(actions[a].first) + "," +
                                            formatNumber(actions[a].second, 0)
                                      : std::string(",-1,0");
        out += ",0," + formatNumber(r.cruiseSpeedMps, 3) + ",0,0,0,0,-1,-1\n";
    }
    return out;
}

Status writeLitchiCsv(const ExportContext& ctx, std::size_t routeIndex, const std::string& path) {
    auto text = litchiCsvText(ctx, routeIndex);
    if (!text)
        return text.error();
    return detail::writeTextFile(path, *text);
}

namespace {

// The header's column names (trimmed, lower case) and their indices.
template <typename Fields> std::map<std::string, std::size_t> columnsOf(const Fields& header) {
    std::map<std::string, std::size_t> col;
    for (std::size_t i = 0; i < header.size(); ++i) {
        std::string name(detail::trim(header[i]));
        std::transform(name.begin(), name.end(), name.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        col.emplace(name, i);
    }
    return col;
}

} // namespace

Result<ImportedWaypoints> parseLitchiCsv(const std::string& text, const std::string& source) {
    using detail::lineError;
    const auto lines = detail::splitLines(text);
    std::size_t first = 0;
    while (first < lines.size() && detail::trim(lines[first]).empty())
        ++first;
    if (first == lines.size())
        return makeError(ErrorCode::ParseError, source + ": the file is empty");
    // A spreadsheet in a locale with decimal commas saves "49,0108;8,3272;...": semicolons between
    // the fields, commas in the numbers.
    const std::string_view headerLine = lines[first];
    const char sep = headerLine.find(',') == std::string_view::npos && headerLine.find(';') != std::string_view::npos
                         ? ';'
                         : ',';
    const auto header = detail::splitChar(lines[first], sep);
    const std::map<std::string, std::size_t> col = columnsOf(header);
    for (const char* required : {"latitude", "longitude", "altitude(m)", "heading(deg)"})
        if (!col.count(required))
            return lineError(source, first + 1,
                             std::string("not a Litchi waypoint CSV: the header has no \"") +
                                 required + "\" column");

    ImportedWaypoints out;
    route::Route r;
    std::vector<bool> photo;
    bool speedSet = false;
    for (std::size_t li = first + 1; li < lines.size(); ++li) {
        const std::size_t lineNo = li + 1;
        if (detail::trim(lines[li]).empty())
            continue;
        const auto fields = detail::splitChar(lines[li], sep);
        if (fields.size() != header.size())
            return lineError(source, lineNo,
                             "expected " + std::to_string(header.size()) +
                                 (sep == ';' ? " semicolon" : " comma") + "-separated fields but found " +
                                 std::to_string(fields.size()));
        auto number = [&](const std::string& name) -> Result<double> {
            const std::string_view f = fields[col.at(name)];
            std::string decimal(f);
            if (sep == ';')
                std::replace(decimal.begin(), decimal.end(), ',', '.');
            auto v = detail::parseNumber(decimal);
            if (!v)
                return lineError(source, lineNo,
                                 "column " + name + ": \"" + std::string(detail::trim(f)) +
                                     "\" is not a number");
            return *v;
        };
        auto lat = number("latitude");
        if (!lat)
            return lat.error();
        auto lon = number("longitude");
        if (!lon)
            return lon.error();
        auto alt = number("altitude(m)");
        if (!alt)
            return alt.error();
        auto hdg = number("heading(deg)");
        if (!hdg)
            return hdg.error();
        if (std::abs(*lat) > 90 || std::abs(*lon) > 180)
            return lineError(source, lineNo, "latitude or longitude out of range");
        bool isPhoto = false;
        for (int a = 1; a <= kActions; ++a) {
            const std::string name = "actiontype" + std::to_string(a);
            if (!col.count(name))
                continue;
            auto t = number(name);
            if (!t)
                return t.error();
            // Compared as a number: casting a huge value to int would be undefined behaviour.
            isPhoto = isPhoto || *t == kTakePhoto;
        }
        if (!speedSet && col.count("speed(m/s)")) {
            auto s = number("speed(m/s)");
            if (!s)
                return s.error();
            if (*s > 0) {
                r.cruiseSpeedMps = *s;
                speedSet = true;
            }
        }
        // The first row's gimbal pitch: oblique photos keep their tilt when converted.
        if (r.waypoints.empty() && col.count("gimbalpitchangle"))
            if (auto pitch = number("gimbalpitchangle"))
                out.cameraTiltDeg = cameraTiltFromPitch(*pitch);
        route::Waypoint w;
        w.position = {*lon, *lat};
        w.altitudeM = *alt;
        w.headingDeg = detail::normaliseHeading(*hdg);
        r.waypoints.push_back(w);
        photo.push_back(isPhoto);
    }
    detail::inferNonPhotoKinds(r.waypoints, photo);
    out.routes.push_back(std::move(r));
    return out;
}

Result<ImportedWaypoints> readLitchiCsv(const std::string& path) {
    auto text = detail::readTextFile(path);
    if (!text)
        return text.error();
    return parseLitchiCsv(*text, path);
}

} // namespace pf::io
