// Curvature-bounded connections for planes: Dubins paths (arcs of a minimum radius and straight
// segments) between two poses, their sampling, and the time of a plane flying lanes joined by them.
#pragma once

#include "core/geo/types.h"
#include "core/plan/flight_time.h"

#include <array>
#include <optional>
#include <vector>

namespace pf::route {

// A position and a direction of flight in the mission's local frame (metres, x east, y north). The
// heading is in radians counter-clockwise from +x (east), as atan2 counts angles; waypoint headings
// (degrees clockwise from north) convert with headingFromCompassDeg / compassFromHeadingRad.
struct Pose {
    geo::Vec2 pos{0, 0};
    double headingRad = 0.0;
};
double headingFromCompassDeg(double compassDeg);
double compassFromHeadingRad(double headingRad); // in [0, 360)

// The six words of Dubins' theorem: every shortest path of bounded curvature between two poses is
// one of them (L a left arc, R a right arc, S a straight segment; arcs of exactly the minimum
// radius).
enum class DubinsWord { LSL, RSR, LSR, RSL, RLR, LRL };
inline constexpr std::array<DubinsWord, 6> kDubinsWords{DubinsWord::LSL, DubinsWord::RSR,
                                                        DubinsWord::LSR, DubinsWord::RSL,
                                                        DubinsWord::RLR, DubinsWord::LRL};
const char* dubinsWordName(DubinsWord w); // "LSL", ...

enum class SegmentKind { Left, Straight, Right };

// One Dubins path: its word and its three segments, an arc as its turn in radians (its length is
// the turn times the radius), the straight as its length in metres. Segments may be empty.
struct DubinsPath {
    Pose start;
    double radiusM = 0.0;
    DubinsWord word = DubinsWord::LSL;
    std::array<double, 3> segment{0, 0, 0};

    SegmentKind kind(int i) const;
    double segmentLengthM(int i) const;
    double lengthM() const { return segmentLengthM(0) + segmentLengthM(1) + segmentLengthM(2); }
    // The pose `s` metres along the path (clamped to [0, lengthM()]).
    Pose poseAt(double s) const;
    Pose end() const { return poseAt(lengthM()); }
};

// The path of one word from `from` to `to` with minimum turn radius `radiusM` (>= 0), or nothing
// when that word cannot join them (LSR/RSL when the two turning circles overlap, RLR/LRL when they
// lie more than four radii apart, or the radius is 0). Of the two middle circles a CCC word can
// use, the shorter path is returned. Radius 0 turns on the spot: every CSC word is then the
// straight line between the points, whatever the headings (a heading change costs no length).
std::optional<DubinsPath> dubinsPath(const Pose& from, const Pose& to, double radiusM,
                                     DubinsWord word);

// The shortest of the six words (one always exists). Constant time, a few dozen floating-point
// operations: the planners call it for every pair of lane ends they compare.
DubinsPath shortestDubinsPath(const Pose& from, const Pose& to, double radiusM);
// Its length alone.
double dubinsDistanceM(const Pose& from, const Pose& to, double radiusM);

// Poses along the path at equal steps of at most `stepM` metres (> 0) from its start to its end
// pose (both included): consecutive positions are at most `stepM` apart and headings change by at
// most stepM / radius between them. For drawing, the exports' turn waypoints and the curvature
// check.
std::vector<Pose> samplePath(const DubinsPath& path, double stepM);
// The positions of samplePath appended to `out`, without the first one when `skipFirst` (to chain
// lanes and connections into one polyline without repeating a point).
void appendSampledPoints(const DubinsPath& path, double stepM, std::vector<geo::Vec2>& out,
                         bool skipFirst = false);

// The largest curvature (1 / metres) of a polyline: at each interior vertex that of the circle
// through it and its two neighbours (Menger curvature: 4 x triangle area / product of the three
// sides); 0 for collinear points and fewer than three; infinite where the polyline doubles back on
// itself. A path of minimum radius R sampled along its length has at most 1 / R. Repeated points
// are skipped.
double maxCurvature(const std::vector<geo::Vec2>& polyline);

// A lane as a plane flies it: from `start` to `end`, photos along it.
struct DirectedLane {
    geo::Vec2 start{0, 0};
    geo::Vec2 end{0, 0};
};

// What a plane flies over lanes in order, estimated without sampling: each lane from its run-in
// point
// (`runInM` before its start on its line: the camera level and the track settled before the first
// photo) to its end, and between lanes the shortest Dubins path of radius `radiusM` from the end of
// one lane (heading along it) to the run-in point of the next (heading along that). Level flight at
// the model's cruise speed: the time is the length / V, as plan::flightTime gives for the flown
// polyline (planeLanesPath) of a fixed-wing model. Lanes of zero length are skipped.
struct PlaneLanesEstimate {
    double lanesM = 0.0;       // the lanes, run-ins included
    double connectionsM = 0.0; // the Dubins connections between them
    double timeS = 0.0;
    double lengthM() const { return lanesM + connectionsM; }
};
PlaneLanesEstimate planeLanesEstimate(const std::vector<DirectedLane>& lanes, double radiusM,
                                      double runInM, const plan::FlightTimeModel& model);

// The flown polyline of that flight, the arcs sampled every `stepM` metres (at most): what
// plan::flightTime times and maxCurvature checks. Its length is planeLanesEstimate's less the chord
// error of the sampling (under 0.1 % at a step of R / 10).
std::vector<geo::Vec2> planeLanesPath(const std::vector<DirectedLane>& lanes, double radiusM,
                                      double runInM, double stepM);

} // namespace pf::route
