#include "ui/shape_validation.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <cmath>
#include <set>
#include <utility>

namespace pf::ui {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("ShapeValidation", text); }

QString formatLonLat(const geo::LonLat& p) {
    return QStringLiteral("%1° %2, %3° %4")
        .arg(std::abs(p.lat), 0, 'f', 5)
        .arg(p.lat >= 0 ? QLatin1Char('N') : QLatin1Char('S'))
        .arg(std::abs(p.lon), 0, 'f', 5)
        .arg(p.lon >= 0 ? QLatin1Char('E') : QLatin1Char('W'));
}

int distinctVertices(const geo::GeoRing& ring) {
    std::set<std::pair<double, double>> seen;
    for (const auto& p : ring) seen.insert({p.lon, p.lat});
    return int(seen.size());
}

} // namespace

QString shapeProblem(const geo::GeoPolygon& poly) {
    const int n = distinctVertices(poly.outer);
    if (n < 3) return tr("needs at least 3 distinct vertices (has %1)").arg(n);
    for (const auto& p : poly.outer)
        if (!(std::abs(p.lat) <= 90.0 && std::abs(p.lon) <= 180.0))
            return tr("a vertex lies outside the valid latitude/longitude range");
    auto frame = geo::LocalFrame::forArea(poly);
    if (!frame) return QString::fromStdString(frame.error().message);
    const geo::Polygon local = frame->toLocal(poly);
    if (std::abs(geo::signedArea(local.outer)) < 1e-6) return tr("has no area (all vertices on one line)");
    std::string reason;
    if (geo::isValid(local, &reason)) return {};
    // GEOS reports a location in the local frame, e.g. "Self-intersection[12.3 -4.5]": give it in lon/lat.
    const QString r = QString::fromStdString(reason);
    const QRegularExpression loc(QStringLiteral("\\[\\s*(-?[0-9.eE+-]+)\\s+(-?[0-9.eE+-]+)"));
    const auto m = loc.match(r);
    QString where;
    if (m.hasMatch()) {
        const geo::LonLat at = frame->toGeo(geo::Vec2(m.captured(1).toDouble(), m.captured(2).toDouble()));
        where = tr(" near %1").arg(formatLonLat(at));
    }
    if (r.contains(QStringLiteral("Self-intersection"), Qt::CaseInsensitive) ||
        r.contains(QStringLiteral("Ring Self-intersection"), Qt::CaseInsensitive))
        return tr("edges cross each other%1").arg(where);
    if (r.contains(QStringLiteral("Hole lies outside"), Qt::CaseInsensitive))
        return tr("a hole lies outside the polygon%1").arg(where);
    if (r.contains(QStringLiteral("Too few points"), Qt::CaseInsensitive))
        return tr("needs at least 3 distinct vertices");
    return tr("invalid polygon: %1").arg(r);
}

} // namespace pf::ui
