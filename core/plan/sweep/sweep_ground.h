// What surrounds a sweep's free space: the area, the no-fly zones and their grown margins, with the
// point tests and boundary runs the lanes are placed by.
#pragma once

#include "core/geo/even_odd.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/types.h"

#include <vector>

namespace pf::plan {

// What surrounds the free space, in world coordinates: the area, the zones and their grown margins.
class SweepGround {
public:
    SweepGround(const geo::MultiPolygon& area, const std::vector<geo::Polygon>& zones,
                const geo::MultiPolygon& grownZones);

    bool insideArea(const geo::Vec2& p) const;
    // Ground inside the area that only the margin of a zone keeps the aircraft from (admissible
    // ground).
    bool inMargin(const geo::Vec2& p) const;
    bool inZone(const geo::Vec2& p) const;
    // Inside a grown zone (which circumscribes its margin); probes off the boundary.
    bool inGrown(const geo::Vec2& p) const;
    // How far from p (on a boundary) along unit direction u the first boundary beyond lies: a zone,
    // a grown margin's edge or the area's outline (at most cap). From a lane end into a margin, how
    // far its ground runs; from a lane end over the area's edge, where the line comes back.
    double runToBoundary(const geo::Vec2& p, const geo::Vec2& u, double cap) const;
    // The zones whose boundary lies within d of p.
    std::vector<int> zonesNear(const geo::Vec2& p, double d) const;
    const geo::Polygon& zone(int i) const { return m_zones[static_cast<std::size_t>(i)]; }

private:
    struct Rings {
        std::vector<geo::Ring> rings;
        geo::Box box;
    };
    const geo::MultiPolygon& m_area;
    const geo::MultiPolygon& m_grown;
    const std::vector<geo::Polygon>& m_zones;
    std::vector<Rings> m_blockers; // per zone and per grown polygon; the area last
    std::vector<geo::Box> m_areaBoxes, m_grownBoxes;
    // The point tests' edges by height (the same answers as geo::insideEvenOdd).
    std::vector<geo::EvenOddIndex> m_areaIndex, m_grownIndex, m_zoneIndex;
};

} // namespace pf::plan
