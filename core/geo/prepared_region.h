// A region prepared once for many small queries (does it contain this cell? what of it lies in this cell?).
#pragma once

#include "core/geo/types.h"

#include <memory>

namespace pf::geo {

// GEOS's prepared geometry behind OGR: the region's edges are indexed once, so that testing many small
// polygons against a large region (an area with dozens of zone holes) costs little per query. Not
// copyable; cheap to move.
class PreparedRegion {
public:
    explicit PreparedRegion(const MultiPolygon& region);
    ~PreparedRegion();
    PreparedRegion(PreparedRegion&&) noexcept;
    PreparedRegion& operator=(PreparedRegion&&) noexcept;

    // True if `poly` lies wholly inside the region (boundary contact allowed on the outside only as
    // GEOS defines "contains").
    bool contains(const Polygon& poly) const;
    bool intersects(const Polygon& poly) const;
    // The part of `poly` inside the region.
    MultiPolygon intersection(const Polygon& poly) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace pf::geo
