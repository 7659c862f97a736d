#include "core/route/route_sorties.h"

#include "core/geo/geodesic.h"

#include <cmath>

namespace pf::route {

namespace {

bool atHome(const Waypoint& w, const geo::LonLat& home) {
    if (w.kind != WaypointKind::Transit)
        return false;
    // A cheap look first (a degree of latitude is over 110 km): most transit points are far away.
    if (std::abs(w.position.lat - home.lat) > 1e-4 || std::abs(w.position.lon - home.lon) > 1e-3)
        return false;
    return geo::geodesicDistance(w.position, home) <= kAtHomeM;
}

} // namespace

std::vector<SortieRange> sortieRanges(const Route& route, const std::optional<geo::LonLat>& home) {
    std::vector<SortieRange> out;
    const std::size_t n = route.waypoints.size();
    std::size_t start = 0;
    for (std::size_t i = 0; i <= n; ++i) {
        const bool cut = i == n || (home && atHome(route.waypoints[i], *home));
        if (!cut)
            continue;
        if (i > start)
            out.push_back({start, i - 1});
        start = i + 1;
    }
    return out;
}

std::vector<Route> splitSorties(const Route& route, const std::optional<geo::LonLat>& home) {
    std::vector<Route> out;
    for (const auto& s : sortieRanges(route, home)) {
        Route r(route.aircraft, route.home, route.cruiseSpeedMps, {}, route.homeElevationM);
        r.waypoints.assign(route.waypoints.begin() + static_cast<long>(s.first),
                           route.waypoints.begin() + static_cast<long>(s.last) + 1);
        out.push_back(std::move(r));
    }
    return out;
}

std::vector<int> sortieOfWaypoints(const Route& route, const std::optional<geo::LonLat>& home) {
    std::vector<int> out(route.waypoints.size(), -1);
    const auto ranges = sortieRanges(route, home);
    for (std::size_t s = 0; s < ranges.size(); ++s)
        for (std::size_t i = ranges[s].first; i <= ranges[s].last; ++i)
            out[i] = static_cast<int>(s);
    return out;
}

} // namespace pf::route
