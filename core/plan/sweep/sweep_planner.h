// The sweep planner: lanes over the exact admissible polygon, cell by cell of a boustrophedon
// decomposition, the cells' order and entries chosen by flight time.
#pragma once

#include "core/geo/types.h"
#include "core/plan/flight_time.h"
#include "core/plan/lanes/lane.h"
#include "core/result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pf::plan {

struct SweepOptions {
    double trackSpacingM = 0.0;             // lanes this far apart (effective across-track footprint), > 0
    double photoSpacingM = 0.0;             // trigger distance (effective along-track footprint), > 0
    double realAcrossM = 0.0, realAlongM = 0.0; // the real footprint; 0: the effective one
    double safetyMarginM = 5.0;             // >= 0
    bool keepInside = false;                // transitions stay over the area (else may pass outside when
                                            // shorter, within half a track spacing of it where they can)
    FlightTimeModel time;
    std::optional<geo::Vec2> home, landing; // the flight starts / ends there (landing: home when unset)

    // Lane directions. Given: only these (degrees counter-clockwise from east). Otherwise the candidates
    // are every coarseStepDeg over [0, 180) plus the directions of the `edgeDirections` longest edges of
    // the area and as many of the zones; a quick estimate (lanes, turns, cell count) ranks them and the
    // best `plannedDirections` are planned in full (order, transitions), the fastest kept.
    std::vector<double> anglesDeg;
    double coarseStepDeg = 15.0;            // > 0
    int edgeDirections = 4;                 // >= 0
    int plannedDirections = 3;              // >= 1
    // Also plan in full the directions a Survey would fly over the region (plan::planLawnmower's
    // fastest angle, and its fastest whose photos see the area; the zones ignored), however the quick
    // estimate ranks them; only without anglesDeg.
    bool surveyDirection = true;
    bool mergeCells = true;                 // merge neighbouring cells that one pattern covers
    bool improveOrder = true;               // local search after the nearest-neighbour construction
    int maxOrderRounds = 50;                // local-search passes, >= 0
    // Also start the lane-level search from the lanes row by row across the area (as a Survey flies
    // its lines, a cut line's pieces one after the other round the zones), keeping the faster result.
    bool rowStart = true;
    // Shorten lanes to the ground only they photograph (plan::trimCoveredLanes), at the overlap set.
    bool trimLanes = true;
    // Leave out the photos inside a lane whose ground the other photos already see at the overlap set
    // (plan::thinLanePhotos); the lanes are flown as before.
    bool thinPhotos = true;
    // Photograph the patches of ground the lanes leave unseen (a corner past a lane end's photo, ground
    // between zones whose margins merge) with single photos from safe places, each flown where it adds
    // least time (plan::chooseSpotPhotos, plan::placeSpotPhotos).
    bool spotPhotos = true;
    // Also plan the best directions with their lanes on lines shared by all cells (as a Survey's
    // transects; a cell adds lanes only where the lines beside a zone leave ground), keeping the
    // faster plan.
    bool sharedLines = true;
    // With shared lines, also plan lines placed round the zones (plan::placeSharedLines: not evenly
    // spaced, so that a zone lies between two lines where it can rather than cutting one).
    bool placedLines = true;
    // Segments per quarter circle of the margin polygon the lanes end at and transitions turn around:
    // few segments, few turns (each a stop) on a transition. >= 1.
    int quadrantSegments = 2;
};

struct SweepStats {
    int directionsEstimated = 0;
    int directionsPlanned = 0;
    std::optional<double> surveyAngleDeg;   // the Survey's direction over the region whose photos see it,
                                            // when searched
    bool surveyDirectionPlanned = false;    // it was among the directions planned in full
    double angleDeg = 0.0;                  // the chosen lane direction, counter-clockwise from east, [0, 180)
    int cellsBeforeMerge = 0;               // decomposition cells (chosen direction)
    int cellsAfterMerge = 0;
    int orderRounds = 0;
    int orderMoves = 0;                     // improving local-search moves
    std::int64_t linkEvaluations = 0;       // transitions costed by the order search
    double constructedTimeS = 0.0;          // the same lanes in the construction's order, before local search
    bool rowStart = false;                  // the order kept grew from the row-by-row start
    bool sharedLines = false;               // the plan kept flies lanes on lines shared by all cells
    int unreachablePockets = 0;             // free pieces no safe path reaches
    double unreachableAreaM2 = 0.0;         // their ground the footprints from outside do not reach (estimate)
    int transitionsLeavingArea = 0;         // transitions leaving the area (keep-inside) or straying more
                                            // than half a track spacing from it: no way within existed
    int graphNodes = 0, graphEdges = 0;     // the visibility graph of the transitions
    int laneSegments = 0;                   // lanes across the cells (without the photographed turns)
    int photosLeftOut = 0;                  // interior photos other photos' footprints make redundant
    int spotPhotos = 0;                     // single photos for ground the lanes leave unseen
};

struct SweepPlan {
    std::vector<Lane> lanes;                   // flight order, each flown from photos.front() to photos.back();
                                               // besides the cells' lanes, the straight turns between two of
                                               // them that run along a boundary carry photos too (lanes of
                                               // their own, in the turn's direction)
    std::vector<std::vector<geo::Vec2>> links; // links[i]: points strictly between lane i's last photo and
                                               // lane i + 1's first photo (the safe path); size lanes.size() - 1
    std::vector<geo::Vec2> homeLink, landingLink; // the same from home to the first photo, the last to landing
    std::vector<geo::Polygon> cells;           // the merged cells of the chosen direction (world), for drawing
    std::vector<int> laneCells;                // per lane: index into cells, -1 for a photographed turn or a spot photo
    FlightTime time;                           // of the whole survey (home -> ... -> landing when given)
    SweepStats stats;
    std::vector<std::string> warnings;         // e.g. unreachable pockets (the plan is still complete elsewhere)
};

// Plans `region` (local metres, one or several polygons: an area or an aircraft's share) around the
// un-buffered no-fly zones `noFly`:
// - the free space is the region minus the zones grown by the margin (a polygon slightly larger than
//   the margin, so that lane ends and transitions keep it exactly); it is decomposed, for each candidate
//   direction, into cells that one back-and-forth pattern covers, merged where one pattern covers two;
// - each cell is swept with lanes at the track spacing, photos by plan::makeLane (trigger distance,
//   centred on the strip, photos that the strip would put in a margin moved to its edge), lane ends at
//   the exact boundary; ground in a margin is photographed from outside it;
// - the order of the cells, the corner each is entered at and its first lane's direction are chosen by
//   least flight time (plan::turnCostS and the straight legs: the one model), transitions taking the
//   shortest safe path (geo::VisibilityGraph: around the margins, over the area with keepInside);
// - free pieces no safe path reaches from home (or from the largest piece) are not entered; the plan
//   covers everything else and a warning reports their area.
// Errors: spacings not positive, a negative margin, a time model without speed or turn rate, an empty
// or invalid region, home or landing inside a margin.
Result<SweepPlan> planSweep(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                            const SweepOptions& options);

// Every point flown, in order: home, its link, the lanes' photos with the links between them, the
// landing link and the landing (home and landing only when given). With laneEndsOnly, a lane gives
// only its first and last photo (a lane is straight: the same legs, without the points along them).
std::vector<geo::Vec2> sweepFlightPath(const SweepPlan& plan, const std::optional<geo::Vec2>& home,
                                       const std::optional<geo::Vec2>& landing, bool laneEndsOnly = false);

} // namespace pf::plan
