#include "core/geo/local_frame.h"

#include "core/geo/polygon_ops.h"

#include <ogr_spatialref.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

namespace pf::geo {

struct LocalFrame::Impl {
    std::unique_ptr<OGRCoordinateTransformation> toLocal;
    std::unique_ptr<OGRCoordinateTransformation> toGeo;
};

namespace {

std::unique_ptr<LocalFrame::Impl> makeImpl(LonLat o, std::string* err) {
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    OGRSpatialReference tm;
    tm.SetWellKnownGeogCS("WGS84");
    tm.SetTM(o.lat, o.lon, 1.0, 0.0, 0.0);
    tm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    auto impl = std::make_unique<LocalFrame::Impl>();
    impl->toLocal.reset(OGRCreateCoordinateTransformation(&wgs84, &tm));
    impl->toGeo.reset(OGRCreateCoordinateTransformation(&tm, &wgs84));
    if (!impl->toLocal || !impl->toGeo) {
        *err = "PROJ could not build the local planning frame";
        return nullptr;
    }
    return impl;
}

} // namespace

LocalFrame::LocalFrame(LonLat origin, std::unique_ptr<Impl> impl)
    : m_origin(origin), m_impl(std::move(impl)) {}

Result<LocalFrame> LocalFrame::create(LonLat origin) {
    if (!std::isfinite(origin.lon) || !std::isfinite(origin.lat) || std::abs(origin.lat) > 85.0 ||
        std::abs(origin.lon) > 180.0) {
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "cannot centre a planning frame at lon %.6f, lat %.6f: coordinates out of range",
                      origin.lon, origin.lat);
        return makeError(ErrorCode::InvalidInput, buf);
    }
    std::string err;
    auto impl = makeImpl(origin, &err);
    if (!impl)
        return makeError(ErrorCode::Internal, err);
    return LocalFrame(origin, std::move(impl));
}

Result<LocalFrame> LocalFrame::forArea(const GeoPolygon& area) {
    if (area.outer.empty())
        return makeError(ErrorCode::InvalidGeometry, "the area has no vertices");
    double minLon = area.outer[0].lon, maxLon = minLon, minLat = area.outer[0].lat, maxLat = minLat;
    for (const auto& p : area.outer) {
        minLon = std::min(minLon, p.lon);
        maxLon = std::max(maxLon, p.lon);
        minLat = std::min(minLat, p.lat);
        maxLat = std::max(maxLat, p.lat);
    }
    return create({0.5 * (minLon + maxLon), 0.5 * (minLat + maxLat)});
}

// A copy clones the transformations (each copy has its own: a transformation is not to be used by
// two threads at once): the same PROJ operations, at a fortieth of the cost of building them anew.
LocalFrame::LocalFrame(const LocalFrame& other) : m_origin(other.m_origin) {
    if (other.m_impl) {
        auto impl = std::make_unique<Impl>();
        impl->toLocal.reset(other.m_impl->toLocal->Clone());
        impl->toGeo.reset(other.m_impl->toGeo->Clone());
        if (impl->toLocal && impl->toGeo)
            m_impl = std::move(impl);
    }
    if (!m_impl) {
        std::string err;
        m_impl = makeImpl(m_origin, &err);
    }
    assert(m_impl && "a frame that was built once builds again");
}

LocalFrame& LocalFrame::operator=(const LocalFrame& other) {
    if (this != &other) {
        LocalFrame copy(other);
        *this = std::move(copy);
    }
    return *this;
}

LocalFrame::LocalFrame(LocalFrame&&) noexcept = default;
LocalFrame& LocalFrame::operator=(LocalFrame&&) noexcept = default;
LocalFrame::~LocalFrame() = default;

Vec2 LocalFrame::toLocal(LonLat p) const {
    double x = p.lon, y = p.lat;
    m_impl->toLocal->Transform(1, &x, &y);
    return {x, y};
}

LonLat LocalFrame::toGeo(const Vec2& p) const {
    double x = p.x(), y = p.y();
    m_impl->toGeo->Transform(1, &x, &y);
    return {x, y};
}

Ring LocalFrame::toLocal(const GeoRing& ring) const {
    std::vector<double> xs(ring.size()), ys(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
        xs[i] = ring[i].lon;
        ys[i] = ring[i].lat;
    }
    if (!ring.empty())
        m_impl->toLocal->Transform(static_cast<int>(ring.size()), xs.data(), ys.data());
    Ring out(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i)
        out[i] = Vec2(xs[i], ys[i]);
    return out;
}

GeoRing LocalFrame::toGeo(const Ring& ring) const {
    std::vector<double> xs(ring.size()), ys(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
        xs[i] = ring[i].x();
        ys[i] = ring[i].y();
    }
    if (!ring.empty())
        m_impl->toGeo->Transform(static_cast<int>(ring.size()), xs.data(), ys.data());
    GeoRing out(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i)
        out[i] = LonLat{xs[i], ys[i]};
    return out;
}

Polygon LocalFrame::toLocal(const GeoPolygon& poly) const {
    Polygon out;
    out.outer = toLocal(poly.outer);
    for (const auto& h : poly.holes)
        out.holes.push_back(toLocal(h));
    return out;
}

GeoPolygon LocalFrame::toGeo(const Polygon& poly) const {
    GeoPolygon out;
    out.outer = toGeo(poly.outer);
    for (const auto& h : poly.holes)
        out.holes.push_back(toGeo(h));
    return out;
}

std::string LocalFrame::projString() const {
    char buf[200];
    std::snprintf(buf, sizeof buf, "+proj=tmerc +lat_0=%.9f +lon_0=%.9f +k=1 +x_0=0 +y_0=0 +datum=WGS84 +units=m",
                  m_origin.lat, m_origin.lon);
    return buf;
}

double groundAreaM2(const GeoPolygon& poly) {
    if (poly.outer.size() < 3)
        return 0.0;
    auto frame = LocalFrame::forArea(poly);
    return frame ? area(frame->toLocal(poly)) : 0.0;
}

} // namespace pf::geo
