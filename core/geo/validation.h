// Validation of WGS84 polygons as users draw or import them, with messages that say what and where.
#pragma once

#include "core/geo/types.h"

#include <string>
#include <vector>

namespace pf::geo {

enum class Severity { Warning, Error };

// One problem found in the input. Errors stop planning; warnings are reported and planning goes on.
struct Problem {
    Severity severity = Severity::Error;
    std::string message;
};

// Checks one polygon (outer ring and holes). `what` names it in the messages, e.g. "the area" or
// "no-fly zone \"Warehouse\"". Vertices are numbered from 1 in the order given; a repeated closing
// vertex is allowed. Reports, as errors:
// - coordinates that are not finite or out of range (|lon| <= 180, |lat| <= 85: the planning frame
//   does not reach the poles), naming the vertex;
// - fewer than 3 distinct vertices;
// - zero area (all vertices on one line);
// - self-intersection, naming the two edges and the lon/lat of the crossing
//   ("edges 2-3 and 5-6 cross near 8.330120, 49.012310");
// - a hole outside its outer ring, crossing it, or overlapping another hole;
// - anything else GEOS finds invalid, with its explanation.
std::vector<Problem> validatePolygon(const GeoPolygon& poly, const std::string& what);

// The ring without a repeated closing vertex and without consecutive duplicate vertices.
GeoRing cleanRing(const GeoRing& ring);
GeoPolygon cleanPolygon(const GeoPolygon& poly);

// True if any problem is an error.
bool hasError(const std::vector<Problem>& problems);

} // namespace pf::geo
