// The one place converting between core geo types and Qt Positioning / scene types.
#pragma once

#include "core/geo/types.h"

#include <QGeoCoordinate>
#include <QGeoPolygon>
#include <QPointF>
#include <QPolygonF>
#include <QString>

namespace pf::ui {

QGeoCoordinate toQGeo(const geo::LonLat& p);
geo::LonLat fromQGeo(const QGeoCoordinate& c);
// The outer ring and holes of a core polygon as a QGeoPolygon (open rings, as in the core).
QGeoPolygon toQGeo(const geo::GeoPolygon& poly);
geo::GeoPolygon fromQGeo(const QGeoPolygon& poly);

// Web Mercator (EPSG:3857) metres with y pointing down, as used by the map scene: north is up on
// screen and XYZ tile rows grow downwards like scene y.
QPointF toScene(const geo::LonLat& p);
geo::LonLat fromScene(const QPointF& p);
QPolygonF toScene(const geo::GeoRing& ring);
geo::GeoRing ringFromScene(const QPolygonF& poly);

// "49.012345° N, 8.330000° E": a position as the status bar shows it (six decimals, about 0.1 m).
QString formatLonLat(const geo::LonLat& p);

} // namespace pf::ui
