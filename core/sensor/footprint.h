// A photo's footprint on the ground as a shape: the rectangle each photo covers, turned to the
// direction of flight, in local metres or in WGS84. Its size comes from camera.h (footprintAt).
#pragma once

#include "core/geo/types.h"
#include "core/sensor/camera.h"

namespace pf::sensor {

// One photo's ground footprint: a rectangle centred on the waypoint, its long side across the track
// (paper 001: the sensor's long side is orthogonal to the direction of flight).
struct PhotoFootprint {
    geo::Vec2 pos{0, 0};
    double headingDeg = 0.0; // direction of flight, clockwise from north
    double acrossM = 0.0;    // side across the track
    double alongM = 0.0;     // side along the track
};

// The footprint's corners in local metres (x east, y north), counter-clockwise from the corner
// behind and to the left of the centre: behind-left, behind-right, ahead-right, ahead-left.
geo::Ring footprintRing(const PhotoFootprint& f);

// Where a photo taken from `position` (local metres) in the direction of flight `headingDeg` is
// centred on the ground: the footprint's aheadM ahead (a tilted camera), else right below.
geo::Vec2 photoCentre(geo::Vec2 position, double headingDeg, const Footprint& footprint);
// The footprint of a photo taken from `position`: centred at photoCentre, its sides (and its distance
// ahead) scaled by `scale` (a photo taken at another altitude than the footprint's).
PhotoFootprint photoTakenFrom(geo::Vec2 position, double headingDeg, const Footprint& footprint,
                              double scale = 1.0);

// The four ground corners of a photo taken from `position` with the sensor's long side across the
// direction of flight `headingDeg`, each a geodesic step from the photo's centre (footprint.aheadM
// ahead of the position; no local frame needed): ahead-right, behind-right, behind-left,
// ahead-left.
geo::GeoRing footprintCorners(geo::LonLat position, double headingDeg, const Footprint& footprint);

} // namespace pf::sensor
