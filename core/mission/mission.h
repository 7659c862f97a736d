// Mission: what the operator defines (area, no-fly zones, aircraft, options), as plain value types.
#pragma once

#include "core/fleet/aircraft.h"
#include "core/geo/types.h"
#include "core/plan/flight_time.h"
#include "core/route/waypoint.h"
#include "core/sensor/camera.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pf::mission {

struct NoFlyZone {
    std::string name;
    geo::GeoPolygon polygon;
    friend bool operator==(const NoFlyZone& a, const NoFlyZone& b) {
        return a.name == b.name && a.polygon == b.polygon;
    }
};

// A corridor survey (a road, a river, a rail line, a dike): the ground within half the width of a
// centre line, cut square at the line's ends. A mission surveys either an area or a corridor; with
// a corridor, Mission::area holds the corridor's ground (core/mission/corridor.h keeps the two
// together).
struct Corridor {
    geo::GeoRing line;   // the centre line, WGS84, an open polyline in the order drawn
    double widthM = 0.0; // the full width, > 0
    friend bool operator==(const Corridor& a, const Corridor& b) {
        return a.line == b.line && a.widthM == b.widthM;
    }
    friend bool operator!=(const Corridor& a, const Corridor& b) { return !(a == b); }
};

// One aircraft taking part in the mission, with its camera and flight settings.
struct AircraftConfig {
    std::string name;  // unique label shown to the user, e.g. "Falcon 8 #1"
    std::string model; // catalog aircraft name, or "custom"
    fleet::AircraftKind kind = fleet::AircraftKind::Multirotor;
    sensor::Camera camera;
    // Exactly one of altitude and GSD drives the other; altitude wins when both are set.
    std::optional<double> altitudeM;
    std::optional<double> gsdCm;
    sensor::Overlap overlap;
    double cruiseSpeedMps = 10.0;
    double turnRateDegS = 90.0;
    double accelerationMps2 = plan::kDefaultAccelerationMps2; // for the stop at each turn
    double enduranceMin = 20.0;
    double maxAltitudeM = 120.0;
    fleet::PlanePerformance
        plane; // turn radius, climb, run-in: used when the kind flies as a plane
    std::string colour = "#e6194b"; // #rrggbb, used on the map
    std::optional<geo::LonLat> home; // take-off and landing point; the mission's home if unset
    std::optional<fleet::DjiDroneType>
        dji; // a DJI Enterprise model's WPML drone type (from the catalog)
    friend bool operator==(const AircraftConfig& a, const AircraftConfig& b);
};

// A catalog aircraft as a mission flies it: the catalog name as label and model, its kind, speed,
// turn rate, acceleration, plane figures, endurance and ceiling, and `camera` when given (its
// default camera, looked up by the caller). The altitude is left for the caller to set.
AircraftConfig aircraftFromCatalog(const fleet::AircraftSpec& spec, const sensor::Camera* camera);

// The one flight-time model of this aircraft: its kind (a plane flies FlightDynamics::FixedWing),
// speed, turn rate and acceleration, and a plane's climb and sink rates.
plan::FlightTimeModel flightModel(const AircraftConfig& a);

// Auto: per aircraft the fastest of sweep, stride and raster (the default). Lawnmower: the yardstick
// operators know from their ground station's Survey; it ignores the no-fly zones, so it is never chosen
// by itself and its routes fail the route check wherever they cross one.
enum class PlannerKind { Auto, Sweep, Stride, Raster, Wavefront, Lawnmower };

// Names, labels and the list of kinds: core/mission/planner_kinds.h.

struct PlannerOptions {
    PlannerKind planner = PlannerKind::Auto;
    std::optional<double> gridAngleDeg; // unset: automatic search for the best angle
    double safetyMarginM = 5.0;         // keep-out distance around every no-fly zone
    bool keepInsideArea = false;        // move waypoints inside the area (plus insideMarginM)
    double insideMarginM = 0.0;
    double altitudeSeparationM = 10.0;  // between aircraft flying at the same time
    double batteryReserve = 0.2;        // fraction of endurance kept in reserve
    std::size_t maxCells = 4'000'000;   // grid cell budget
    // Double grid (for 3D models): a second pass over the area with lanes at 90 degrees to the
    // first, each pass a complete survey of its own (core/mission/double_grid.h).
    bool doubleGrid = false;
    // Oblique photos (for 3D models, with the double grid above all): every camera tilted forward by
    // this many degrees from straight down, along the direction of flight, 0 for nadir photos (at
    // most sensor::kMaxCameraTiltDeg). The footprint and overlaps are the tilted camera's
    // (sensor::footprintAt), each photo centred ahead of the aircraft; see docs/corridors.md.
    double cameraTiltDeg = 0.0;
    friend bool operator==(const PlannerOptions& a, const PlannerOptions& b);
};

// The aircraft's camera pointed as the mission points it (tilted forward by options.cameraTiltDeg):
// its sensor::footprintAt is each photo's footprint as planned and checked.
sensor::Camera pointedCamera(const AircraftConfig& a, const PlannerOptions& options);

// Terrain following (docs/terrain.md): off flies every altitude above the take-off point
// over a flat world, as always; follow keeps each aircraft's altitude (or the one of its GSD) above
// the ground under each waypoint, from a digital elevation model.
enum class TerrainMode { Off, Follow };

struct MissionTerrain; // core/mission/terrain_stage.h
constexpr double kDefaultMinClearanceM = 10.0;

struct TerrainOptions {
    TerrainMode mode = TerrainMode::Off;
    std::string demPath;       // the DEM file (a relative path in a mission file: beside the file)
    double minClearanceM = kDefaultMinClearanceM; // no point of a leg closer to the ground (at most the height above ground)
    std::optional<double> homeElevationM; // the take-off point's ground above sea level; from the DEM if unset
    // The DEM read over the area, set by the terrain stage on the mission it plans (planOverTerrain):
    // derived data, neither saved nor compared.
    std::shared_ptr<const MissionTerrain> prepared;
    bool follows() const { return mode == TerrainMode::Follow; }
    // Whether the file must say anything about terrain (a DEM chosen, following on, or a value set).
    bool isDefault() const {
        return mode == TerrainMode::Off && demPath.empty() && minClearanceM == kDefaultMinClearanceM && !homeElevationM;
    }
    friend bool operator==(const TerrainOptions& a, const TerrainOptions& b) {
        return a.mode == b.mode && a.demPath == b.demPath && a.minClearanceM == b.minClearanceM &&
               a.homeElevationM == b.homeElevationM;
    }
};

struct Mission {
    std::string name;
    geo::GeoPolygon area;
    // Set: the mission surveys this corridor with lanes along its line, and `area` is the
    // corridor's ground (mission::applyCorridor), empty while the corridor is not valid.
    std::optional<Corridor> corridor;
    std::vector<NoFlyZone> noFlyZones;
    std::optional<geo::LonLat> home;    // take-off point
    std::optional<geo::LonLat> landing; // landing point; home if unset
    std::vector<AircraftConfig> aircraft;
    PlannerOptions options;
    TerrainOptions terrain;
    // Routes the operator changed by hand, kept with the mission so that saving never loses them.
    // Planning ignores them (a new plan is computed from the definition above); the desktop
    // application shows them instead of a fresh plan until the user agrees to replace them.
    std::vector<route::Route> editedRoutes;
    friend bool operator==(const Mission& a, const Mission& b);
    friend bool operator!=(const Mission& a, const Mission& b) { return !(a == b); }
};

// Equal aircraft, home, speed and waypoints (route::Route has no operator== of its own).
bool sameRoute(const route::Route& a, const route::Route& b);

// Newest mission file format version: 2 added the optional "routes" (hand-edited routes), 3 the
// aircraft's "acceleration_mps2" and the planners "auto", "sweep" and "lawnmower", 4 "terrain"
// (terrain following) and the routes' ground heights, 5 the aircraft's "kind" (multirotor,
// fixed-wing, VTOL) and "plane" figures, a "corridor" and the double grid, 6 the DJI drone and
// payload types of DJI Enterprise aircraft ("dji_drone_enum", "dji_drone_sub_enum", the camera's
// "dji_payload_enum"), 7 the planner's "camera_tilt_deg" (oblique photos). A file is written with the oldest version that holds what it contains
// (version 1 without any of them), so that older releases keep reading it.
constexpr int kMissionFileVersion = 7;

} // namespace pf::mission
