#include "core/geo/validation.h"

#include "core/geo/local_frame.h"
#include "core/geo/ogr_adapter.h"
#include "core/geo/polygon_ops.h"

#include <cpl_error.h>
#include <ogr_geometry.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace pf::geo {

namespace {

// The planning frame (transverse Mercator) is not built beyond this latitude.
constexpr double kMaxLat = 85.0;

std::string fmt(const char* f, double a, double b) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, a, b);
    return buf;
}

// Latitude first with its hemisphere, as the desktop application's cursor readout shows a point:
// "49.011000° N, 8.331000° E" cannot be read the wrong way round.
std::string latLonText(const LonLat& p) {
    return fmt(p.lat >= 0 ? "%.6f° N, " : "%.6f° S, ", std::abs(p.lat), 0.0) +
           fmt(p.lon >= 0 ? "%.6f° E" : "%.6f° W", std::abs(p.lon), 0.0);
}

std::string ringName(int hole, const std::string& what) {
    return hole < 0 ? what : "hole " + std::to_string(hole + 1) + " of " + what;
}

// A cleaned ring with, per vertex, its 1-based number in the ring as given.
struct NumberedRing {
    GeoRing pts;
    std::vector<int> number;
};

NumberedRing numbered(const GeoRing& ring) {
    NumberedRing out;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        if (!out.pts.empty() && out.pts.back() == ring[i])
            continue;
        out.pts.push_back(ring[i]);
        out.number.push_back(static_cast<int>(i) + 1);
    }
    while (out.pts.size() > 1 && out.pts.front() == out.pts.back()) {
        out.pts.pop_back();
        out.number.pop_back();
    }
    return out;
}

int distinctCount(const GeoRing& ring) {
    GeoRing sorted = ring;
    std::sort(sorted.begin(), sorted.end(),
              [](const LonLat& a, const LonLat& b) { return a.lon < b.lon || (a.lon == b.lon && a.lat < b.lat); });
    return static_cast<int>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
}

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Where segments ab and cd meet in more than a shared endpoint of adjacent edges: a proper crossing,
// a vertex touching the other edge, or a collinear overlap. `adjacent` edges share vertex b == c.
bool segmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, bool adjacent, double tol, Vec2* at) {
    const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    const double lab = (b - a).norm(), lcd = (d - c).norm();
    const auto side = [&](double v, double len) { return std::abs(v) <= tol * len ? 0 : (v > 0 ? 1 : -1); };
    const int s1 = side(d1, lcd), s2 = side(d2, lcd), s3 = side(d3, lab), s4 = side(d4, lab);
    if (s1 * s2 < 0 && s3 * s4 < 0) {
        *at = a + (b - a) * (d1 / (d1 - d2));
        return true;
    }
    if (s1 == 0 && s2 == 0 && s3 == 0 && s4 == 0) { // collinear: do they overlap over a length?
        const Vec2 u = (b - a) / std::max(lab, 1e-300);
        double t0 = std::max(0.0, std::min((c - a).dot(u), (d - a).dot(u)));
        double t1 = std::min(lab, std::max((c - a).dot(u), (d - a).dot(u)));
        if (t1 - t0 > tol) {
            *at = a + u * (0.5 * (t0 + t1));
            return true;
        }
        return false;
    }
    if (adjacent)
        return false; // they share b == c and only that
    // A vertex of one lying on the other (a touching ring).
    auto onSeg = [&](const Vec2& p, const Vec2& q0, const Vec2& q1, double len) {
        return std::abs(cross(q0, q1, p)) <= tol * len && (p - q0).dot(q1 - q0) >= -tol * len &&
               (p - q1).dot(q0 - q1) >= -tol * len;
    };
    for (const Vec2* p : {&a, &b})
        if (onSeg(*p, c, d, lcd)) {
            *at = *p;
            return true;
        }
    for (const Vec2* p : {&c, &d})
        if (onSeg(*p, a, b, lab)) {
            *at = *p;
            return true;
        }
    return false;
}

// Whether edges i < j of the ring meet (segmentsMeet, adjacent edges told as such).
bool edgesMeet(const Ring& ring, int i, int j, double tol, Vec2* at) {
    const int n = static_cast<int>(ring.size());
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    const Vec2& c = ring[j];
    const Vec2& d = ring[(j + 1) % n];
    if (i == 0 && j == n - 1) // edges n-1 -> 0 and 0 -> 1 share vertex 0: pass them in that order
        return segmentsMeet(c, d, a, b, true, tol, at);
    return segmentsMeet(a, b, c, d, j == i + 1, tol, at);
}

// Finds the first pair of edges that cross (the smallest first edge, then the smallest second),
// among the pairs whose bounding boxes overlap: the edges are swept in the order of their
// westernmost x, each paired with those that start before it ends, so that a traced boundary of
// 200,000 vertices is searched in well under a second (all pairs would be 2 x 10^10). Only run once GEOS
// has said the ring is not simple, so the cost is paid on the error path only.
bool findCrossing(const Ring& ring, int* e1, int* e2, Vec2* at) {
    const int n = static_cast<int>(ring.size());
    const Box all = bounds(ring);
    const double tol = 1e-9 * std::max(1.0, (all.max - all.min).norm());
    std::vector<Box> box(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const Vec2& a = ring[i];
        const Vec2& b = ring[(i + 1) % n];
        box[static_cast<std::size_t>(i)] = Box{a.cwiseMin(b), a.cwiseMax(b)};
    }
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        order[static_cast<std::size_t>(i)] = i;
    std::sort(order.begin(), order.end(), [&](int x, int y) {
        return box[static_cast<std::size_t>(x)].min.x() < box[static_cast<std::size_t>(y)].min.x();
    });
    int bestI = -1, bestJ = -1;
    for (std::size_t s = 0; s < order.size(); ++s) {
        const Box& bs = box[static_cast<std::size_t>(order[s])];
        for (std::size_t t = s + 1; t < order.size(); ++t) {
            const Box& bt = box[static_cast<std::size_t>(order[t])];
            if (bt.min.x() > bs.max.x())
                break;
            if (!bs.intersects(bt))
                continue;
            const int i = std::min(order[s], order[t]), j = std::max(order[s], order[t]);
            if (bestI >= 0 && std::make_pair(i, j) >= std::make_pair(bestI, bestJ))
                continue;
            Vec2 p;
            if (edgesMeet(ring, i, j, tol, &p)) {
                bestI = i;
                bestJ = j;
                *at = p;
            }
        }
    }
    if (bestI < 0)
        return false;
    *e1 = bestI;
    *e2 = bestJ;
    return true;
}

bool ringIsSimple(const Ring& ring) {
    OGRLineString r; // GEOS judges a closed line string; a bare OGRLinearRing is not handed to it
    for (const auto& p : ring)
        r.addPoint(p.x(), p.y());
    r.addPoint(ring.front().x(), ring.front().y());
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const bool simple = r.IsSimple();
    CPLPopErrorHandler();
    return simple;
}

std::string edgeName(const NumberedRing& r, int e) {
    const int n = static_cast<int>(r.pts.size());
    return std::to_string(r.number[e]) + "-" + std::to_string(r.number[(e + 1) % n]);
}

// Checks one ring; returns false if it is too broken for the checks that need a polygon.
bool checkRing(const GeoRing& raw, int hole, const std::string& what, const LocalFrame* frame,
               std::vector<Problem>& out, Ring* local) {
    const std::string name = ringName(hole, what);
    bool ok = true;
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const LonLat& p = raw[i];
        const std::string v = "vertex " + std::to_string(i + 1) + " of " + name;
        if (!std::isfinite(p.lon) || !std::isfinite(p.lat)) {
            out.push_back({Severity::Error, v + " is not a finite number"});
            ok = false;
        } else if (std::abs(p.lon) > 180.0 || std::abs(p.lat) > 90.0) {
            out.push_back({Severity::Error, v + " (" + fmt("%.6f, %.6f", p.lon, p.lat) +
                                                ") is out of range: longitude must lie within ±180 and latitude "
                                                "within ±90 degrees (is the order lon, lat?)"});
            ok = false;
        } else if (std::abs(p.lat) > kMaxLat) {
            out.push_back({Severity::Error, v + " (" + fmt("%.6f, %.6f", p.lon, p.lat) +
                                                ") is too close to a pole: latitudes beyond ±85 degrees are not "
                                                "supported"});
            ok = false;
        }
    }
    if (!ok)
        return false;
    const NumberedRing r = numbered(raw);
    const int distinct = distinctCount(r.pts);
    if (distinct < 3) {
        out.push_back({Severity::Error, name + " has " + (distinct == 0 ? std::string("no") : std::to_string(distinct)) +
                                            " distinct " + (distinct == 1 ? "vertex" : "vertices") +
                                            "; a polygon needs at least 3"});
        return false;
    }
    if (!frame)
        return true;
    *local = frame->toLocal(r.pts);
    // Zero area and crossings are judged in plain lon/lat (longitude scaled by cos(lat)), where the user
    // drew straight edges; a line of lon/lat points is slightly curved in the planning frame.
    const double k = std::cos(frame->origin().lat * M_PI / 180.0);
    Ring flat;
    for (const auto& p : r.pts)
        flat.emplace_back(p.lon * k, p.lat);
    OGRMultiPoint mp;
    for (const auto& p : flat)
        mp.addGeometry(new OGRPoint(p.x(), p.y()));
    detail::OgrGeomPtr hull(mp.ConvexHull());
    const Box b = bounds(flat);
    const double diag2 = (b.max - b.min).squaredNorm();
    const double hullArea = hull && wkbFlatten(hull->getGeometryType()) == wkbPolygon ? hull->toPolygon()->get_Area() : 0.0;
    if (hullArea <= 1e-9 * diag2) {
        out.push_back({Severity::Error, name + " has zero area: all its vertices lie on one line"});
        return false;
    }
    if (!ringIsSimple(*local)) {
        int e1 = 0, e2 = 0;
        Vec2 at;
        if (findCrossing(flat, &e1, &e2, &at)) {
            const LonLat g{at.x() / k, at.y()};
            out.push_back({Severity::Error, name + " intersects itself: edges " + edgeName(r, e1) + " and " +
                                                edgeName(r, e2) + " cross near " + latLonText(g)});
        } else {
            out.push_back({Severity::Error, name + " intersects itself"});
        }
        return false;
    }
    if (std::abs(signedArea(flat)) <= 1e-9 * diag2) {
        out.push_back({Severity::Error, name + " has zero area"});
        return false;
    }
    return true;
}

std::unique_ptr<OGRPolygon> ringPolygon(const Ring& ring) { return detail::toOgr(Polygon{ring, {}}); }

} // namespace

GeoRing cleanRing(const GeoRing& ring) { return numbered(ring).pts; }

GeoPolygon cleanPolygon(const GeoPolygon& poly) {
    GeoPolygon out;
    out.outer = cleanRing(poly.outer);
    for (const auto& h : poly.holes)
        out.holes.push_back(cleanRing(h));
    return out;
}

bool hasError(const std::vector<Problem>& problems) {
    return std::any_of(problems.begin(), problems.end(),
                       [](const Problem& p) { return p.severity == Severity::Error; });
}

std::vector<Problem> validatePolygon(const GeoPolygon& poly, const std::string& what) {
    std::vector<Problem> out;
    if (poly.outer.empty()) {
        out.push_back({Severity::Error, what + " has no vertices"});
        return out;
    }
    // Ranges first: the planning frame needs sane coordinates.
    Ring dummy;
    bool rangesOk = checkRing(poly.outer, -1, what, nullptr, out, &dummy);
    for (std::size_t h = 0; h < poly.holes.size(); ++h)
        rangesOk = checkRing(poly.holes[h], static_cast<int>(h), what, nullptr, out, &dummy) && rangesOk;
    if (!rangesOk)
        return out;
    auto frame = LocalFrame::forArea(cleanPolygon(poly));
    if (!frame.ok()) {
        out.push_back({Severity::Error, what + ": " + frame.error().message});
        return out;
    }
    Ring outer;
    if (!checkRing(poly.outer, -1, what, &*frame, out, &outer))
        return out;
    std::vector<Ring> holes(poly.holes.size());
    std::vector<bool> holeOk(poly.holes.size(), false);
    for (std::size_t h = 0; h < poly.holes.size(); ++h)
        holeOk[h] = checkRing(poly.holes[h], static_cast<int>(h), what, &*frame, out, &holes[h]);
    if (hasError(out))
        return out;

    const auto outerPoly = ringPolygon(outer);
    std::vector<std::unique_ptr<OGRPolygon>> holePolys;
    for (std::size_t h = 0; h < holes.size(); ++h) {
        holePolys.push_back(ringPolygon(holes[h]));
        const std::string hn = "hole " + std::to_string(h + 1) + " of " + what;
        if (!holePolys[h]->Intersects(outerPoly.get()))
            out.push_back({Severity::Error, hn + " lies outside its outer ring"});
        else if (!holePolys[h]->Within(outerPoly.get()))
            out.push_back({Severity::Error, hn + " crosses the outer ring"});
    }
    for (std::size_t a = 0; a < holePolys.size(); ++a)
        for (std::size_t b = a + 1; b < holePolys.size(); ++b)
            if (holePolys[a]->Overlaps(holePolys[b].get()) || holePolys[a]->Within(holePolys[b].get()) ||
                holePolys[b]->Within(holePolys[a].get()))
                out.push_back({Severity::Error, "holes " + std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                                                    " of " + what + " overlap"});
    if (hasError(out))
        return out;

    // Anything else (a hole touching the outer ring along an edge, ...): GEOS's own explanation.
    std::string reason;
    Polygon local{outer, holes};
    if (!isValid(local, &reason)) {
        double x = 0, y = 0;
        const auto at = reason.find(" at or near point ");
        if (at != std::string::npos && std::sscanf(reason.c_str() + at + 18, "%lf %lf", &x, &y) == 2) {
            const LonLat g = frame->toGeo(Vec2(x, y));
            reason = reason.substr(0, at) + " near " + fmt("%.6f, %.6f", g.lon, g.lat);
        }
        out.push_back({Severity::Error, what + " is not a valid polygon: " + reason});
    }
    return out;
}

} // namespace pf::geo
