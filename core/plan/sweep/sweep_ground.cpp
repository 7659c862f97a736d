#include "core/plan/sweep/sweep_ground.h"

#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pf::plan {

using geo::Vec2;

namespace {

double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// The ground model probes points a few centimetres off a boundary, never on one: the even-odd rule
// alone is exact there.
bool insideAny(const std::vector<geo::EvenOddIndex>& polys, const std::vector<geo::Box>& boxes,
               const Vec2& p) {
    for (std::size_t i = 0; i < polys.size(); ++i)
        if (boxes[i].contains(p) && polys[i].inside(p))
            return true;
    return false;
}

void addRings(const geo::Polygon& poly, std::vector<geo::Ring>& out) {
    out.push_back(poly.outer);
    for (const auto& h : poly.holes)
        out.push_back(h);
}

} // namespace

SweepGround::SweepGround(const geo::MultiPolygon& area, const std::vector<geo::Polygon>& zones,
                         const geo::MultiPolygon& grownZones)
    : m_area(area), m_grown(grownZones), m_zones(zones) {
    auto add = [&](const geo::Polygon& poly) {
        Rings r;
        addRings(poly, r.rings);
        r.box = geo::bounds(poly);
        m_blockers.push_back(std::move(r));
    };
    for (const auto& z : zones)
        add(z);
    for (const auto& g : grownZones)
        add(g);
    for (const auto& a : area)
        add(a);
    for (const auto& a : area) {
        m_areaBoxes.push_back(geo::bounds(a));
        m_areaIndex.emplace_back(a);
    }
    for (const auto& g : grownZones) {
        m_grownBoxes.push_back(geo::bounds(g));
        m_grownIndex.emplace_back(g);
    }
    for (const auto& z : zones)
        m_zoneIndex.emplace_back(z);
}

bool SweepGround::insideArea(const Vec2& p) const {
    return insideAny(m_areaIndex, m_areaBoxes, p);
}

bool SweepGround::inMargin(const Vec2& p) const {
    return insideArea(p) && inGrown(p);
}

bool SweepGround::inGrown(const Vec2& p) const {
    return insideAny(m_grownIndex, m_grownBoxes, p);
}

bool SweepGround::inZone(const Vec2& p) const {
    for (std::size_t i = 0; i < m_zones.size(); ++i)
        if (m_blockers[i].box.contains(p) && m_zoneIndex[i].inside(p))
            return true;
    return false;
}

double SweepGround::runToBoundary(const Vec2& p, const Vec2& u, double cap) const {
    double best = cap;
    const Vec2 far = p + cap * u;
    const geo::Box ray{p.cwiseMin(far), p.cwiseMax(far)};
    for (const auto& b : m_blockers) {
        if (!b.box.intersects(ray))
            continue;
        for (const auto& ring : b.rings) {
            const std::size_t n = ring.size();
            for (std::size_t i = 0; i < n; ++i) {
                const Vec2& c = ring[i];
                const Vec2 e = ring[(i + 1) % n] - c;
                const double den = cross(u, e);
                if (std::abs(den) < 1e-15)
                    continue;
                const Vec2 pc = c - p;
                const double t = cross(pc, e) / den; // along the ray
                const double s = cross(pc, u) / den; // along the edge
                if (t > 0.02 && t < best && s >= 0.0 && s <= 1.0)
                    best = t;
            }
        }
    }
    return best;
}

std::vector<int> SweepGround::zonesNear(const Vec2& p, double d) const {
    std::vector<int> out;
    for (std::size_t i = 0; i < m_zones.size(); ++i) {
        const geo::Box& b = m_blockers[i].box;
        if (p.x() < b.min.x() - d || p.x() > b.max.x() + d || p.y() < b.min.y() - d ||
            p.y() > b.max.y() + d)
            continue;
        if (geo::insideEvenOdd(m_zones[i], p) || geo::distanceToBoundary(m_zones[i], p) <= d)
            out.push_back(static_cast<int>(i));
    }
    return out;
}

} // namespace pf::plan
