#include "core/geo/geodesic.h"

#include <geodesic.h>

#include <cmath>

namespace pf::geo {

namespace {

const geod_geodesic& wgs84() {
    // Initialised once and only read afterwards: safe to share between threads.
    static const geod_geodesic g = [] {
        geod_geodesic init{};
        geod_init(&init, 6378137.0, 1.0 / 298.257223563);
        return init;
    }();
    return g;
}

} // namespace

GeodesicInverse geodesicInverse(LonLat a, LonLat b) {
    GeodesicInverse r;
    geod_inverse(&wgs84(), a.lat, a.lon, b.lat, b.lon, &r.distanceM, &r.azimuth1Deg, &r.azimuth2Deg);
    return r;
}

double geodesicDistance(LonLat a, LonLat b) { return geodesicInverse(a, b).distanceM; }

double initialBearingDeg(LonLat a, LonLat b) {
    double az = geodesicInverse(a, b).azimuth1Deg;
    az = std::fmod(az + 360.0, 360.0);
    return az;
}

LonLat geodesicDirect(LonLat a, double azimuthDeg, double distanceM) {
    double lat2 = 0, lon2 = 0, azi2 = 0;
    geod_direct(&wgs84(), a.lat, a.lon, azimuthDeg, distanceM, &lat2, &lon2, &azi2);
    return {lon2, lat2};
}

} // namespace pf::geo
