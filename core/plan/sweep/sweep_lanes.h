// The lanes of one cell of a sweep: their heights across the cell, what each photographs and where
// it is flown, given what lies around the cell (the area's edge, a no-fly margin).
#pragma once

#include "core/geo/even_odd.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/types.h"
#include "core/plan/lanes/lane.h"
#include "core/plan/sweep/decomposition.h"
#include "core/plan/sweep/sweep_ground.h"

#include <functional>
#include <optional>
#include <vector>

namespace pf::plan {

struct SweepLaneParams {
    double trackSpacingM = 0.0;
    double photoSpacingM = 0.0;
    // The grown margin: how far a zone lies beyond the free space's edge.
    double grownMarginM = 0.0;
    // Lanes may be flown beyond the area's edge (never into a margin) up to their strip's end.
    bool flyOutsideArea = true;
    double marginRunCapM = 0.0; // > 0
    // How far a photo sees along the lane beyond itself: half the real footprint along the track.
    double reachAlongM = 0.0;
    // How far into a neighbour lane's strip the real footprint reaches ((real across - spacing) / 2):
    // that part of a half band is the neighbour's, not a wedge of this lane.
    double neighbourReachM = 0.0;
    // Lanes on shared lines: given (frame y, increasing, at most trackSpacingM apart over the free
    // space's height), a cell's lanes lie on these lines, with a lane of its own only where no line
    // meets the cell's bottom or top window (plan::trimCoveredLanes then shortens it to that
    // stretch), so that the lanes of cells side by side continue one another as a Survey's
    // transects do round a zone; the wedges the lines leave beside a zone's edge inside a cell go
    // to spot photos. Empty: each cell spaces its lanes on its own (fewest lanes for the cell,
    // neighbours' lines not aligned, a lane in every window). See latticeLines and
    // placeSharedLines.
    std::vector<double> sharedLines;
};

// One lane of a cell, left to right in the sweep frame (world coordinates).
struct CellLane {
    geo::Vec2 stripA{0, 0}, stripB{0, 0}; // the strip's admissible ground, along the lane's line
    geo::Vec2 flyA{0, 0}, flyB{0, 0};     // what may be flown of it
    LaneSpan span;                        // first and last photo (left to right) and their count
    double y = 0.0;                       // height in the sweep frame
    int part = 0;                         // the decomposition cell it lies in
    // How far the cell's ground runs on beyond each fly end (frame x) in the lower and upper half of
    // the lane's strip (less what the neighbour lanes' real footprints see): ground that only a flight
    // along the boundary there can photograph, as the connection to the neighbour lane on that side is.
    double wedgeLeftBelow = 0.0, wedgeLeftAbove = 0.0, wedgeRightBelow = 0.0, wedgeRightAbove = 0.0;
};

// Heights of the lanes of a merged cell (frame y, increasing): lanes `trackSpacingM` apart at most,
// the outer ones covering the cell's bottom and top (and the margin ground beyond a flat contact), and
// at every cut between its parts a lane whose strip covers the wider part's ground up to the cut.
// coverFrom / coverTo, when given, replace the cell's bottom and top as the heights its lanes' strips
// must reach (a neighbour's lane covers the rest); with nothing left to cover the cell gets no lanes.
// `fixed` heights must stay lanes (others lean on them).
std::vector<double> laneHeights(const Decomposition& d, const MergedCell& m, const SweepLaneParams& p,
                                const SweepGround& ground, std::optional<double> coverFrom = std::nullopt,
                                std::optional<double> coverTo = std::nullopt, const std::vector<double>& fixed = {});

// Heights of the lanes of every merged cell of a decomposition. A cell beside an obstacle, between a
// cell below that keeps a lane just under the obstacle and one above that keeps one just over it (the
// windows at their cuts), leans on those lanes where their strips reach over its own ends: it needs
// lanes only for what they leave between them, often none.
// A cell others lean on keeps its own lanes; `pinned` (when given) flags the lanes leaned on.
std::vector<std::vector<double>> allLaneHeights(const Decomposition& d, const std::vector<MergedCell>& merged,
                                                const SweepLaneParams& p, const SweepGround& ground,
                                                std::vector<std::vector<char>>* pinned = nullptr);

// The lanes at those heights: fly interval = the cell's interval at the lane's height; strip = the
// cell's extent within the lane's band (its part's share), run on through the margin ground beyond a
// lane end; beyond the area's edge, flown up to the strip's end when allowed and `safe`.
std::vector<CellLane> cellLanes(const Decomposition& d, const MergedCell& m, const std::vector<double>& heights,
                                const SweepLaneParams& p, const SweepGround& ground,
                                const std::function<bool(const geo::Vec2&, const geo::Vec2&)>& safe);

// Shared lines trackSpacingM apart through y0, over [ylo, yhi] (a Survey's transects).
std::vector<double> latticeLines(double y0, double spacingM, double ylo, double yhi);

// Shared lines placed round the zones: heights at most spacingM apart, the lowest within half a
// spacing of the free space's bottom and the highest of its top, chosen by dynamic programming over
// candidate heights (a fine grid plus just below and above every cut of the decomposition) to
// minimise the sum over the lines of lineCost(length, runs), where runs is how many cells the line
// crosses (how many lanes it becomes) and length their summed width. A zone no wider than a spacing
// with its margins then often lies between two lines (one just under it, one just over it) instead
// of cutting one, and a wider one cuts the fewest lines; extra lines are bought only where the cost
// says the saved lane ends pay for them.
std::vector<double>
placeSharedLines(const Decomposition& d, double spacingM,
                 const std::function<double(double lengthM, int runs)>& lineCost);

} // namespace pf::plan
