#include "core/mission/corridor.h"

#include "core/geo/polygon_ops.h"
#include "core/plan/corridor/corridor_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pf::mission {

namespace {

std::string num(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, std::abs(v) >= 1e9 ? "%g" : f, v);
    return buf;
}

Result<geo::LocalFrame> lineFrame(const geo::GeoRing& line) {
    double lo0 = line.front().lon, lo1 = lo0, la0 = line.front().lat, la1 = la0;
    for (const auto& p : line) {
        lo0 = std::min(lo0, p.lon);
        lo1 = std::max(lo1, p.lon);
        la0 = std::min(la0, p.lat);
        la1 = std::max(la1, p.lat);
    }
    return geo::LocalFrame::create({0.5 * (lo0 + lo1), 0.5 * (la0 + la1)});
}

} // namespace

std::vector<geo::Problem> validateCorridor(const Corridor& c) {
    std::vector<geo::Problem> out;
    auto error = [&](std::string msg) { out.push_back({geo::Severity::Error, std::move(msg)}); };
    for (std::size_t i = 0; i < c.line.size(); ++i) {
        const auto& p = c.line[i];
        if (!std::isfinite(p.lon) || !std::isfinite(p.lat) || std::abs(p.lon) > 180 ||
            std::abs(p.lat) > 85) {
            error("the corridor's point " + std::to_string(i + 1) + " (" + num("%.6f", p.lon) +
                  ", " + num("%.6f", p.lat) +
                  ") is out of range: longitude must lie within ±180 and latitude within ±85 "
                  "degrees");
            return out;
        }
    }
    if (!std::isfinite(c.widthM) || c.widthM <= 0)
        error("the corridor's width must be greater than 0 m (got " + num("%g", c.widthM) + " m)");
    else if (c.widthM > kMaxCorridorWidthM)
        error("the corridor's width of " + num("%.0f", c.widthM) + " m is more than " +
              num("%.0f", kMaxCorridorWidthM) + " m: survey it as an area");
    if (c.line.empty()) {
        error("the corridor has no line: draw its centre line or import it from a file");
        return out;
    }
    auto frame = lineFrame(c.line);
    if (!frame) {
        error("the corridor's line: " + frame.error().message);
        return out;
    }
    const auto line = corridorLine(c, *frame);
    if (line.size() < 2)
        error("the corridor's line needs at least two distinct points (it has " +
              std::to_string(line.size()) + ")");
    else if (plan::lineLength(line) > kMaxCorridorLengthM)
        error("the corridor's line is " + num("%.1f", plan::lineLength(line) / 1000.0) +
              " km long, more than " + num("%.0f", kMaxCorridorLengthM / 1000.0) +
              " km: split it into several missions");
    return out;
}

Result<geo::GeoPolygon> corridorArea(const Corridor& c) {
    const auto problems = validateCorridor(c);
    if (!problems.empty())
        return makeError(ErrorCode::InvalidGeometry, problems.front().message);
    auto frame = lineFrame(c.line);
    if (!frame)
        return frame.error();
    const geo::MultiPolygon ground = plan::corridorGround(corridorLine(c, *frame), c.widthM);
    if (ground.empty())
        return makeError(ErrorCode::InvalidGeometry, "the corridor has no ground");
    // One connected line gives one polygon (a line crossing itself: with holes).
    const auto largest = std::max_element(
        ground.begin(), ground.end(),
        [](const geo::Polygon& a, const geo::Polygon& b) { return geo::area(a) < geo::area(b); });
    return geo::cleanPolygon(frame->toGeo(*largest));
}

void applyCorridor(Mission& m, std::optional<Corridor> c) {
    m.corridor = std::move(c);
    m.area = {};
    if (m.corridor)
        if (auto a = corridorArea(*m.corridor))
            m.area = std::move(*a);
}

std::vector<geo::Vec2> corridorLine(const Corridor& c, const geo::LocalFrame& frame) {
    return plan::cleanLine(frame.toLocal(c.line));
}

double corridorLengthM(const Corridor& c) {
    if (c.line.size() < 2)
        return 0.0;
    auto frame = lineFrame(c.line);
    return frame ? plan::lineLength(corridorLine(c, *frame)) : 0.0;
}

} // namespace pf::mission
