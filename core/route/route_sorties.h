// The sorties of a route as it is flown: one battery's flight each, cut where the route passes
// through home (a transit waypoint at the take-off point, where the battery is changed).
#pragma once

#include "core/geo/types.h"
#include "core/route/waypoint.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace pf::route {

// A transit waypoint this close to home is the battery change between two sorties (the planner
// puts it exactly at home; the WGS84 round trip moves it by far less).
constexpr double kAtHomeM = 0.5;

// One sortie's waypoints in the route: [first, last], both inclusive.
struct SortieRange {
    std::size_t first = 0;
    std::size_t last = 0;
    friend bool operator==(const SortieRange& a, const SortieRange& b) {
        return a.first == b.first && a.last == b.last;
    }
};

// The route's sorties in flight order. A planned route needing several batteries flies through
// home between two sorties: a Transit waypoint at `home` (within kAtHomeM), which belongs to no
// sortie. A route that never passes through home (or without a home) is one sortie; an empty
// route has none. Works on routes edited by hand or read back from a file too, as long as they
// keep the waypoint at home.
std::vector<SortieRange> sortieRanges(const Route& route, const std::optional<geo::LonLat>& home);

// Each sortie as a route of its own (everything but the waypoints copied from `route`).
std::vector<Route> splitSorties(const Route& route, const std::optional<geo::LonLat>& home);

// The sortie (0-based) each waypoint belongs to, -1 for the waypoints at home between two.
std::vector<int> sortieOfWaypoints(const Route& route, const std::optional<geo::LonLat>& home);

} // namespace pf::route
