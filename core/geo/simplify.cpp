#include "core/geo/simplify.h"

#include "core/geo/ogr_adapter.h"

#include <cpl_error.h>

namespace pf::geo {

Polygon simplified(const Polygon& poly, double toleranceM) {
    auto g = detail::toOgr(poly);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    detail::OgrGeomPtr s(g->SimplifyPreserveTopology(toleranceM));
    const bool valid = s && s->IsValid();
    CPLPopErrorHandler();
    if (!valid)
        return poly;
    MultiPolygon parts = detail::fromOgr(s.get());
    return parts.size() == 1 ? std::move(parts.front()) : poly;
}

std::size_t vertexCount(const Polygon& poly) {
    std::size_t n = poly.outer.size();
    for (const auto& h : poly.holes)
        n += h.size();
    return n;
}

} // namespace pf::geo
