// Corridor geometry: a centre line and a width, the ground within half the width of the line, and
// the lines parallel to it that a corridor's lanes fly.
#pragma once

#include "core/geo/types.h"

#include <vector>

namespace pf::plan {

using Polyline = std::vector<geo::Vec2>;

// The line without repeated points (closer than 1 cm) and without vertices the line runs straight
// through (a turn below 0.01 degrees): every vertex left is a bend.
Polyline cleanLine(const Polyline& line);

// The distance along the line from its first point to each vertex (size line.size()).
std::vector<double> lineStations(const Polyline& line);
double lineLength(const Polyline& line);

// The signed turn at vertex i (0 < i < size - 1) in radians, (-pi, pi]: positive to the left.
double turnAt(const Polyline& line, std::size_t i);

// The corridor's ground: every point within widthM / 2 of the line, cut square across the line at
// its two ends. On the outside of a bend that is a circular sector round the vertex (the ground a
// road's verge sweeps), on the inside the two straight parts overlap. `quadrantSegments` polygon
// edges per quarter circle (the polygon lies inside the true circle by at most
// widthM / 2 * (1 - cos(pi / (4 * quadrantSegments)))). A line crossing itself gives a polygon with
// holes, or several. Empty for fewer than two points or a width not positive.
geo::MultiPolygon corridorGround(const Polyline& line, double widthM, int quadrantSegments = 16);

// The part of the line from station a to station b (0 <= a < b <= length), its ends interpolated.
Polyline subLine(const Polyline& line, double a, double b);

// The point at station s of the line, and the unit direction of the segment it lies on.
geo::Vec2 pointAt(const Polyline& line, const std::vector<double>& stations, double s,
                  geo::Vec2* dir = nullptr);

// One lane's line: the centre line moved sideways by `offsetM` (positive to the left of the
// direction of the line), from the square cut at its first point to the one at its last.
// - On the inside of a bend the lane turns at the point where its two straight parts meet (a
// mitre):
//   its strip's two parts overlap there and nothing inside the bend is photographed twice more than
//   that. Beyond 150 degrees the mitre would lie far back down the corridor, so the two parts are
//   joined straight (a bevel). A straight part that a tight bend makes run backwards is dropped and
//   its neighbours joined where they meet, as in any offset of a polygon.
// - On the outside the lane follows the circle round the vertex at |offsetM|, as the corridor's
// ground
//   does, flown as straight legs tangent to that circle: as few as keep every corner within
//   `arcToleranceM` of it (a single corner, the mitre, for small bends and lanes near the line).
// `stations` gives, per point, the station of the centre line it lies beside (its projection on the
// segment it belongs to; a bend's points the bend's station).
struct OffsetLine {
    Polyline points;
    std::vector<double> stations;
};
OffsetLine offsetLine(const Polyline& line, double offsetM, double arcToleranceM);

// The lateral offsets of `count` lanes across a corridor of width widthM whose strips are
// trackSpacingM wide: centred, the outer strips flush with the corridor's edges and the lanes
// evenly spaced (at most trackSpacingM apart when count = laneCount(...)); one lane on the line for
// count 1.
int laneCount(double widthM, double trackSpacingM);
std::vector<double> laneOffsets(double widthM, double trackSpacingM, int count);

} // namespace pf::plan
