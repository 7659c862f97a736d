// Boustrophedon cellular decomposition of a polygon with holes along a sweep direction, and the merging
// of neighbouring cells into larger ones that one back-and-forth pattern still covers.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"

#include <cmath>
#include <utility>
#include <vector>

namespace pf::plan {

// The sweep frame: world coordinates rotated so that the lanes run along the frame's x axis.
struct SweepFrame {
    SweepFrame() = default;
    explicit SweepFrame(double angle) : angleRad(angle), cosA(std::cos(angle)), sinA(std::sin(angle)) {}
    double angleRad = 0.0; // lane direction, counter-clockwise from east
    // Its cosine and sine, computed once: the planner turns every lane point and photo through the frame.
    double cosA = 1.0, sinA = 0.0;
    geo::Vec2 toFrame(const geo::Vec2& p) const { return {cosA * p.x() + sinA * p.y(), -sinA * p.x() + cosA * p.y()}; }
    geo::Vec2 toWorld(const geo::Vec2& p) const { return {cosA * p.x() - sinA * p.y(), sinA * p.x() + cosA * p.y()}; }
};

// One cell, in the sweep frame: every horizontal line between ylo and yhi meets it in one interval
// [xLeft(y), xRight(y)], so a back-and-forth pattern of horizontal lanes covers it without leaving it.
// The cell is bounded below and above by cuts (horizontal segments, possibly points) and on the sides
// by two chains of the polygon's boundary.
struct MonotoneCell {
    std::vector<geo::Vec2> left, right; // chains from bottom to top (y non-decreasing)
    double ylo = 0.0, yhi = 0.0;
    std::vector<int> below, above;      // cells across the bottom and the top cut
    // x ranges of boundary lying flat along the bottom (y = ylo) and top (y = yhi): what lies beyond
    // there is not free (outside the polygon); the planner decides whether it is ground to photograph.
    std::vector<std::pair<double, double>> bottomContacts, topContacts;
    // Boundary vertices that touch the bottom / top from beyond (where an obstacle begins or ends).
    std::vector<geo::Vec2> bottomTouches, topTouches;

    // The cell's interval at y (clamped to [ylo, yhi]); at a height where a chain runs horizontally,
    // the narrower interval.
    double xLeft(double y) const;
    double xRight(double y) const;
    // The extreme x of the cell between heights y1 <= y2 (clamped to [ylo, yhi]).
    double minLeft(double y1, double y2) const;
    double maxRight(double y1, double y2) const;
    // The outline (counter-clockwise): the right chain upwards, then the left chain downwards.
    geo::Ring ring() const;
    double area() const;
};

struct Decomposition {
    SweepFrame frame;
    std::vector<MonotoneCell> cells; // cells of zero height are dropped (their neighbours joined)
};

// The boustrophedon decomposition of `polys` (world coordinates, valid polygons with holes) for lanes
// along `frame`: a sweep line parallel to the lanes moves across the polygons; a cell ends and new ones
// begin wherever the line's intersection with the polygons splits or joins (vertices are ordered by
// (y, x), which handles boundary edges parallel to the lanes). Errors: geometry the sweep cannot
// order consistently (touching or crossing rings).
Result<Decomposition> decompose(const geo::MultiPolygon& polys, const SweepFrame& frame);

// A bottom-to-top chain of decomposition cells, each sharing its top cut with the next one's bottom:
// their union meets every horizontal line in one interval, so one pattern covers it.
struct MergedCell {
    std::vector<int> parts;
};

// Cells merged along the cuts: each cell joins at most one neighbour above and one below, the pairs
// that share the longest stretch of cut first (the lanes there continue with the least change).
std::vector<MergedCell> mergeCells(const Decomposition& d);

// A merged cell's outline in the sweep frame.
geo::Ring mergedRing(const Decomposition& d, const MergedCell& m);

} // namespace pf::plan
