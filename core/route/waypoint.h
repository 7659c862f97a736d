// Waypoints and per-aircraft routes: what is flown and exported.
#pragma once

#include "core/geo/types.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::route {

enum class WaypointKind : unsigned char {
    Photo,   // take a picture here
    Turn,    // a turn point without a photo
    Transit, // home -> start, end -> home, detours, sortie returns
};

struct Waypoint {
    geo::LonLat position;
    double altitudeM = 0.0;  // above the take-off point
    double headingDeg = 0.0; // yaw, clockwise from north, [0, 360)
    WaypointKind kind = WaypointKind::Photo;
    friend bool operator==(const Waypoint& a, const Waypoint& b) {
        return a.position == b.position && a.altitudeM == b.altitudeM &&
               a.headingDeg == b.headingDeg && a.kind == b.kind;
    }
};

// A waypoint in the mission's local frame, as the planning stages produce and adjust it.
struct LocalWaypoint {
    geo::Vec2 pos{0, 0};     // local metres
    double headingDeg = 0.0; // clockwise from north
    WaypointKind kind = WaypointKind::Photo;
    int cell = -1; // grid cell the waypoint photographs, -1 for none
};

// One aircraft's flight: the ordered waypoints of one sortie (take-off at home, land at home).
struct Route {
    std::string aircraft;
    std::optional<geo::LonLat> home;
    double cruiseSpeedMps = 10.0;
    std::vector<Waypoint> waypoints;
};

} // namespace pf::route
