#include "core/geo/prepared_region.h"

#include "core/geo/ogr_adapter.h"

#include <ogr_api.h>
#include <ogr_geometry.h>

namespace pf::geo {

struct PreparedRegion::Impl {
    std::unique_ptr<OGRMultiPolygon> geom;
    OGRPreparedGeometryH prepared = nullptr;
    ~Impl() {
        if (prepared)
            OGRDestroyPreparedGeometry(prepared);
    }
};

PreparedRegion::PreparedRegion(const MultiPolygon& region) : m(std::make_unique<Impl>()) {
    m->geom = detail::toOgr(region);
    m->prepared = OGRCreatePreparedGeometry(OGRGeometry::ToHandle(m->geom.get()));
}

PreparedRegion::~PreparedRegion() = default;
PreparedRegion::PreparedRegion(PreparedRegion&&) noexcept = default;
PreparedRegion& PreparedRegion::operator=(PreparedRegion&&) noexcept = default;

bool PreparedRegion::contains(const Polygon& poly) const {
    const auto p = detail::toOgr(poly);
    if (m->prepared)
        return OGRPreparedGeometryContains(m->prepared, OGRGeometry::ToHandle(p.get())) != 0;
    return m->geom->Contains(p.get());
}

bool PreparedRegion::intersects(const Polygon& poly) const {
    const auto p = detail::toOgr(poly);
    if (m->prepared)
        return OGRPreparedGeometryIntersects(m->prepared, OGRGeometry::ToHandle(p.get())) != 0;
    return m->geom->Intersects(p.get());
}

MultiPolygon PreparedRegion::intersection(const Polygon& poly) const {
    const auto p = detail::toOgr(poly);
    detail::OgrGeomPtr r(m->geom->Intersection(p.get()));
    return r ? detail::fromOgr(r.get()) : MultiPolygon{};
}

} // namespace pf::geo
