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

geo::Vec2 photoCentre(geo::Vec2 position, double headingDeg, const Footprint& fp) {
    const double h = headingDeg * M_PI / 180.0;
    return position + fp.aheadM * geo::Vec2(std::sin(h), std::cos(h));
}

PhotoFootprint photoTakenFrom(geo::Vec2 position, double headingDeg, const Footprint& fp, double scale) {
    const Footprint scaled{fp.longSideM * scale, fp.shortSideM * scale, fp.aheadM * scale};
    return {photoCentre(position, headingDeg, scaled), headingDeg, scaled.longSideM, scaled.shortSideM};
}

geo::GeoRing footprintCorners(geo::LonLat position, double headingDeg, const Footprint& fp) {
    const geo::LonLat centre =
        fp.aheadM == 0.0 ? position : geo::geodesicDirect(position, headingDeg, fp.aheadM);
    const double along = fp.shortSideM / 2.0, across = fp.longSideM / 2.0;
    const double dist = std::hypot(along, across);
    const double a = std::atan2(across, along) * 180.0 / M_PI;
    geo::GeoRing ring;
    for (double az : {headingDeg + a, headingDeg + 180.0 - a, headingDeg + 180.0 + a, headingDeg - a})
        ring.push_back(geo::geodesicDirect(centre, az, dist));
    return ring;
}

} // namespace pf::sensor
