// Conversions between geo value types and OGR geometries. Internal: include from .cpp files only.
#pragma once

#include "core/geo/types.h"

#include <ogr_geometry.h>

#include <memory>

namespace pf::geo::detail {

struct OgrDeleter {
    void operator()(OGRGeometry* g) const { OGRGeometryFactory::destroyGeometry(g); }
};
using OgrGeomPtr = std::unique_ptr<OGRGeometry, OgrDeleter>;

std::unique_ptr<OGRPolygon> toOgr(const Polygon& poly);
std::unique_ptr<OGRMultiPolygon> toOgr(const MultiPolygon& polys);
// Polygons of any geometry (polygon, multipolygon, collection); other parts are dropped.
MultiPolygon fromOgr(const OGRGeometry* geom);

} // namespace pf::geo::detail
