#include "core/geo/polygon_ops.h"

#include "core/geo/ogr_adapter.h"

#include <cpl_error.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pf::geo {

namespace detail {

namespace {

OGRLinearRing* ringToOgr(const Ring& ring) {
    auto* r = new OGRLinearRing();
    r->setNumPoints(static_cast<int>(ring.size()) + (ring.empty() ? 0 : 1), FALSE);
    for (std::size_t i = 0; i < ring.size(); ++i)
        r->setPoint(static_cast<int>(i), ring[i].x(), ring[i].y());
    if (!ring.empty())
        r->setPoint(static_cast<int>(ring.size()), ring[0].x(), ring[0].y());
    return r;
}

Ring ringFromOgr(const OGRLinearRing* r) {
    Ring out;
    const int n = r->getNumPoints();
    out.reserve(static_cast<std::size_t>(std::max(0, n)));
    for (int i = 0; i < n; ++i)
        out.emplace_back(r->getX(i), r->getY(i));
    if (out.size() > 1 && out.front() == out.back())
        out.pop_back();
    return out;
}

void collect(const OGRGeometry* g, MultiPolygon& out) {
    if (!g || g->IsEmpty())
        return;
    switch (wkbFlatten(g->getGeometryType())) {
    case wkbPolygon: {
        const auto* p = g->toPolygon();
        Polygon poly;
        poly.outer = ringFromOgr(p->getExteriorRing());
        for (int i = 0; i < p->getNumInteriorRings(); ++i)
            poly.holes.push_back(ringFromOgr(p->getInteriorRing(i)));
        out.push_back(std::move(poly));
        break;
    }
    case wkbMultiPolygon:
    case wkbGeometryCollection: {
        const auto* c = g->toGeometryCollection();
        for (int i = 0; i < c->getNumGeometries(); ++i)
            collect(c->getGeometryRef(i), out);
        break;
    }
    default:
        break; // points and lines carry no area
    }
}

} // namespace

std::unique_ptr<OGRPolygon> toOgr(const Polygon& poly) {
    auto p = std::make_unique<OGRPolygon>();
    p->addRingDirectly(ringToOgr(poly.outer));
    for (const auto& h : poly.holes)
        p->addRingDirectly(ringToOgr(h));
    return p;
}

std::unique_ptr<OGRMultiPolygon> toOgr(const MultiPolygon& polys) {
    auto m = std::make_unique<OGRMultiPolygon>();
    for (const auto& p : polys)
        m->addGeometryDirectly(toOgr(p).release());
    return m;
}

MultiPolygon fromOgr(const OGRGeometry* geom) {
    MultiPolygon out;
    collect(geom, out);
    return out;
}

} // namespace detail

using detail::fromOgr;
using detail::OgrGeomPtr;
using detail::toOgr;

double signedArea(const Ring& ring) {
    double a = 0.0;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& p = ring[i];
        const Vec2& q = ring[(i + 1) % n];
        a += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * a;
}

double area(const Polygon& poly) { return toOgr(poly)->get_Area(); }

double area(const MultiPolygon& polys) {
    double a = 0;
    for (const auto& p : polys)
        a += area(p);
    return a;
}

namespace {

bool pointInRing(const Ring& ring, const Vec2& p) {
    bool inside = false;
    const std::size_t n = ring.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Vec2& a = ring[i];
        const Vec2& b = ring[j];
        if ((a.y() > p.y()) != (b.y() > p.y())) {
            const double x = (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x();
            if (p.x() < x)
                inside = !inside;
        }
    }
    return inside;
}

double segDist(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return (a + t * ab - p).norm();
}

double ringDist(const Ring& ring, const Vec2& p) {
    double d = std::numeric_limits<double>::infinity();
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i)
        d = std::min(d, segDist(p, ring[i], ring[(i + 1) % n]));
    return d;
}

} // namespace

// Containment and distances are hot in the grid builder; the even-odd test and a scan of the
// edges are exact for simple polygons and avoid building an OGR geometry per query.
bool contains(const Polygon& poly, const Vec2& p) {
    if (ringDist(poly.outer, p) == 0.0)
        return true;
    if (!pointInRing(poly.outer, p))
        return false;
    for (const auto& h : poly.holes)
        if (pointInRing(h, p) && ringDist(h, p) > 0.0)
            return false;
    return true;
}

bool contains(const MultiPolygon& polys, const Vec2& p) {
    return std::any_of(polys.begin(), polys.end(), [&](const Polygon& q) { return contains(q, p); });
}

double distanceToBoundary(const Polygon& poly, const Vec2& p) {
    double d = ringDist(poly.outer, p);
    for (const auto& h : poly.holes)
        d = std::min(d, ringDist(h, p));
    return d;
}

Vec2 nearestOnBoundary(const MultiPolygon& polys, const Vec2& p) {
    Vec2 best = p;
    double bestD = std::numeric_limits<double>::infinity();
    auto ring = [&](const Ring& r) {
        for (std::size_t i = 0; i < r.size(); ++i) {
            const Vec2& a = r[i];
            const Vec2 ab = r[(i + 1) % r.size()] - a;
            const double len2 = ab.squaredNorm();
            const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
            const Vec2 q = a + t * ab;
            const double d = (q - p).squaredNorm();
            if (d < bestD) {
                bestD = d;
                best = q;
            }
        }
    };
    for (const auto& poly : polys) {
        ring(poly.outer);
        for (const auto& h : poly.holes)
            ring(h);
    }
    return best;
}

double distanceTo(const Polygon& poly, const Vec2& p) {
    return contains(poly, p) ? 0.0 : distanceToBoundary(poly, p);
}

double distanceTo(const MultiPolygon& polys, const Vec2& p) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& q : polys)
        d = std::min(d, distanceTo(q, p));
    return d;
}

MultiPolygon buffer(const Polygon& poly, double d, int quadrantSegments) {
    auto g = toOgr(poly);
    OgrGeomPtr b(g->Buffer(d, quadrantSegments));
    return fromOgr(b.get());
}

MultiPolygon buffer(const MultiPolygon& polys, double d, int quadrantSegments) {
    if (polys.empty())
        return {};
    auto g = toOgr(polys);
    OgrGeomPtr b(g->Buffer(d, quadrantSegments));
    return fromOgr(b.get());
}

MultiPolygon unite(const MultiPolygon& polys) {
    if (polys.empty())
        return {};
    auto g = toOgr(polys);
    OgrGeomPtr u(g->UnionCascaded());
    if (!u) // invalid input: fall back to a buffer(0) clean-up, which GEOS accepts more often
        u.reset(g->Buffer(0.0));
    return fromOgr(u.get());
}

MultiPolygon difference(const Polygon& a, const MultiPolygon& b) {
    return difference(MultiPolygon{a}, b);
}

MultiPolygon difference(const MultiPolygon& a, const MultiPolygon& b) {
    if (b.empty())
        return a;
    auto ga = toOgr(a);
    auto gb = toOgr(unite(b));
    OgrGeomPtr d(ga->Difference(gb.get()));
    return fromOgr(d.get());
}

MultiPolygon intersection(const Polygon& a, const Polygon& b) {
    auto ga = toOgr(a);
    auto gb = toOgr(b);
    OgrGeomPtr r(ga->Intersection(gb.get()));
    return fromOgr(r.get());
}

MultiPolygon intersection(const MultiPolygon& a, const Polygon& b) {
    if (a.empty())
        return {};
    auto ga = toOgr(a);
    auto gb = toOgr(b);
    OgrGeomPtr r(ga->Intersection(gb.get()));
    return fromOgr(r.get());
}

bool segmentCrossesInterior(const Polygon& poly, const Vec2& a, const Vec2& b) {
    // Sample-free exact test: the segment enters the interior if its midpoint, or the midpoint of
    // any piece between consecutive boundary crossings, lies strictly inside.
    std::vector<double> ts{0.0, 1.0};
    const Vec2 d = b - a;
    auto addCrossings = [&](const Ring& ring) {
        const std::size_t n = ring.size();
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2& p = ring[i];
            const Vec2 e = ring[(i + 1) % n] - p;
            const double den = d.x() * e.y() - d.y() * e.x();
            if (std::abs(den) < 1e-15)
                continue;
            const Vec2 ap = p - a;
            const double t = (ap.x() * e.y() - ap.y() * e.x()) / den;
            const double u = (ap.x() * d.y() - ap.y() * d.x()) / den;
            if (t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0)
                ts.push_back(t);
        }
    };
    addCrossings(poly.outer);
    for (const auto& h : poly.holes)
        addCrossings(h);
    std::sort(ts.begin(), ts.end());
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
        if (ts[i + 1] - ts[i] < 1e-12)
            continue;
        const Vec2 m = a + 0.5 * (ts[i] + ts[i + 1]) * d;
        if (contains(poly, m) && distanceToBoundary(poly, m) > 1e-9)
            return true;
    }
    return false;
}

bool segmentCrossesInterior(const MultiPolygon& polys, const Vec2& a, const Vec2& b) {
    const Box sb{Vec2(std::min(a.x(), b.x()), std::min(a.y(), b.y())),
                 Vec2(std::max(a.x(), b.x()), std::max(a.y(), b.y()))};
    for (const auto& poly : polys)
        if (bounds(poly).intersects(sb) && segmentCrossesInterior(poly, a, b))
            return true;
    return false;
}

bool isValid(const Polygon& poly, std::string* reason) {
    auto g = toOgr(poly);
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const bool ok = g->IsValid();
    const std::string msg = CPLGetLastErrorMsg();
    CPLPopErrorHandler();
    if (!ok && reason)
        *reason = msg;
    return ok;
}

Box bounds(const Ring& ring) {
    Box b{Vec2(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()),
          Vec2(-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity())};
    for (const auto& p : ring) {
        b.min = b.min.cwiseMin(p);
        b.max = b.max.cwiseMax(p);
    }
    return b;
}

Box bounds(const Polygon& poly) { return bounds(poly.outer); }

Box bounds(const MultiPolygon& polys) {
    Box b = polys.empty() ? Box{} : bounds(polys.front());
    for (const auto& p : polys) {
        const Box q = bounds(p);
        b.min = b.min.cwiseMin(q.min);
        b.max = b.max.cwiseMax(q.max);
    }
    return b;
}

} // namespace pf::geo
