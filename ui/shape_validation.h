// Live validation of a drawn polygon, with the reason in words for the status bar.
#pragma once

#include "core/geo/types.h"
#include "core/mission/mission.h"

#include <QString>

namespace pf::ui {

// Empty when the polygon can be used; otherwise the first error found by the core's validation,
// a sentence naming the shape by `what` (e.g. "the area intersects itself: edges 2-3 and 5-6 cross
// near 8.330120, 49.012310"). Cheap enough to call on every mouse move during a drag.
QString shapeProblem(const geo::GeoPolygon& poly, const QString& what = QStringLiteral("the shape"));

// The same for a corridor: its line and width (mission::validateCorridor).
QString corridorProblem(const mission::Corridor& corridor);

} // namespace pf::ui
