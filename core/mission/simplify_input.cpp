#include "core/mission/simplify_input.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/simplify.h"
#include "core/geo/validation.h"
#include "core/mission/validation.h"
#include "core/sensor/camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace pf::mission {

namespace {

// Without the repeated closing vertex of each ring.
std::size_t vertexCount(const geo::GeoPolygon& p) {
    const auto ringCount = [](const geo::GeoRing& r) {
        return r.size() - (r.size() > 1 && r.front() == r.back() ? 1 : 0);
    };
    std::size_t n = ringCount(p.outer);
    for (const auto& h : p.holes)
        n += ringCount(h);
    return n;
}

std::string thousands(std::size_t n) {
    std::string s = std::to_string(n), out;
    const int len = static_cast<int>(s.size());
    for (int i = 0; i < len; ++i) {
        out += s[static_cast<std::size_t>(i)];
        if ((len - i - 1) % 3 == 0 && i + 1 < len)
            out += ',';
    }
    return out;
}

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// The widening that puts every point within `toleranceM` of the simplified boundary inside it: the
// buffer's round corners are drawn with 2 segments a quadrant, whose chords lie cos(22.5 deg) of
// the radius from the corner.
constexpr int kBufferQuadrantSegments = 2;
double wideningFor(double toleranceM) {
    return toleranceM / std::cos(M_PI / (4.0 * kBufferQuadrantSegments));
}

// `poly` simplified within `toleranceM` and widened to hold the given polygon; nothing when it has
// no vertex to spare or GEOS cannot simplify it into one valid polygon.
std::optional<geo::Polygon> simplifiedAndWidened(const geo::Polygon& poly, double toleranceM) {
    const geo::Polygon s = geo::simplified(poly, toleranceM);
    if (geo::vertexCount(s) >= geo::vertexCount(poly))
        return std::nullopt; // nothing to simplify (a hand-drawn zone): planned exactly as given
    if (geo::vertexCount(s) > kMaxPlanVertices)
        return s; // refused anyway (limitError): not worth widening
    const geo::MultiPolygon wide = geo::buffer(s, wideningFor(toleranceM), kBufferQuadrantSegments);
    if (wide.size() != 1)
        return std::nullopt;
    return wide.front();
}

std::string noteFor(const InputSimplification& r) {
    const double change = r.areaAfterM2 - r.areaBeforeM2;
    const double pct = r.areaBeforeM2 > 0.0 ? 100.0 * change / r.areaBeforeM2 : 0.0;
    const std::string within =
        " within " + fixed(r.toleranceM, 2) +
        " m (5 % of the smallest track spacing, at most 0.5 m) and widened by " +
        fixed(wideningFor(r.toleranceM), 2) + " m";
    std::string note;
    if (r.areaVerticesAfter != r.areaVerticesBefore)
        note = "the area's traced boundary of " + thousands(r.areaVerticesBefore) +
               " vertices was simplified to " + thousands(r.areaVerticesAfter) + within +
               " so that it holds all of the given area: its area changed by " +
               (change >= 0 ? "+" : "") + fixed(change, 0) + " m2 (" + (change >= 0 ? "+" : "") +
               fixed(pct, 3) + " %)";
    if (r.zoneVerticesBefore != r.zoneVerticesAfter)
        note += (note.empty() ? "the no-fly zones' " : "; the no-fly zones' ") +
                thousands(r.zoneVerticesBefore) + " vertices became " +
                thousands(r.zoneVerticesAfter) + (note.empty() ? within : std::string()) +
                ", each zone widened to hold all of the given one";
    return note;
}

std::string limitError(const InputSimplification& r) {
    const std::size_t after = r.areaVerticesAfter + r.zoneVerticesAfter;
    const std::string what =
        r.zoneVerticesAfter > 0 ? "the area and its no-fly zones have " : "the area has ";
    return what + thousands(after) + " vertices" +
           (r.simplified ? " after simplifying to " + fixed(r.toleranceM, 2) + " m"
                         : std::string()) +
           "; Photoflight plans areas of at most " + thousands(kMaxPlanVertices) +
           " vertices (area and no-fly zones together): simplify it in a GIS first";
}

} // namespace

double simplifyToleranceM(const Mission& m) {
    double tol = kMaxSimplifyToleranceM;
    for (const auto& a : m.aircraft) {
        auto alt = resolvedAltitude(a);
        if (!alt)
            continue;
        auto eff = sensor::effectiveFootprint(a.camera, *alt, a.overlap);
        if (eff && std::isfinite(eff->acrossM) && eff->acrossM > 0.0)
            tol = std::min(tol, kSimplifyShareOfSpacing * eff->acrossM);
    }
    return tol;
}

InputSimplification simplifyInput(const Mission& m, bool checkedValid) {
    InputSimplification r;
    r.mission = m;
    r.areaVerticesBefore = r.areaVerticesAfter = vertexCount(m.area);
    for (const auto& z : m.noFlyZones)
        r.zoneVerticesBefore += vertexCount(z.polygon);
    r.zoneVerticesAfter = r.zoneVerticesBefore;
    if (m.corridor || r.areaVerticesBefore + r.zoneVerticesBefore <= kSimplifyAboveVertices)
        return r;
    // An invalid polygon stays as given, so that validation names its vertices as the user knows
    // them.
    if (!checkedValid && geo::hasError(geo::validatePolygon(m.area, "the area")))
        return r;
    auto frame = geo::LocalFrame::forArea(geo::cleanPolygon(m.area));
    if (!frame)
        return r;
    r.toleranceM = simplifyToleranceM(m);
    const geo::Polygon area = frame->toLocal(geo::cleanPolygon(m.area));
    r.areaBeforeM2 = r.areaAfterM2 = geo::area(area);
    if (auto s = simplifiedAndWidened(area, r.toleranceM)) {
        r.mission.area = frame->toGeo(*s);
        r.areaVerticesAfter = geo::vertexCount(*s);
        r.areaAfterM2 = geo::area(*s);
    }
    r.zoneVerticesAfter = 0;
    for (auto& z : r.mission.noFlyZones) {
        if (!checkedValid && geo::hasError(geo::validatePolygon(z.polygon, "a zone"))) {
            r.zoneVerticesAfter += vertexCount(z.polygon);
            continue;
        }
        if (auto s =
                simplifiedAndWidened(frame->toLocal(geo::cleanPolygon(z.polygon)), r.toleranceM))
            z.polygon = frame->toGeo(*s);
        r.zoneVerticesAfter += vertexCount(z.polygon);
    }
    r.simplified = r.mission.area != m.area || r.zoneVerticesAfter != r.zoneVerticesBefore;
    if (r.simplified)
        r.note = noteFor(r);
    if (r.areaVerticesAfter + r.zoneVerticesAfter > kMaxPlanVertices)
        r.error = limitError(r);
    return r;
}

} // namespace pf::mission
