// Test helpers for corridors: generated centre lines with bends, the cameras of the tests, the real
// footprints of a plan checked over the corridor's ground and the lawnmower's photos over it.
#pragma once

#include "core/geo/polygon_ops.h"
#include "core/plan/corridor/corridor_planner.h"
#include "core/plan/coverage_check.h"
#include "core/plan/lawnmower_planner.h"

#include <cmath>
#include <string>
#include <vector>

namespace pf::plan::corridortest {

using geo::Vec2;

// A camera of 60 x 45 degrees at 30 m with its overlaps (the real footprint 34.6 x 24.9 m).
struct Camera {
    double front = 0.2, side = 0.2;
    double realAcross = 2 * 30 * std::tan(30 * M_PI / 180);
    double realAlong = 2 * 30 * std::tan(22.5 * M_PI / 180);
    double track() const { return (1 - side) * realAcross; }
    double photo() const { return (1 - front) * realAlong; }
};

// A line of legs of `legM` from the origin, heading `startDeg` (counter-clockwise from east),
// turning by each of `turnsDeg` in turn (positive to the left).
inline Polyline bentLine(double legM, const std::vector<double>& turnsDeg, double startDeg = 20.0) {
    Polyline line{Vec2(0, 0)};
    double a = startDeg * M_PI / 180.0;
    for (std::size_t i = 0; i <= turnsDeg.size(); ++i) {
        line.push_back(line.back() + legM * Vec2(std::cos(a), std::sin(a)));
        if (i < turnsDeg.size())
            a += turnsDeg[i] * M_PI / 180.0;
    }
    return line;
}

// A width of exactly `lanes` lanes at the camera's track spacing, less `short` of a lane.
inline double widthFor(int lanes, const Camera& cam, double shortOf = 0.0) {
    return (lanes - shortOf) * cam.track();
}

inline CorridorOptions optionsFor(double widthM, const Camera& cam) {
    CorridorOptions o;
    o.widthM = widthM;
    o.trackSpacingM = cam.track();
    o.photoSpacingM = cam.photo();
    return o;
}

inline std::vector<PhotoFootprint> footprints(const CorridorPlan& p, const Camera& cam) {
    std::vector<PhotoFootprint> out;
    for (const auto& r : p.runs)
        for (const auto& q : r.points)
            if (q.photo)
                out.push_back({q.pos, q.headingDeg, cam.realAcross, cam.realAlong});
    return out;
}

// The share of `ground` the plan's real footprints see (0.5 m pixels).
inline double coverage(const CorridorPlan& p, const geo::MultiPolygon& ground, const Camera& cam,
                       double resolutionM = 0.5) {
    CoverageCheckOptions o;
    o.resolutionM = resolutionM;
    o.patchShapes = false;
    auto r = checkCoverage(ground, footprints(p, cam), o);
    return r ? r->coveredFraction : 0.0;
}

// The photos of the lawnmower (the Survey pattern) over the corridor's ground: its fastest angle
// and entry whose photos see 99.5 % of the ground, as eval --survey takes it.
inline int lawnmowerPhotos(const geo::MultiPolygon& ground, const Camera& cam) {
    LawnmowerOptions o;
    o.trackSpacingM = cam.track();
    o.photoSpacingM = cam.photo();
    o.footprintAcrossM = cam.realAcross;
    o.footprintAlongM = cam.realAlong;
    o.searchCoverageResolutionM = 2.0; // the search's raster only: the tests stay fast
    auto p = planLawnmower(ground, o);
    return p ? p->photos : -1;
}

inline int photoCount(const CorridorPlan& p) {
    return p.stats.photos;
}

} // namespace pf::plan::corridortest
