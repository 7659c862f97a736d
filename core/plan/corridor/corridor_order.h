// The order a corridor's runs are flown in: lanes back and forth along the whole corridor, or
// section by section between the no-fly zones that cut it, whichever flies soonest. Internal to the
// corridor planner.
#pragma once

#include "core/geo/types.h"
#include "core/plan/corridor/corridor_lanes.h"
#include "core/plan/flight_time.h"

#include <functional>
#include <optional>
#include <vector>

namespace pf::plan::corridor_detail {

// The points strictly between a and b of the safe way from a to b, or nullopt when there is none.
using LinkFn =
    std::function<std::optional<std::vector<geo::Vec2>>(const geo::Vec2& a, const geo::Vec2& b)>;

struct OrderInput {
    std::vector<CorridorRun> runs; // every run, in its lane's direction
    int lanes = 0;
    // Station intervals of the centre line where zones cut lanes (merged): where sections may end.
    std::vector<std::pair<double, double>> cuts;
    std::optional<geo::Vec2> home, landing;
    FlightTimeModel time;
    LinkFn link;
};

struct FlightOrder {
    std::vector<CorridorRun> runs; // flight order, each in its flight direction
    std::vector<std::vector<geo::Vec2>> links;
    std::vector<geo::Vec2> homeLink,
        landingLink; // the safe ways from home and to the landing point
    int sections = 1;
    double timeS = 0.0; // +infinity when some link has no safe way
};

// Lanes alternate direction within a section, the first starting at the side (first or last lane)
// nearer to where the flight is; sections follow one another along the line, from either end. The
// sections: none (each lane end to end), or divided in the middle of any of the cuts, chosen
// greedily (all or none first, then each cut toggled while that flies sooner).
FlightOrder chooseOrder(const OrderInput& in);

// A run flown the other way: its points reversed, headings turned round.
CorridorRun reversed(CorridorRun run);

} // namespace pf::plan::corridor_detail
