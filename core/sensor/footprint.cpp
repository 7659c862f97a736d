#include "core/sensor/footprint.h"

#include "core/geo/geodesic.h"

#include <cmath>

namespace pf::sensor {

geo::Ring footprintRing(const PhotoFootprint& f) {
    const double h = f.headingDeg * M_PI / 180.0;
    const geo::Vec2 along(std::sin(h), std::cos(h));  // direction of flight
    const geo::Vec2 right(std::cos(h), -std::sin(h)); // across the track, to the right
    const geo::Vec2 a = 0.5 * f.alongM * along, c = 0.5 * f.acrossM * right;
    return {f.pos - a - c, f.pos - a + c, f.pos + a + c, f.pos + a - c};
}

geo::GeoRing footprintCorners(geo::LonLat centre, double headingDeg, const Footprint& fp) {
    const double along = fp.shortSideM / 2.0, across = fp.longSideM / 2.0;
    const double dist = std::hypot(along, across);
    const double a = std::atan2(across, along) * 180.0 / M_PI;
    geo::GeoRing ring;
    for (double az : {headingDeg + a, headingDeg + 180.0 - a, headingDeg + 180.0 + a, headingDeg - a})
        ring.push_back(geo::geodesicDirect(centre, az, dist));
    return ring;
}

} // namespace pf::sensor
