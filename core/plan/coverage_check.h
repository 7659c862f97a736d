// Independent coverage check: rasterises the real photo footprints over the admissible area and
// reports what is left uncovered, plus the waypoints and legs that break a no-fly margin.
#pragma once

#include "core/geo/polygon_ops.h"
#include "core/geo/types.h"
#include "core/result.h"
#include "core/sensor/footprint.h"

#include <cstddef>
#include <vector>

namespace pf::plan {

// The check takes the photos' footprints as sensor/footprint lays them out.
using sensor::PhotoFootprint;
using sensor::footprintRing;

struct CoverageCheckOptions {
    // Pixel side in metres; 0 picks min(0.5 m, shortest footprint side / 20).
    double resolutionM = 0.0;
    // The pixel side grows as needed to keep the raster within this many pixels (one byte each): the
    // memory stays within 64 MB and the time grows with the area plus the photos (each costs the
    // pixels of its footprint), never with their product. 64 M pixels keep the default resolution up
    // to a 2.7 km square at 5 m altitude (0.21 m pixels); a 5 km square is checked with 0.63 m.
    std::size_t maxPixels = 64'000'000;
    // Patches listed with a polygon, largest first; smaller ones still count in uncoveredAreaM2.
    std::size_t maxPatches = 100;
    // false: the patches come without their polygon (no union of pixels), with their pixels only
    // (UncoveredPatch::box and mask), for callers that only look pixels up.
    bool patchShapes = true;
};

struct UncoveredPatch {
    geo::MultiPolygon shape; // union of its pixels, local metres (empty without patchShapes)
    double areaM2 = 0.0;
    geo::Vec2 centroid{0, 0};
    // Its pixels: the box of their edges (the bounds of shape), `columns` pixels across it, and per
    // pixel of the box row by row from its lower left, 1 for the patch's own.
    geo::Box box;
    int columns = 0;
    std::vector<char> mask;
};

struct CoverageReport {
    double resolutionM = 0.0;      // pixel side actually used
    double admissibleAreaM2 = 0.0; // as rasterised (pixel centres inside the admissible area)
    double coveredAreaM2 = 0.0;
    double uncoveredAreaM2 = 0.0;
    double coveredFraction = 1.0;  // covered / admissible (1 for an empty area)
    int patchCount = 0;            // connected uncovered pieces (4-connected pixels), all of them
    std::vector<UncoveredPatch> patches; // the largest maxPatches, largest first
};

// Rasterises the admissible area and every photo's REAL footprint (not the effective one) and
// measures what the photos leave uncovered. The admissible area is the area minus the no-fly zones
// (what must appear on the images). Errors: a footprint side not positive, options out of range.
// `outlines`, when given, holds each photo's real outline (its footprint on the terrain, see
// core/terrain), checked instead of its rectangle; the rectangles still set the resolution.
Result<CoverageReport> checkCoverage(const geo::MultiPolygon& admissible, const std::vector<PhotoFootprint>& photos,
                                     const CoverageCheckOptions& opt = {},
                                     const std::vector<geo::Ring>* outlines = nullptr);

struct NoFlyViolations {
    int waypoints = 0; // waypoints closer to a no-fly zone than the margin (inside one included)
    int segments = 0;  // straight legs between consecutive waypoints that come closer than the margin
    int total() const { return waypoints + segments; }
};

// Counts margin breaches along each path (consecutive points are joined by straight legs), measured
// as exact distances to the zones with a small tolerance (1 cm + 0.5 % of the margin) so that points
// placed on a polygonised buffer of the margin are not counted.
NoFlyViolations countNoFlyViolations(const std::vector<std::vector<geo::Vec2>>& paths,
                                     const std::vector<geo::Polygon>& noFly, double marginM);

} // namespace pf::plan
