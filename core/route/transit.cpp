#include "core/route/transit.h"

#include <cstdio>

namespace pf::route {

namespace {
std::string where(const geo::Vec2& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.1f, %.1f) m", p.x(), p.y());
    return buf;
}

double polylineLength(const std::vector<geo::Vec2>& pts) {
    double len = 0;
    for (std::size_t i = 1; i < pts.size(); ++i)
        len += (pts[i] - pts[i - 1]).norm();
    return len;
}
} // namespace

Result<std::vector<geo::Vec2>> safePolyline(const geo::Vec2& a, const geo::Vec2& b, const SafePathFinder& finder) {
    auto mid = finder.detour(a, b);
    if (!mid)
        return mid.error();
    std::vector<geo::Vec2> out;
    out.reserve(mid->size() + 2);
    out.push_back(a);
    out.insert(out.end(), mid->begin(), mid->end());
    out.push_back(b);
    return out;
}

Result<std::vector<LocalWaypoint>> withTransit(const std::vector<LocalWaypoint>& survey, const geo::Vec2& home,
                                               const SafePathFinder& finder, const std::optional<geo::Vec2>& landing,
                                               TransitReport* report) {
    TransitReport local;
    TransitReport& rep = report ? *report : local;
    const double margin = finder.field().marginM();
    char m[32];
    std::snprintf(m, sizeof m, "%.1f", margin);
    if (!finder.field().pointIsSafe(home))
        return makeError(ErrorCode::InvalidInput, "The home point " + where(home) + " lies within the " +
                                                      std::string(m) + " m safety margin of a no-fly zone: move it.");
    const geo::Vec2 land = landing.value_or(home);
    if (!finder.field().pointIsSafe(land))
        return makeError(ErrorCode::InvalidInput, "The landing point " + where(land) + " lies within the " +
                                                      std::string(m) + " m safety margin of a no-fly zone: move it.");
    if (survey.empty())
        return survey;
    auto out = safePolyline(home, survey.front().pos, finder);
    if (!out)
        return makeError(out.error().code, "Transit from home to the first waypoint: " + out.error().message);
    auto back = safePolyline(survey.back().pos, land, finder);
    if (!back)
        return makeError(back.error().code, "Transit from the last waypoint back home: " + back.error().message);
    rep.outboundM = polylineLength(*out);
    rep.returnM = polylineLength(*back);
    std::vector<LocalWaypoint> wps;
    wps.reserve(survey.size() + out->size() + back->size());
    auto addTransit = [&](const std::vector<geo::Vec2>& pts) {
        for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
            LocalWaypoint w;
            w.pos = pts[i];
            w.headingDeg = headingDeg(pts[i], pts[i + 1]);
            w.kind = WaypointKind::Transit;
            wps.push_back(w);
            ++rep.waypointsAdded;
        }
    };
    addTransit(*out);
    wps.insert(wps.end(), survey.begin(), survey.end());
    addTransit(*back);
    return wps;
}

} // namespace pf::route
