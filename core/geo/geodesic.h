// Geodesic distance, bearing and direct problem on the WGS84 ellipsoid (PROJ's geodesic routines).
#pragma once

#include "core/geo/types.h"

namespace pf::geo {

struct GeodesicInverse {
    double distanceM = 0.0;   // along the geodesic
    double azimuth1Deg = 0.0; // initial bearing at a, clockwise from north, (-180, 180]
    double azimuth2Deg = 0.0; // forward azimuth at b
};

GeodesicInverse geodesicInverse(LonLat a, LonLat b);
double geodesicDistance(LonLat a, LonLat b);
// Initial bearing from a to b in [0, 360).
double initialBearingDeg(LonLat a, LonLat b);
// The point reached from `a` after `distanceM` metres along azimuth `azimuthDeg`.
LonLat geodesicDirect(LonLat a, double azimuthDeg, double distanceM);

} // namespace pf::geo
