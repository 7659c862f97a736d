// LocalFrame: the mission's planning frame, a transverse Mercator (k = 1) centred on the area.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"

#include <memory>

namespace pf::geo {

// WGS84 lon/lat <-> local metres (x east, y north) through PROJ, via OGR.
// A transverse Mercator with scale 1 on its central meridian keeps scale error below
// 1e-6 within ~10 km of the origin, which is far below a camera footprint.
// Copying is cheap enough (it rebuilds the transformation); one copy per thread.
class LocalFrame {
public:
    // Frame whose origin (false easting/northing 0) is at `origin`.
    static Result<LocalFrame> create(LonLat origin);
    // Frame centred on the bounding box of the polygon's outer ring.
    static Result<LocalFrame> forArea(const GeoPolygon& area);

    LocalFrame(const LocalFrame& other);
    LocalFrame& operator=(const LocalFrame& other);
    LocalFrame(LocalFrame&&) noexcept;
    LocalFrame& operator=(LocalFrame&&) noexcept;
    ~LocalFrame();

    LonLat origin() const { return m_origin; }

    Vec2 toLocal(LonLat p) const;
    LonLat toGeo(const Vec2& p) const;
    Ring toLocal(const GeoRing& ring) const;
    GeoRing toGeo(const Ring& ring) const;
    Polygon toLocal(const GeoPolygon& poly) const;
    GeoPolygon toGeo(const Polygon& poly) const;

    // The frame's definition as a PROJ string (for diagnostics and exports).
    std::string projString() const;

    struct Impl; // opaque: keeps OGR out of this header

private:
    explicit LocalFrame(LonLat origin, std::unique_ptr<Impl> impl);
    LonLat m_origin;
    std::unique_ptr<Impl> m_impl;
};

// The ground area of a WGS84 polygon in m² (holes subtracted), measured in its own local frame
// (forArea); 0 for fewer than three vertices. What the GUI shows as an area's or a zone's size.
double groundAreaM2(const GeoPolygon& poly);

} // namespace pf::geo
