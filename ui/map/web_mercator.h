// Web Mercator (EPSG:3857) and the XYZ tile pyramid, in the map scene's coordinates (metres, y down).
#pragma once

#include <QPointF>
#include <QRectF>

namespace pf::ui::mercator {

constexpr double kEarthRadius = 6378137.0;
constexpr double kHalfWorld = 20037508.342789244; // pi * R
constexpr double kMaxLatitude = 85.0511287798066;
constexpr int kTileSize = 256;
constexpr int kMaxZoom = 22;

// lon/lat (degrees) -> scene point (x east, y = -northing). Latitudes beyond +-85.05 are clamped.
QPointF toScene(double lonDeg, double latDeg);
// scene point -> QPointF(lon, lat) in degrees.
QPointF toLonLat(const QPointF& scene);

// Scene rectangle covered by tile (z, x, y) of the XYZ scheme (row 0 at the north).
QRectF tileRect(int z, int x, int y);
// Side of a tile at zoom z, in scene metres.
double tileSpan(int z);
// The zoom level whose tiles show at about one tile pixel per screen pixel for `metresPerPixel`.
int zoomForResolution(double metresPerPixel);
// Ground metres per scene metre at a latitude (Mercator stretches by 1/cos(lat)).
double groundScale(double latDeg);

} // namespace pf::ui::mercator
