// Lanes: the straight, photographed legs of a coverage flight, and the one rule placing their photos.
#pragma once

#include "core/geo/types.h"

#include <vector>

namespace pf::plan {

// One straight lane. Its strip is the ground of width `track spacing` centred on the lane's line;
// stripStart and stripEnd are where, along that line, the strip's admissible ground begins and ends
// (exact geometry, not the cell staircase). The aircraft flies from the first photo to the last and
// turns there: no photo point lies outside [stripStart, stripEnd].
struct Lane {
    geo::Vec2 stripStart{0, 0};
    geo::Vec2 stripEnd{0, 0};
    std::vector<geo::Vec2> photos; // in flight order, from stripStart's side to stripEnd's
    double headingDeg = 0.0;       // clockwise from north, the direction of flight
};

// The photo points of a strip from a to b with the trigger distance `spacing` (the effective
// footprint along the track): n = max(1, ceil(|ab| / spacing)) points exactly `spacing` apart,
// centred on the strip, so that their effective footprints (spacing long each) tile a stretch of
// n * spacing >= |ab| that contains the strip: the first and last photos cover the strip up to its
// ends, and constant spacing is what a camera triggering by distance takes. A Survey transect starts
// photographing at the boundary itself (half a footprint of photo outside the area at each end);
// centring saves up to one photo per lane and flies the lane up to `spacing` shorter.
std::vector<geo::Vec2> stripPhotos(const geo::Vec2& a, const geo::Vec2& b, double spacing);

// A Lane from its strip: the photos by stripPhotos, the heading from a to b (north for a == b).
Lane makeLane(const geo::Vec2& a, const geo::Vec2& b, double spacing);

// The same when only [flyA, flyB] of the strip's line may be flown (a no-fly margin covers the strip's
// ends: its ground is admissible and must be seen, but from outside the margin). flyA and flyB lie on
// the segment ab, flyA nearer to a. A photo that stripPhotos puts beyond them moves to the nearer of
// them, where the real footprint, longer than the trigger distance, still sees the margin's ground up
// to half its length ahead; photos that then coincide (within 1 cm) become one. The spacing stays
// exact between the photos that did not move.
Lane makeLane(const geo::Vec2& a, const geo::Vec2& b, double spacing, const geo::Vec2& flyA, const geo::Vec2& flyB);

// What makeLane(a, b, spacing, flyA, flyB) flies, without placing every photo: its first and last
// photo and how many it takes. For planners that weigh many candidate lanes before building some.
struct LaneSpan {
    geo::Vec2 first{0, 0};
    geo::Vec2 last{0, 0};
    int photos = 0;
};
LaneSpan laneSpan(const geo::Vec2& a, const geo::Vec2& b, double spacing, const geo::Vec2& flyA, const geo::Vec2& flyB);

} // namespace pf::plan
