// Numbers and local-frame points as messages show them: "12.5", "(3.0, -4.2) m".
#pragma once

#include "core/geo/types.h"

#include <string>

namespace pf::geo {

// `v` with `decimals` digits after the point.
std::string fixedText(double v, int decimals = 1);
// A local-frame point in metres, one decimal: "(3.0, -4.2) m".
std::string pointText(const Vec2& p);

} // namespace pf::geo
