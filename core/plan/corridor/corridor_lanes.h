// A corridor lane's photos: the trigger distance measured along the lane, closer where the lane
// turns so that its strip keeps the overlap on the outside of every bend; cut where no-fly margins
// cross it.
#pragma once

#include "core/geo/types.h"
#include "core/plan/corridor/corridor_geometry.h"

#include <utility>
#include <vector>

namespace pf::plan {

// A point a corridor flight passes: a photo, or a corner of a lane flown without one.
struct CorridorPoint {
    geo::Vec2 pos{0, 0};
    double headingDeg = 0.0; // clockwise from north: the lane's direction there
    bool photo = false;
    double along = 0.0;   // distance along its lane from the lane's start
    double station = 0.0; // the centre line's station beside it
};

// The photos of one lane (in the lane's direction), as a camera triggering by distance takes them,
// with the distance measured on the strip's outer edge rather than on the lane:
// - on a straight stretch every `spacingM` (the trigger distance), centred on the lane as
//   plan::stripPhotos centres a straight lane (n = ceil(measure / spacing) photos);
// - where the lane turns by an angle a, its strip's outer edge jumps by the chord
//   stripWidthM * sin(a / 2) (on the circle of half a strip round the corner) while the lane does
//   not move: that chord is added to the measure, so the photos round a corner lie closer on the
//   lane and their footprints still meet on the outside. On the outside of a bend, where the lane
//   follows a circle of radius r in short tangent legs, this gives a spacing of spacing * r / (r +
//   strip / 2) along the lane: the outer edge of its strip sees the trigger distance. On the
//   inside, and on a straight lane, the spacing stays the trigger distance: no photos stacked where
//   the lanes are short. A corner's chord counts at most 0.9 spacings, so at most one photo falls
//   on a corner; it takes the heading half way between the legs.
std::vector<CorridorPoint> lanePhotos(const OffsetLine& lane, double spacingM, double stripWidthM);

// Lengths along the lane, [from, to], that lie inside any of `blocked` (no-fly zones grown by their
// margin), sorted and merged.
using Interval = std::pair<double, double>;
std::vector<Interval> blockedIntervals(const Polyline& lane, const geo::MultiPolygon& blocked);

// A lane's flyable stretches with their photos: a photo inside a blocked stretch moves to its
// nearer end (where its footprint still sees the margin's ground ahead; photos meeting there become
// one), photos in a stretch at the lane's own end move to the other end; each flyable stretch with
// at least one photo is one run, from its first photo to its last, with the lane's corners between
// them as points without a photo.
struct CorridorRun {
    int lane = 0;
    std::vector<CorridorPoint> points; // in the lane's direction
    double firstStation() const { return points.front().station; }
    double lastStation() const { return points.back().station; }
};
std::vector<CorridorRun> laneRuns(const OffsetLine& lane, int laneIndex,
                                  std::vector<CorridorPoint> photos,
                                  const std::vector<Interval>& blocked);

// Heading clockwise from north of direction d (north for a zero vector).
double compassHeadingDeg(const geo::Vec2& d);

} // namespace pf::plan
