// The no-fly model: zones with their safety margin, exact clearances and the shortest safe paths.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"

#include <utility>
#include <vector>

namespace pf::geo {

// No-fly zones with their safety margin, measured exactly (distances to the zones' edges) rather
// than through a polygonised buffer, so that every stage agrees on what "safe" means.
//
// What keeps the margin, everywhere: a clearance of at least margin - tolerance(). A leg passing at
// exactly the margin (5.0 m of 5 m) keeps it, and so does one a few millimetres closer (the drawing
// tolerance below); one at 4.96 m of 5 m does not, and the route check prints it so (never "5.0 m").
// Two uses, two strictnesses:
// - the final checks (mission::checkRoute, plan::countNoFlyViolations: field made with forCheck())
//   flag a breach below margin - tolerance();
// - the planner's own tests (a field made with the constructor: detours, transits, sorties, photo
//   placement's safety net) ask kPlanningSlackM more, so that a leg the planner accepts at its limit
//   is still accepted by the check after the rounding it goes through (the route is checked in WGS84,
//   converted back to metres in the check's own frame). The slack is no safety distance: a stage
//   that moves or drops waypoints after the no-fly stage must test the legs it makes with the
//   planner's field (dropNearDuplicates does).
// The grid asks a third kind (ofGrownZones): its zones buffered as polygons by a little more than the
// margin, the polygons its cells and flight positions are cut from, so that its answers agree with
// its cells. That buffer contains the margin's true offset (grid.h), so what the grid calls safe a
// margin field of the same zones calls safe too; not the other way round: the grid keeps up to 2 %
// more, and asking a margin field instead would change the grid's cells and so its plans.
class NoFlyField {
public:
    // The planner's slack beyond the check's threshold: 300 times what a round trip through WGS84 costs
    // (3e-9 m measured across an 800 m area), so small that it changes no plan of the 60 generated
    // areas (1 mm already added a detour corner on one).
    static constexpr double kPlanningSlackM = 1e-6;

    NoFlyField() = default;
    // A field for planning: safe means at least margin - tolerance() + kPlanningSlackM away.
    NoFlyField(std::vector<Polygon> zones, double marginM);
    // A field for the final check: safe means at least margin - tolerance() away.
    static NoFlyField forCheck(std::vector<Polygon> zones, double marginM);
    // A field of zones already grown by their margin as polygons (the grid's buffered zones, whose
    // cells and flight positions are cut from those polygons): safe means not inside them. Their
    // boundary counts as outside, to kGrownBoundaryM for a point (a flight position computed on it
    // carries rounding errors of ~1e-9 m), and a segment may run along it or touch it.
    static NoFlyField ofGrownZones(std::vector<Polygon> grown);
    static constexpr double kGrownBoundaryM = 1e-6;

    const std::vector<Polygon>& zones() const { return m_zones; }
    double marginM() const { return m_margin; }
    bool empty() const { return m_zones.empty(); }
    // Slack granted below the margin: 1 cm + 0.5 % of it, the gap between a circle and the polygon
    // GEOS uses for a buffer (8 segments per quarter), so points on such a buffer count as safe.
    double tolerance() const { return 0.01 + 0.005 * m_margin; }
    // The least clearance this field accepts (see above): margin - tolerance(), plus the planning
    // slack for a planner's field.
    double minClearance() const { return m_margin - tolerance() + m_slack; }

    // Distance from p (or from the segment ab) to the nearest zone; 0 inside or across one.
    double clearance(const Vec2& p) const;
    double clearance(const Vec2& a, const Vec2& b) const;
    // Inside or touching a zone is never safe, whatever the margin (but see ofGrownZones).
    // The same answers as isSafeClearance(clearance(...)), but a zone whose bounding box lies beyond
    // the margin is skipped and the scan stops at the first zone too close: planners ask these
    // millions of times. A field of grown zones answers by containment as said above.
    bool pointIsSafe(const Vec2& p) const;
    bool segmentIsSafe(const Vec2& a, const Vec2& b) const;
    bool isSafeClearance(double c) const { return c > 0.0 && c >= minClearance(); }

private:
    std::vector<Polygon> m_zones;
    std::vector<std::pair<Vec2, Vec2>> m_boxes; // per zone: min, max
    std::vector<std::pair<Vec2, double>> m_circles; // per zone: a circle holding it (centre, radius)
    std::vector<double> m_reach;                    // per zone: its farthest vertex from that centre
    // Every zone's edges with their boxes, zone after zone (zone i: m_edgeBegin[i] to m_edgeBegin[i + 1]),
    // so that the segment test reads them in order without working them out again.
    struct Edge {
        Vec2 c{0, 0}, d{0, 0}, lo{0, 0}, hi{0, 0};
    };
    std::vector<Edge> m_edges;
    std::vector<std::size_t> m_edgeBegin;
    double m_margin = 0.0;
    double m_slack = kPlanningSlackM;
    bool m_grown = false; // made by ofGrownZones: the margin is in the polygons
};

// Shortest safe paths around the zones: a visibility graph over the vertices of the zones buffered
// by a little more than the margin (so the graph's straight edges, chords of that buffer, still
// keep the margin), searched with Dijkstra.
class SafePathFinder {
public:
    explicit SafePathFinder(NoFlyField field = {});

    const NoFlyField& field() const { return m_field; }
    // The points strictly between a and b of the shortest safe path (empty when the straight
    // segment is safe). Errors: a or b inside a margin, or no safe way around.
    Result<std::vector<Vec2>> detour(const Vec2& a, const Vec2& b) const;
    // The nearest safe point to p (p itself when it is safe): on the inflated margin's boundary.
    Vec2 nearestSafePoint(const Vec2& p) const;

private:
    NoFlyField m_field;
    std::vector<Vec2> m_nodes;
    std::vector<std::vector<std::pair<int, double>>> m_edges;
    MultiPolygon m_inflated;
};

} // namespace pf::geo
