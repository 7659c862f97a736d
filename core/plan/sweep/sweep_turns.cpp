#include "core/plan/sweep/sweep_turns.h"

#include <algorithm>
#include <cmath>

namespace pf::plan::sweep_detail {

using geo::Vec2;

std::optional<Lane> photographedTurn(const CellLane& l, bool ltr, const CellLane& nl, bool nltr, const Vec2& u,
                                     double reach, double ph) {
    const bool right = ltr; // the turn is at the lanes' right ends
    const double o = right ? 1.0 : -1.0;
    const Vec2 P = ltr ? l.span.last : l.span.first, Q = nltr ? nl.span.first : nl.span.last;
    const double eP = o * P.dot(u), eQ = o * Q.dot(u);
    const bool pNear = eP < eQ;
    const CellLane& nearLane = pNear ? l : nl;
    const bool otherBelow = pNear ? nl.y < l.y : l.y < nl.y;
    const double wedge = right ? (otherBelow ? nearLane.wedgeRightBelow : nearLane.wedgeRightAbove)
                               : (otherBelow ? nearLane.wedgeLeftBelow : nearLane.wedgeLeftAbove);
    const double eNear = std::min(eP, eQ), eFar = std::max(eP, eQ);
    const double lo = eNear + reach, hi = std::min(eNear + wedge, eFar - reach);
    if (hi > lo + 1e-6 && eFar > eNear) {
        const double L = (Q - P).norm();
        const double t0 = (lo - eP) / (eQ - eP), t1 = (hi - eP) / (eQ - eP);
        const double ta = std::min(t0, t1), tb = std::max(t0, t1);
        const int n = std::max(1, static_cast<int>(std::ceil((tb - ta) * L / ph - 1e-9)));
        Lane side;
        const Vec2 d = (Q - P) / L;
        for (int k = 0; k < n; ++k) {
            const double t = std::clamp(0.5 * (ta + tb) + (k - 0.5 * (n - 1)) * ph / L, 0.0, 1.0);
            side.photos.push_back(P + t * L * d);
        }
        side.stripStart = P + ta * L * d;
        side.stripEnd = P + tb * L * d;
        double h = std::atan2(d.x(), d.y()) * 180.0 / M_PI;
        side.headingDeg = h < 0 ? h + 360.0 : h;
        return side;
    }
    return std::nullopt;
}

} // namespace pf::plan::sweep_detail
