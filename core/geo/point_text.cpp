// Numbers and local-frame points as messages show them (see point_text.h).
#include "core/geo/point_text.h"

#include <cstdio>

namespace pf::geo {

std::string fixedText(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string pointText(const Vec2& p) { return "(" + fixedText(p.x()) + ", " + fixedText(p.y()) + ") m"; }

} // namespace pf::geo
