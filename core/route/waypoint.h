// Waypoints and per-aircraft routes: what is flown and exported.
#pragma once

#include "core/geo/types.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pf::route {

enum class WaypointKind : unsigned char {
    Photo,   // take a picture here
    Turn,    // a turn point without a photo
    Transit, // home -> start, end -> home, detours, sortie returns
};

struct Waypoint {
    Waypoint() = default;
    Waypoint(geo::LonLat p, double altitude, double heading = 0.0, WaypointKind k = WaypointKind::Photo,
             std::optional<double> ground = std::nullopt)
        : position(p), altitudeM(altitude), headingDeg(heading), kind(k), groundM(ground) {}
    geo::LonLat position;
    double altitudeM = 0.0;  // above the take-off point
    double headingDeg = 0.0; // yaw, clockwise from north, [0, 360)
    WaypointKind kind = WaypointKind::Photo;
    // The ground under the waypoint above mean sea level, when the route was planned over a terrain
    // model (with Route::homeElevationM: above ground = home + altitude - ground).
    std::optional<double> groundM;
    friend bool operator==(const Waypoint& a, const Waypoint& b) {
        return a.position == b.position && a.altitudeM == b.altitudeM &&
               a.headingDeg == b.headingDeg && a.kind == b.kind && a.groundM == b.groundM;
    }
};

// A waypoint in the mission's local frame, as the planning stages produce and adjust it.
struct LocalWaypoint {
    geo::Vec2 pos{0, 0};     // local metres
    double headingDeg = 0.0; // clockwise from north
    WaypointKind kind = WaypointKind::Photo;
    int cell = -1; // grid cell the waypoint photographs, -1 for none
    int pass = 0;  // a double grid's pass: 0 the first, 1 the second at 90 degrees to it
};

// One aircraft's flight: the ordered waypoints of one sortie (take-off at home, land at home).
struct Route {
    Route() = default;
    Route(std::string name, std::optional<geo::LonLat> homePoint, double speedMps, std::vector<Waypoint> points,
          std::optional<double> homeElevation = std::nullopt)
        : aircraft(std::move(name)), home(homePoint), cruiseSpeedMps(speedMps), waypoints(std::move(points)),
          homeElevationM(homeElevation) {}
    std::string aircraft;
    std::optional<geo::LonLat> home;
    double cruiseSpeedMps = 10.0;
    std::vector<Waypoint> waypoints;
    // The take-off point's ground above mean sea level, when known (a terrain model, or given): the
    // waypoints' altitudes above take-off become altitudes above sea level.
    std::optional<double> homeElevationM;
    // Whether the route follows the terrain: a home elevation and the ground under every waypoint.
    bool hasTerrain() const {
        if (!homeElevationM || waypoints.empty())
            return false;
        for (const auto& w : waypoints)
            if (!w.groundM)
                return false;
        return true;
    }
};

} // namespace pf::route
