// Live validation of a drawn polygon, with the reason in words for the status bar.
#pragma once

#include "core/geo/types.h"

#include <QString>

namespace pf::ui {

// Empty when the polygon can be used; otherwise why not ("edges cross near 49.01201 N, 8.32911 E").
// Kept in ui/ as a thin wrapper over the core's geometry checks so the map can call it on every
// mouse move during a drag.
QString shapeProblem(const geo::GeoPolygon& poly);

} // namespace pf::ui
