// Seeded sets of test areas like the unseen sites operators fly: rectangles, rectilinear and polygonal
// sites with no-fly zones, including zones so close that their margins merge into unreachable pockets.
#pragma once

#include "core/geo/types.h"
#include "core/plan/evaluation.h"
#include "core/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pf::plan {

// The families of area outlines.
enum class AreaFamily {
    Rectangle,   // aspect 1:1 to 3:1
    Rectilinear, // L, U, T or staircase (3 to 5 steps), right angles only
    Polygonal,   // convex (5 to 10 vertices) or concave star-shaped (7 to 12 vertices)
};
const char* areaFamilyName(AreaFamily f); // "rectangle", "rectilinear", "polygonal"
std::vector<AreaFamily> allAreaFamilies();

struct AreaGeneratorOptions {
    int count = 50;                 // areas, >= 1
    std::uint64_t seed = 1;
    double minAreaM2 = 100'000.0;   // 0.1 km2
    double maxAreaM2 = 250'000.0;   // 0.25 km2
    int minZones = 0;               // no-fly zones per area, drawn uniformly in [minZones, maxZones]
    int maxZones = 20;
    std::vector<AreaFamily> families = allAreaFamilies(); // area i has family families[i % size]
    geo::LonLat origin{8.40, 49.05}; // where the areas lie (WGS84); every area is centred here
    double marginM = 5.0;           // the safety margin the close zones are designed around
};

// One generated area. `shape` names its outline ("rectangle", "L", "U", "T", "staircase", "convex",
// "concave"), zoneKinds each zone's kind, parallel to area.noFly:
// - "rectangle" (8-50 m sides) and "circle" (6-25 m radius, a 24-gon), at any rotation;
// - "U": a U whose opening (3-8 m) is narrower than two margins, so that its margin closes the U
//   around a pocket;
// - "pair": two rectangles 2-10 m apart, whose margins merge;
// - "pocket": four bars around a square of 12-30 m with gaps of 2-8.5 m at the corners: the margins
//   merge into a closed ring and the square inside can only be photographed from outside it.
// Each group of zones is a pocket (8 %), a pair (10 %), a U (10 %), a circle (30 %) or a rectangle.
// Zones lie inside the area, at least 2 m from each other (except within a pair or pocket, by
// design), and cover at most a quarter of it.
struct GeneratedArea {
    EvalArea area;
    double areaM2 = 0.0;
    std::string shape;
    std::vector<std::string> zoneKinds;
};

// Area i depends only on (seed, i) and the options other than count: a larger count extends a set
// without changing its first areas. Every polygon passes geo::validatePolygon, every zone lies within
// the area. Errors: options out of range.
Result<std::vector<GeneratedArea>> generateAreas(const AreaGeneratorOptions& options);

// The area as an eval area file (resources/areas format): a GeoJSON FeatureCollection in WGS84, the
// area feature with role "area", name, shape, area_m2 and zones, then one feature per zone with role
// "nofly", name ("zone N") and kind. loadEvalArea reads it back.
std::string generatedAreaGeoJson(const GeneratedArea& area);

// A file name for it: "<name>.geojson".
std::string generatedAreaFileName(const GeneratedArea& area);

} // namespace pf::plan
