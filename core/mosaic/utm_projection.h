// UtmProjection: the output grid's coordinate system, the UTM zone of the site (WGS84), through
// PROJ.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"

#include <memory>
#include <string>

namespace pf::mosaic {

// Not thread-safe (one PROJ transformation per object): the mosaic uses it while setting up and
// when writing vectors, never from its worker threads.
class UtmProjection {
public:
    // The zone containing `site` (north or south by its latitude; Norway and Svalbard exceptions
    // are not applied: a site there gets its standard 6-degree zone).
    static Result<UtmProjection> forSite(geo::LonLat site);
    UtmProjection(UtmProjection&&) noexcept;
    UtmProjection& operator=(UtmProjection&&) noexcept;
    ~UtmProjection();

    int zone() const { return m_zone; }
    bool north() const { return m_north; }
    int epsg() const { return (m_north ? 32600 : 32700) + m_zone; }
    // "UTM zone 32N (EPSG:32632)".
    std::string name() const;
    std::string wkt() const;

    geo::Vec2 toGrid(geo::LonLat p) const;
    geo::LonLat toGeo(const geo::Vec2& p) const;
    // How a direction clockwise from true north at `p` reads clockwise from grid north: add this
    // (the meridian convergence, degrees).
    double gridFromTrueDeg(geo::LonLat p) const;
    // Grid metres per ground metre at `p` (the UTM point scale, 0.9996 on the central meridian).
    double scaleFactor(geo::LonLat p) const;

    struct Impl;

private:
    UtmProjection(int zone, bool north, std::unique_ptr<Impl> impl);
    int m_zone = 0;
    bool m_north = true;
    std::unique_ptr<Impl> m_impl;
};

// A ring or polygon of the grid in WGS84.
geo::GeoRing ringToGeo(const geo::Ring& r, const UtmProjection& utm);
geo::GeoPolygon polygonToGeo(const geo::Polygon& p, const UtmProjection& utm);

} // namespace pf::mosaic
