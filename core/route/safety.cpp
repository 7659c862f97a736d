#include "core/route/safety.h"

#include "core/job_scope.h"

#include "core/geo/polygon_ops.h"
#include "core/geo/point_text.h"
#include "core/sensor/footprint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <queue>

namespace pf::route {

namespace {

using geo::fixedText;
using geo::pointText;
using geo::Vec2;

} // namespace

// ---------------------------------------------------------------------------------------------

double headingDeg(const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    if (d.squaredNorm() == 0.0)
        return 0.0;
    double h = std::atan2(d.x(), d.y()) * 180.0 / M_PI;
    if (h < 0)
        h += 360.0;
    return h >= 360.0 ? 0.0 : h;
}

// ---------------------------------------------------------------------------------------------

Result<std::vector<LocalWaypoint>> enforceNoFly(const std::vector<LocalWaypoint>& waypoints,
                                                const SafePathFinder& finder, SafetyReport* report) {
    SafetyReport local;
    SafetyReport& rep = report ? *report : local;
    std::vector<LocalWaypoint> moved = waypoints;
    for (std::size_t i = 0; i < moved.size(); ++i) {
        if ((i & 0xFFFF) == 0 && stopRequested())
            return makeError(ErrorCode::Cancelled, "making the route safe: cancelled");
        if (finder.field().pointIsSafe(moved[i].pos))
            continue;
        const Vec2 to = finder.nearestSafePoint(moved[i].pos);
        rep.warnings.push_back("Waypoint " + std::to_string(i + 1) + " at " + pointText(moved[i].pos) +
                               " was inside a no-fly margin and moved " +
                               fixedText((to - moved[i].pos).norm()) + " m out.");
        moved[i].pos = to;
        ++rep.waypointsMoved;
    }
    std::vector<LocalWaypoint> out;
    out.reserve(moved.size());
    for (std::size_t i = 0; i < moved.size(); ++i) {
        if ((i & 0x3FF) == 0 && stopRequested())
            return makeError(ErrorCode::Cancelled, "making the route safe: cancelled");
        if (i > 0) {
            const Vec2 a = moved[i - 1].pos, b = moved[i].pos;
            auto path = finder.detour(a, b);
            if (!path)
                return makeError(path.error().code, "Between waypoints " + std::to_string(i) + " and " +
                                                        std::to_string(i + 1) + ": " + path.error().message);
            if (!path->empty()) {
                ++rep.detours;
                double len = 0;
                Vec2 prev = a;
                for (std::size_t j = 0; j < path->size(); ++j) {
                    const Vec2 next = j + 1 < path->size() ? (*path)[j + 1] : b;
                    LocalWaypoint w;
                    w.pos = (*path)[j];
                    w.headingDeg = headingDeg(w.pos, next);
                    w.kind = WaypointKind::Transit;
                    out.push_back(w);
                    len += (w.pos - prev).norm();
                    prev = w.pos;
                    ++rep.detourWaypoints;
                }
                len += (b - prev).norm();
                rep.addedLengthM += len - (b - a).norm();
            }
        }
        out.push_back(moved[i]);
    }
    return out;
}

Result<std::vector<LocalWaypoint>> keepInsideArea(const std::vector<LocalWaypoint>& waypoints,
                                                  const geo::MultiPolygon& area, const geo::MultiPolygon& admissible,
                                                  const PhotoSides& sides, double marginM,
                                                  const SafePathFinder& finder, SafetyReport* report) {
    SafetyReport local;
    SafetyReport& rep = report ? *report : local;
    if (!(sides.effectiveAcrossM > 0) || !(sides.effectiveAlongM > 0) || !(sides.realAcrossM > 0) ||
        !(sides.realAlongM > 0))
        return makeError(ErrorCode::InvalidInput, "Keeping waypoints inside the area needs positive footprint sides.");
    if (marginM < 0)
        return makeError(ErrorCode::InvalidInput, "The inside margin must not be negative.");
    const geo::MultiPolygon inner = marginM > 0 ? geo::buffer(area, -marginM) : area;
    if (inner.empty() || geo::area(inner) <= 0)
        return makeError(ErrorCode::InvalidInput, "The area shrunk by the inside margin of " + fixedText(marginM) +
                                                      " m is empty: reduce the margin.");
    auto rect = [](const Vec2& p, double h, double across, double along) {
        return geo::Polygon{sensor::footprintRing(sensor::PhotoFootprint{p, h, across, along}), {}};
    };
    std::vector<LocalWaypoint> out = waypoints;
    for (std::size_t i = 0; i < out.size(); ++i) {
        auto& w = out[i];
        if (w.kind == WaypointKind::Transit || geo::contains(inner, w.pos))
            continue;
        const Vec2 from = w.pos;
        const Vec2 target = geo::nearestOnBoundary(inner, from);
        if (w.kind == WaypointKind::Turn) {
            if (finder.field().pointIsSafe(target)) {
                w.pos = target;
                ++rep.keptInside;
            } else {
                ++rep.leftOutside;
                rep.warnings.push_back("Turn waypoint " + std::to_string(i + 1) +
                                       " stays outside the area: the nearest inside point is in a no-fly margin.");
            }
            continue;
        }
        const auto resp = geo::intersection(admissible, rect(from, w.headingDeg, sides.effectiveAcrossM,
                                                             sides.effectiveAlongM));
        const double respArea = geo::area(resp);
        auto feasible = [&](double t) {
            const Vec2 q = from + t * (target - from);
            if (!finder.field().pointIsSafe(q))
                return false;
            if (respArea <= 1e-9)
                return true;
            const auto left = geo::difference(resp, geo::MultiPolygon{rect(q, w.headingDeg, sides.realAcrossM,
                                                                            sides.realAlongM)});
            return geo::area(left) <= 1e-6 * respArea + 1e-6;
        };
        if (feasible(1.0)) {
            w.pos = target;
            ++rep.keptInside;
            continue;
        }
        double lo = 0.0, hi = 1.0;
        for (int it = 0; it < 14; ++it) {
            const double mid = 0.5 * (lo + hi);
            (feasible(mid) ? lo : hi) = mid;
        }
        w.pos = from + lo * (target - from);
        ++rep.leftOutside;
        rep.warnings.push_back("Photo waypoint " + std::to_string(i + 1) + " stays " +
                               fixedText((target - w.pos).norm()) +
                               " m outside the area: moving it further in would leave part of its ground unphotographed.");
    }
    return out;
}

} // namespace pf::route
