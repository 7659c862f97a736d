#include "ui/shape_validation.h"

#include "core/geo/validation.h"
#include "core/mission/corridor.h"

namespace pf::ui {

QString shapeProblem(const geo::GeoPolygon& poly, const QString& what) {
    for (const auto& p : geo::validatePolygon(poly, what.toStdString()))
        if (p.severity == geo::Severity::Error) return QString::fromStdString(p.message);
    return {};
}

QString corridorProblem(const mission::Corridor& corridor) {
    for (const auto& p : mission::validateCorridor(corridor))
        if (p.severity == geo::Severity::Error)
            return QString::fromStdString(p.message);
    return {};
}

} // namespace pf::ui
