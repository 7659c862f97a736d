// Photo footprints on the terrain (rays through the image border meet the ground) and the lowest
// height above ground a camera sees when it follows the terrain.
#pragma once

#include "core/geo/types.h"
#include "core/terrain/height_grid.h"

#include <functional>

namespace pf::terrain {

// A nadir camera at `pos` (local metres), `altitudeM` above mean sea level, flying towards
// `headingDeg` (clockwise from north) with the image's long side across the track: tanHalfAcross and
// tanHalfAlong are the tangents of half the fields of view across and along the track.
struct NadirCamera {
    geo::Vec2 pos{0, 0};
    double altitudeM = 0.0;
    double headingDeg = 0.0;
    double tanHalfAcross = 0.0;
    double tanHalfAlong = 0.0;
};

// Where the ray from the camera through the image point (u, v) in [-1, 1]^2 (u across the track,
// to the right; v along it, ahead) first meets the ground. Where the grid has no data the ground is
// taken as level with the last known height (the ground under the camera, else 0).
geo::Vec2 groundPoint(const HeightGrid& grid, const NadirCamera& cam, double u, double v);

// The footprint on the terrain as a ring (counter-clockwise, local metres): the ground points of
// `perSide` rays along each side of the image border (flat facets between them).
geo::Ring footprintOnTerrain(const HeightGrid& grid, const NadirCamera& cam, int perSide = 6);

// Per node of `grid`: the largest rise of the ground within `radiusM` (a square of half-side
// radiusM) over the ground at that node, NaN where the node has no data (nodes without data count as
// no rise). A camera following the terrain at height H above the ground under that node sees no
// ground closer than H minus this. A separable running maximum (two passes of a monotone queue):
// linear in the number of nodes whatever the radius.
HeightGrid riseWithin(const HeightGrid& grid, double radiusM);

// The largest rise of the ground within `radiusM` of any node whose position `inside` accepts
// (riseWithin, then the largest over those nodes).
double maxRiseWithin(const HeightGrid& grid, double radiusM, const std::function<bool(const geo::Vec2&)>& inside);
// The same over rises riseWithin already found.
double maxRiseWithin(const HeightGrid& rises, const std::function<bool(const geo::Vec2&)>& inside);

// The largest of riseWithin's rises along the segment a -> b: at every node of the grid cells the
// segment passes through (so never less than at the segment's own points); +infinity where the
// segment leaves the grid (nothing is known there) or the grid is empty.
double maxRiseAlong(const HeightGrid& rises, const geo::Vec2& a, const geo::Vec2& b);

} // namespace pf::terrain
