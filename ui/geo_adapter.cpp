#include "ui/geo_adapter.h"

#include "ui/map/web_mercator.h"

#include <cmath>

namespace pf::ui {

QGeoCoordinate toQGeo(const geo::LonLat& p) { return QGeoCoordinate(p.lat, p.lon); }

geo::LonLat fromQGeo(const QGeoCoordinate& c) { return geo::LonLat{c.longitude(), c.latitude()}; }

QGeoPolygon toQGeo(const geo::GeoPolygon& poly) {
    QList<QGeoCoordinate> outer;
    for (const auto& p : poly.outer) outer << toQGeo(p);
    QGeoPolygon out(outer);
    for (const auto& hole : poly.holes) {
        QList<QGeoCoordinate> h;
        for (const auto& p : hole) h << toQGeo(p);
        out.addHole(h);
    }
    return out;
}

geo::GeoPolygon fromQGeo(const QGeoPolygon& poly) {
    geo::GeoPolygon out;
    for (const auto& c : poly.path()) out.outer.push_back(fromQGeo(c));
    for (int i = 0; i < poly.holesCount(); ++i) {
        geo::GeoRing h;
        for (const auto& c : poly.holePath(i)) h.push_back(fromQGeo(c));
        out.holes.push_back(std::move(h));
    }
    return out;
}

QPointF toScene(const geo::LonLat& p) { return mercator::toScene(p.lon, p.lat); }

geo::LonLat fromScene(const QPointF& p) {
    const QPointF ll = mercator::toLonLat(p);
    return geo::LonLat{ll.x(), ll.y()};
}

QPolygonF toScene(const geo::GeoRing& ring) {
    QPolygonF out;
    out.reserve(int(ring.size()));
    for (const auto& p : ring) out << toScene(p);
    return out;
}

geo::GeoRing ringFromScene(const QPolygonF& poly) {
    geo::GeoRing out;
    out.reserve(std::size_t(poly.size()));
    for (const auto& p : poly) out.push_back(fromScene(p));
    return out;
}

QString formatLonLat(const geo::LonLat& p) {
    return QStringLiteral("%1° %2, %3° %4")
        .arg(std::abs(p.lat), 0, 'f', 6)
        .arg(p.lat >= 0 ? QLatin1Char('N') : QLatin1Char('S'))
        .arg(std::abs(p.lon), 0, 'f', 6)
        .arg(p.lon >= 0 ? QLatin1Char('E') : QLatin1Char('W'));
}

} // namespace pf::ui
