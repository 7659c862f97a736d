#include "core/mission/route_check.h"

#include "core/fleet/aircraft.h"
#include "core/geo/local_frame.h"
#include "core/geo/no_fly_field.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/prepared_region.h"
#include "core/sensor/footprint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pf::mission {

namespace {

std::string num(double v, int decimals = 1) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

void add(std::string& slot, const std::string& why) { slot += (slot.empty() ? "" : "; ") + why; }

// A clearance that breaches the margin, with the decimals it takes to read as less than the least
// clearance allowed: 4.96 m for a leg 4.964 m from a zone with a 5 m margin, never "5.0 m (margin
// 5.0 m)", which reads as if the margin were kept.
std::string breachText(double c, const geo::NoFlyField& f) {
    int decimals = 1;
    double scale = 10.0;
    while (decimals < 4 && std::round(c * scale) / scale >= f.minClearance()) {
        ++decimals;
        scale *= 10.0;
    }
    return num(c, decimals);
}

// A frame for the check: centred on the area when there is one, else on the route itself.
Result<geo::LocalFrame> frameFor(const route::Route& route, const RouteLimits& limits) {
    if (limits.area.outer.size() >= 3)
        return geo::LocalFrame::forArea(limits.area);
    geo::GeoPolygon box;
    for (const auto& w : route.waypoints)
        box.outer.push_back(w.position);
    if (limits.home)
        box.outer.push_back(*limits.home);
    if (box.outer.empty())
        return makeError(ErrorCode::InvalidInput, "the route has no waypoint");
    return geo::LocalFrame::forArea(box);
}

// Whether the photo a waypoint outside the area would take sees part of it: its footprint at the
// waypoint's height above the ground, turned to its heading, meets the area. `d` is the waypoint's
// distance from the area. Unset when the camera gives no footprint.
std::optional<bool> photoSeesArea(const route::Route& route, std::size_t i, const geo::Vec2& p,
                                  double d, const sensor::Camera& cam, const geo::Polygon& area,
                                  std::optional<geo::PreparedRegion>& prepared) {
    const auto& w = route.waypoints[i];
    const double h = route.homeElevationM && w.groundM
                         ? *route.homeElevationM + w.altitudeM - *w.groundM
                         : w.altitudeM;
    const auto fp = sensor::footprintAt(cam, h);
    if (!fp)
        return std::nullopt;
    // Around the waypoint for nadir photos; an oblique photo's lies aheadM ahead of it.
    if (fp->aheadM == 0.0 && d <= 0.5 * std::min(fp->shortSideM, fp->longSideM))
        return true; // the disc the footprint always holds reaches the area
    if (d > fp->aheadM + 0.5 * std::hypot(fp->longSideM, fp->shortSideM))
        return false; // farther than the footprint's corners
    if (!prepared)
        prepared.emplace(geo::MultiPolygon{area});
    const sensor::PhotoFootprint f = sensor::photoTakenFrom(p, w.headingDeg, *fp);
    return prepared->intersects(geo::Polygon{sensor::footprintRing(f), {}});
}

// The waypoints outside the area, grouped by why they are there (OutsideReason); `total` gets their
// number.
std::vector<OutsideGroup> outsideGroups(const route::Route& route, const RouteLimits& limits,
                                        const geo::LocalFrame& frame,
                                        const std::vector<geo::Vec2>& local, int* total) {
    const geo::Polygon area = frame.toLocal(limits.area);
    // A lane ends on the boundary itself: a waypoint within 5 cm of it (rounding of the exact
    // geometry and of the WGS84 round trip) is inside.
    constexpr double kOnBoundaryM = 0.05;
    // Home as the route's transit waypoint between two sorties lies within this of it.
    constexpr double kAtHomeM = 1.0;
    const bool hasHome = limits.home.has_value();
    const geo::Vec2 home = hasHome ? frame.toLocal(*limits.home) : geo::Vec2(0, 0);
    std::vector<OutsideGroup> groups(5);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        groups[g].reason = OutsideReason(g);
        groups[g].atHomeOnly = groups[g].reason == OutsideReason::Transit;
    }
    std::optional<geo::PreparedRegion> prepared;
    for (std::size_t i = 0; i < local.size(); ++i) {
        if (geo::contains(area, local[i]))
            continue;
        const double d = geo::distanceTo(area, local[i]);
        if (d <= kOnBoundaryM)
            continue;
        const bool transit = route.waypoints[i].kind == route::WaypointKind::Transit;
        const bool planeTurn = limits.plane && route.waypoints[i].kind == route::WaypointKind::Turn;
        std::optional<bool> sees;
        if (!transit && !planeTurn && limits.camera)
            sees = photoSeesArea(route, i, local[i], d, *limits.camera, area, prepared);
        const OutsideReason reason = transit     ? OutsideReason::Transit
                                     : planeTurn ? OutsideReason::PlaneTurn
                                     : !sees     ? OutsideReason::Unknown
                                     : *sees     ? OutsideReason::CoversBoundary
                                                 : OutsideReason::SeesNothing;
        OutsideGroup& g = groups[std::size_t(reason)];
        g.waypoints.push_back(int(i));
        if (transit && !(hasHome && (local[i] - home).norm() <= kAtHomeM))
            g.atHomeOnly = false;
        if (d > g.farthestM) {
            g.farthestM = d;
            g.farthest = int(i);
        }
        ++*total;
    }
    groups.erase(std::remove_if(groups.begin(), groups.end(),
                                [](const OutsideGroup& g) { return g.waypoints.empty(); }),
                 groups.end());
    return groups;
}

} // namespace

const OutsideGroup* RouteCheck::outsideGroup(OutsideReason reason) const {
    for (const auto& g : outside)
        if (g.reason == reason)
            return &g;
    return nullptr;
}

int RouteCheck::count() const {
    int n = (fromHome.empty() ? 0 : 1) + (toHome.empty() ? 0 : 1);
    for (const auto& s : waypoint)
        n += s.empty() ? 0 : 1;
    for (const auto& s : leg)
        n += s.empty() ? 0 : 1;
    return n;
}

std::vector<std::string> RouteCheck::messages(const std::string& routeLabel) const {
    std::vector<std::string> out;
    if (!fromHome.empty())
        out.push_back(routeLabel + ", take-off: " + fromHome);
    for (std::size_t i = 0; i < waypoint.size(); ++i) {
        if (!waypoint[i].empty())
            out.push_back(routeLabel + ", waypoint " + std::to_string(i + 1) + ": " + waypoint[i]);
        if (i < leg.size() && !leg[i].empty())
            out.push_back(routeLabel + ", waypoint " + std::to_string(i + 1) + ": " + leg[i]);
    }
    if (!toHome.empty())
        out.push_back(routeLabel + ", landing: " + toHome);
    return out;
}

RouteCheck checkRoute(const route::Route& route, const RouteLimits& limits) {
    RouteCheck out;
    const std::size_t n = route.waypoints.size();
    out.waypoint.resize(n);
    out.leg.resize(n > 0 ? n - 1 : 0);
    for (std::size_t i = 0; i < n; ++i) {
        // Over a terrain model the limits hold above the ground under the waypoint (a legal ceiling
        // and a safe height are heights above ground), not above the take-off point.
        const auto& w = route.waypoints[i];
        const bool agl = route.homeElevationM && w.groundM;
        const double alt = agl ? *route.homeElevationM + w.altitudeM - *w.groundM : w.altitudeM;
        const std::string what = agl ? "height above ground " : "altitude ";
        if (!std::isfinite(alt) || alt < limits.minAltitudeM)
            add(out.waypoint[i], what + num(alt) + " m is below the minimum safe altitude of " +
                                     num(limits.minAltitudeM) + " m");
        else if (limits.maxAltitudeM && alt > *limits.maxAltitudeM)
            add(out.waypoint[i], what + num(alt) + " m is above the aircraft's maximum of " +
                                     num(*limits.maxAltitudeM) + " m");
    }
    if (n == 0)
        return out;
    auto frame = frameFor(route, limits);
    if (!frame)
        return out;
    // One transformation for all waypoints (one call per point allocates inside PROJ each time).
    geo::GeoRing geoPoints(n);
    for (std::size_t i = 0; i < n; ++i)
        geoPoints[i] = route.waypoints[i].position;
    const std::vector<geo::Vec2> local = frame->toLocal(geoPoints);

    // One field per zone, so that a message names the zone. The check's threshold: margin less the
    // drawing tolerance, without the planner's slack (geo/no_fly_field.h).
    const double margin = limits.safetyMarginM;
    std::vector<geo::NoFlyField> fields;
    std::vector<geo::Polygon> localZones;
    for (const auto& z : limits.zones) {
        localZones.push_back(frame->toLocal(z.polygon));
        fields.push_back(geo::NoFlyField::forCheck(std::vector<geo::Polygon>{localZones.back()}, margin));
    }
    // All zones at once answer "safe" fast (far zones skipped by their boxes); the zone by zone
    // clearance that names the zone is measured only where that answer is no.
    const geo::NoFlyField all = geo::NoFlyField::forCheck(localZones, margin);
    auto zoneName = [&](std::size_t z) {
        return limits.zones[z].name.empty() ? "no-fly zone " + std::to_string(z + 1)
                                            : "no-fly zone " + limits.zones[z].name;
    };
    // The message names the first zone breached; every zone breached is recorded.
    std::vector<bool> entered(fields.size(), false);
    auto pointProblem = [&](const geo::Vec2& p) -> std::string {
        if (all.pointIsSafe(p))
            return {};
        std::string why;
        for (std::size_t z = 0; z < fields.size(); ++z) {
            const double c = fields[z].clearance(p);
            if (fields[z].isSafeClearance(c) && c > 0.0)
                continue;
            entered[z] = true;
            if (why.empty())
                why = c <= 0.0 ? "inside " + zoneName(z)
                               : breachText(c, fields[z]) + " m from " + zoneName(z) + " (margin " +
                                     num(margin) + " m)";
        }
        return why;
    };
    auto legProblem = [&](const geo::Vec2& a, const geo::Vec2& b, const std::string& what) -> std::string {
        if (all.segmentIsSafe(a, b))
            return {};
        std::string why;
        for (std::size_t z = 0; z < fields.size(); ++z) {
            const double c = fields[z].clearance(a, b);
            if (fields[z].isSafeClearance(c) && c > 0.0)
                continue;
            entered[z] = true;
            if (why.empty())
                why = c <= 0.0 ? what + " crosses " + zoneName(z)
                               : what + " passes " + breachText(c, fields[z]) + " m from " +
                                     zoneName(z) + " (margin " + num(margin) + " m)";
        }
        return why;
    };
    for (std::size_t i = 0; i < n; ++i)
        if (auto why = pointProblem(local[i]); !why.empty()) {
            add(out.waypoint[i], why);
            ++out.noFly;
        }
    for (std::size_t i = 0; i + 1 < n; ++i) {
        if (all.segmentIsSafe(local[i], local[i + 1]))
            continue; // no message to build
        out.leg[i] = legProblem(local[i], local[i + 1], "the leg to waypoint " + std::to_string(i + 2));
        out.noFly += out.leg[i].empty() ? 0 : 1;
    }
    if (limits.home) {
        out.fromHome = legProblem(frame->toLocal(*limits.home), local.front(), "the leg from home to waypoint 1");
        out.noFly += out.fromHome.empty() ? 0 : 1;
    }
    if (const auto& land = limits.landing ? limits.landing : limits.home) {
        out.toHome = legProblem(local.back(), frame->toLocal(*land),
                                "the leg from waypoint " + std::to_string(n) + " back home");
        out.noFly += out.toHome.empty() ? 0 : 1;
    }

    for (std::size_t z = 0; z < entered.size(); ++z)
        if (entered[z])
            out.zonesEntered.push_back(z);

    if (limits.area.outer.size() >= 3)
        out.outside = outsideGroups(route, limits, *frame, local, &out.outsideArea);
    return out;
}

RouteLimits routeLimits(const Mission& m, const route::Route& route) {
    RouteLimits l;
    l.zones = m.noFlyZones;
    l.safetyMarginM = m.options.safetyMarginM;
    l.area = m.area;
    l.home = route.home;
    for (const auto& a : m.aircraft)
        if (a.name == route.aircraft) {
            l.maxAltitudeM = a.maxAltitudeM;
            l.camera = pointedCamera(a, m.options);
            l.plane = fleet::fliesAsPlane(a.kind);
            if (!l.home)
                l.home = a.home;
        }
    if (!l.home)
        l.home = m.home;
    l.landing = m.landing;
    return l;
}

std::vector<std::string> routeErrors(const Mission& m, const std::vector<route::Route>& routes) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < routes.size(); ++i) {
        const auto& r = routes[i];
        const auto lines = checkRoute(r, routeLimits(m, r)).messages(r.aircraft.empty() ? "route " + std::to_string(i + 1)
                                                                                          : r.aircraft);
        out.insert(out.end(), lines.begin(), lines.end());
    }
    return out;
}

std::vector<std::string> planRouteErrors(const Mission& m, const MissionPlan& plan) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < plan.aircraft.size(); ++i) {
        const auto& a = plan.aircraft[i];
        const std::string label = a.route.aircraft.empty() ? "route " + std::to_string(i + 1) : a.route.aircraft;
        if (a.sortieRoutes.size() < 2) {
            const auto lines = checkRoute(a.route, routeLimits(m, a.route)).messages(label);
            out.insert(out.end(), lines.begin(), lines.end());
            continue;
        }
        for (std::size_t s = 0; s < a.sortieRoutes.size(); ++s) {
            const auto& r = a.sortieRoutes[s];
            RouteLimits limits = routeLimits(m, r);
            if (s + 1 < a.sortieRoutes.size())
                limits.landing.reset(); // every sortie but the last comes back home
            const auto lines = checkRoute(r, limits).messages(label + ", sortie " + std::to_string(s + 1));
            out.insert(out.end(), lines.begin(), lines.end());
        }
    }
    return out;
}

std::vector<std::string> zonesEntered(const Mission& m, const MissionPlan& plan) {
    std::vector<bool> entered(m.noFlyZones.size(), false);
    for (const auto& a : plan.aircraft)
        for (std::size_t z : checkRoute(a.route, routeLimits(m, a.route)).zonesEntered)
            entered[z] = true;
    std::vector<std::string> names;
    for (std::size_t z = 0; z < entered.size(); ++z)
        if (entered[z])
            names.push_back(m.noFlyZones[z].name.empty() ? "no-fly zone " + std::to_string(z + 1)
                                                         : m.noFlyZones[z].name);
    return names;
}

} // namespace pf::mission
