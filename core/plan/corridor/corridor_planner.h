// The corridor planner: lanes that follow a centre line (a road, a river, a pipeline) at the track
// spacing, flown back and forth along it, round the no-fly zones that cut it.
#pragma once

#include "core/geo/types.h"
#include "core/plan/corridor/corridor_lanes.h"
#include "core/plan/flight_time.h"
#include "core/result.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::plan {

struct CorridorOptions {
    double widthM = 0.0;        // the corridor's full width, > 0
    double trackSpacingM = 0.0; // between lanes at most (effective across-track footprint), > 0
    double photoSpacingM = 0.0; // trigger distance (effective along-track footprint), > 0
    double safetyMarginM = 5.0; // >= 0
    FlightTimeModel time;
    std::optional<geo::Vec2> home,
        landing; // the flight starts / ends there (landing: home when unset)
    // How far a corner of a lane on the outside of a bend may lie beyond the circle the corridor's
    // edge follows there; 0: a quarter of the track spacing.
    double arcToleranceM = 0.0;
};

struct CorridorStats {
    int lanes = 0;        // parallel lanes across the corridor
    int runs = 0;         // flown stretches (a lane cut by a zone gives several)
    int sections = 1;     // stretches of the corridor flown one after the other
    double lengthM = 0.0; // of the centre line
    int photos = 0;
    int droppedRuns = 0; // stretches no safe path reaches (their photos left out)
};

struct CorridorPlan {
    std::vector<CorridorRun> runs; // flight order, each flown from its first point to its last
    std::vector<std::vector<geo::Vec2>>
        links; // links[i]: points strictly between run i's last point and
               // run i + 1's first (the shortest safe path); size runs - 1
    std::vector<geo::Vec2> homeLink,
        landingLink; // the same from home to the first point, the last to landing
    FlightTime time; // of the survey (home -> ... -> landing when given)
    CorridorStats stats;
    std::vector<std::string> warnings;
};

// Plans the corridor of `line` (local metres, at least two distinct points) and options.widthM:
// - laneCount(width, track spacing) lanes (laneOffsets: evenly spread, the outer strips flush with
//   the corridor's edges), each an offsetLine of the centre line, so that every lane turns with the
//   line; their photos by lanePhotos (trigger distance along the lane, closer where the lane
//   turns);
// - a lane crossing a no-fly zone grown by the margin is cut there (laneRuns: the photos of the cut
//   stretch at its ends, from where their footprints see the margin's ground);
// - flown back and forth: at each end the aircraft turns to the next lane. With zones, the lanes
// are
//   either flown end to end (round each zone on the shortest safe path) or the corridor is flown in
//   sections between the zones, lanes back and forth in each: of the choices (which zones divide
//   it, from which end and which side it starts) the one flown soonest by the time model is kept,
//   home and landing included when given;
// - the ways from home and back are the shortest safe paths too;
// - stretches no safe path reaches are left out with a warning.
// Errors: spacings or width not positive or not finite, a negative margin, a time model without
// speed or turn rate, a line of fewer than two distinct points.
Result<CorridorPlan> planCorridor(const Polyline& line, const std::vector<geo::Polygon>& noFly,
                                  const CorridorOptions& options);

// Every point flown, in order: home, its link, the runs' points with the links between them, the
// landing link and the landing (home and landing only when given; landing: home when unset).
std::vector<geo::Vec2> corridorFlightPath(const CorridorPlan& plan,
                                          const std::optional<geo::Vec2>& home,
                                          const std::optional<geo::Vec2>& landing);

} // namespace pf::plan
