#include "ui/shape_validation.h"

#include "core/geo/validation.h"

namespace pf::ui {

QString shapeProblem(const geo::GeoPolygon& poly, const QString& what) {
    for (const auto& p : geo::validatePolygon(poly, what.toStdString()))
        if (p.severity == geo::Severity::Error) return QString::fromStdString(p.message);
    return {};
}

} // namespace pf::ui
