#include "core/mosaic/utm_projection.h"

#include "core/geo/geodesic.h"

#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pf::mosaic {

struct UtmProjection::Impl {
    OGRSpatialReference utm;
    std::unique_ptr<OGRCoordinateTransformation> toGrid;
    std::unique_ptr<OGRCoordinateTransformation> toGeo;
};

UtmProjection::UtmProjection(int zone, bool north, std::unique_ptr<Impl> impl)
    : m_zone(zone), m_north(north), m_impl(std::move(impl)) {}
UtmProjection::UtmProjection(UtmProjection&&) noexcept = default;
UtmProjection& UtmProjection::operator=(UtmProjection&&) noexcept = default;
UtmProjection::~UtmProjection() = default;

Result<UtmProjection> UtmProjection::forSite(geo::LonLat site) {
    if (!std::isfinite(site.lon) || !std::isfinite(site.lat) || std::abs(site.lat) > 84.0 ||
        std::abs(site.lon) > 180.0) {
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "no UTM zone for lon %.6f, lat %.6f (UTM covers latitudes 80 S to 84 N)",
                      site.lon, site.lat);
        return makeError(ErrorCode::InvalidInput, buf);
    }
    const int zone = std::clamp(static_cast<int>(std::floor((site.lon + 180.0) / 6.0)) + 1, 1, 60);
    const bool north = site.lat >= 0.0;
    auto impl = std::make_unique<Impl>();
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (impl->utm.importFromEPSG((north ? 32600 : 32700) + zone) != OGRERR_NONE)
        return makeError(ErrorCode::Internal, "PROJ does not know the UTM zone " +
                                                  std::to_string(zone) +
                                                  " (is proj-data installed?)");
    impl->utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    impl->toGrid.reset(OGRCreateCoordinateTransformation(&wgs84, &impl->utm));
    impl->toGeo.reset(OGRCreateCoordinateTransformation(&impl->utm, &wgs84));
    if (!impl->toGrid || !impl->toGeo)
        return makeError(ErrorCode::Internal, "PROJ could not build the UTM transformation");
    return UtmProjection(zone, north, std::move(impl));
}

std::string UtmProjection::name() const {
    return "UTM zone " + std::to_string(m_zone) + (m_north ? "N" : "S") +
           " (EPSG:" + std::to_string(epsg()) + ")";
}

std::string UtmProjection::wkt() const {
    char* text = nullptr;
    m_impl->utm.exportToWkt(&text);
    std::string out = text ? text : "";
    CPLFree(text);
    return out;
}

geo::Vec2 UtmProjection::toGrid(geo::LonLat p) const {
    double x = p.lon, y = p.lat;
    if (!m_impl->toGrid->Transform(1, &x, &y))
        return {std::nan(""), std::nan("")};
    return {x, y};
}

geo::LonLat UtmProjection::toGeo(const geo::Vec2& p) const {
    double x = p.x(), y = p.y();
    if (!m_impl->toGeo->Transform(1, &x, &y))
        return {std::nan(""), std::nan("")};
    return {x, y};
}

double UtmProjection::gridFromTrueDeg(geo::LonLat p) const {
    // A short step due north, seen in the grid.
    const geo::LonLat q = geo::geodesicDirect(p, 0.0, 10.0);
    const geo::Vec2 a = toGrid(p), b = toGrid(q);
    return std::atan2(b.x() - a.x(), b.y() - a.y()) * 180.0 / 3.14159265358979323846;
}

double UtmProjection::scaleFactor(geo::LonLat p) const {
    const geo::LonLat q = geo::geodesicDirect(p, 45.0, 10.0);
    return (toGrid(q) - toGrid(p)).norm() / 10.0;
}

geo::GeoRing ringToGeo(const geo::Ring& r, const UtmProjection& utm) {
    geo::GeoRing out;
    out.reserve(r.size());
    for (const auto& p : r)
        out.push_back(utm.toGeo(p));
    return out;
}

geo::GeoPolygon polygonToGeo(const geo::Polygon& p, const UtmProjection& utm) {
    geo::GeoPolygon out;
    out.outer = ringToGeo(p.outer, utm);
    for (const auto& h : p.holes)
        out.holes.push_back(ringToGeo(h, utm));
    return out;
}

} // namespace pf::mosaic
