// What the waypoint exporters need besides the routes (mission area, no-fly zones, home,
// footprints), and what the importers give back for editing.
#pragma once

#include "core/fleet/aircraft.h"
#include "core/geo/types.h"
#include "core/mission/mission.h"
#include "core/result.h"
#include "core/route/trajectory.h"
#include "core/route/waypoint.h"
#include "core/sensor/camera.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pf::io {

// Autopilot firmware a QGroundControl .plan is written for (its MAV_AUTOPILOT number).
enum class QgcFirmware { ArduPilot = 3, PX4 = 12 };
// What the vehicle does after the last waypoint.
enum class MissionEnd { ReturnToLaunch, Land };
// The MAVLink command that takes a photo at a photo waypoint.
enum class CaptureCommand {
    ImageStartCapture, // MAV_CMD_IMAGE_START_CAPTURE (2000), one image: cameras speaking the camera
                       // protocol
    DigicamControl,    // MAV_CMD_DO_DIGICAM_CONTROL (203): a camera triggered by the autopilot
};

// The MAVLink command that points the camera straight down at the start of the mission.
enum class GimbalCommand {
    MountControl,          // MAV_CMD_DO_MOUNT_CONTROL (205): pitch -90, mount mode MAVLink targeting
    GimbalManagerPitchYaw, // MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW (1000): gimbal protocol v2
    None,                  // the camera is fixed or pointed by hand
};
// How photos are taken along a lane in MAVLink missions (.plan, .waypoints, upload).
enum class CameraTrigger {
    PerPhoto, // a waypoint and a capture command for every photo
    Distance, // MAV_CMD_DO_SET_CAM_TRIGG_DIST: only the lane ends, the camera fires every d metres
};

// Which altitudes the MAVLink missions (.plan, .waypoints, upload) carry.
enum class AltitudeFrame {
    Auto,           // above sea level for a route planned over a terrain model, else relative to home
    RelativeToHome, // MAV_FRAME_GLOBAL_RELATIVE_ALT (3): above the take-off point
    AboveSeaLevel,  // MAV_FRAME_GLOBAL (0): the home's elevation plus the altitude above take-off
    AboveTerrain,   // MAV_FRAME_GLOBAL_TERRAIN_ALT (10): the height above the ground under each
                    // waypoint, the vehicle following its own terrain data between them
};

struct ExportOptions {
    QgcFirmware firmware = QgcFirmware::ArduPilot;
    MissionEnd end = MissionEnd::ReturnToLaunch;
    CaptureCommand capture = CaptureCommand::ImageStartCapture;
    GimbalCommand gimbal = GimbalCommand::MountControl;
    CameraTrigger trigger = CameraTrigger::PerPhoto;
    std::optional<double> hoverSpeedMps; // .plan hoverSpeed; the route's cruise speed when unset
    // Ground elevation of the home point above mean sea level, for the .plan's planned home and the
    // .waypoints home line (both AMSL); 0 when unknown (a connected vehicle replaces it with its own).
    std::optional<double> homeElevationM;
    AltitudeFrame altitudeFrame = AltitudeFrame::Auto;
    // The direction a plane lands towards, degrees from north (into the wind: the direction the wind
    // blows from); unset: the heading of its first lane, turned where the approach would enter a
    // no-fly margin (planeLandingHeadingDeg).
    std::optional<double> landingHeadingDeg;
    // Write a file the route's aircraft cannot fly (Litchi's CSV for a DJI Enterprise model, ...):
    // the user insisted (--force, "Export anyway").
    bool forceAircraft = false;
};

// The home's elevation above sea level for a route: its own (planned over a terrain model: the
// altitudes and the ground heights are measured from it), else the options' (given by the user);
// nothing when neither knows it.
std::optional<double> homeElevation(const route::Route& route, const ExportOptions& options);
// A waypoint's altitude above sea level (the home's elevation plus its altitude above take-off), or
// nothing without a home elevation.
std::optional<double> altitudeAmsl(const route::Route& route, const route::Waypoint& w, const ExportOptions& options);

// Everything an export can draw on. `routes[i]` is flown by the aircraft of the mission whose name
// is `routes[i].aircraft` (if any). The parallel vectors may be shorter than `routes` (missing
// entries mean "none").
struct ExportContext {
    mission::Mission mission;                                 // area, no-fly zones, home, aircraft
    std::vector<route::Route> routes;                         // one per aircraft (or per sortie)
    std::vector<std::optional<sensor::Footprint>> footprints; // photo footprint per route, for KML
    std::vector<std::vector<geo::LonLat>> trajectories; // smoothed flight path per route, for KML
    // The route's name in files where set (e.g. "Falcon 8, sortie 2 of 5"), else routeLabel's rule.
    std::vector<std::string> labels;

    // The route's home: its own, else its aircraft's, else the mission's.
    std::optional<geo::LonLat> homeFor(std::size_t routeIndex) const;
    // Where the route lands: the mission's landing point, else the home.
    std::optional<geo::LonLat> landingFor(std::size_t routeIndex) const;
    // The mission's aircraft flying the route, or nullptr.
    const mission::AircraftConfig* aircraftFor(std::size_t routeIndex) const;
    // The route's label in files: labels[i] when set, else its aircraft name, or "Route N".
    std::string routeLabel(std::size_t routeIndex) const;
    std::optional<sensor::Footprint> footprintFor(std::size_t routeIndex) const;
    // The kind of the route's aircraft (a multirotor when the route has no aircraft, e.g. imported).
    fleet::AircraftKind kindFor(std::size_t routeIndex) const;
    // The gimbal pitch the route's photos are taken at, in degrees (negative down, as MAVLink's
    // gimbal commands and DJI's WPML count it): -90 straight down, -90 + the mission's camera tilt
    // for oblique photos (PlannerOptions::cameraTiltDeg; a plane's camera always looks down).
    double gimbalPitchDeg(std::size_t routeIndex) const;
};

// A context for a planned mission: footprints from each aircraft's camera at its altitude (set
// altitude, else the one giving its GSD), where the camera allows it.
ExportContext makeExportContext(const mission::Mission& mission, std::vector<route::Route> routes);

// Fills ctx.trajectories (drawn by the KML export) with each route's smoothed flight path: a
// route::buildTrajectory in the mission's local frame, from and to the home, kept out of the no-fly
// zones grown by the mission's safety margin.
Status addTrajectories(ExportContext& ctx, const route::TrajectoryOptions& options = {});

// What a waypoint file holds, read back for editing.
struct ImportedWaypoints {
    std::vector<route::Route> routes;           // in file order, waypoints in flight order
    std::vector<mission::NoFlyZone> noFlyZones; // a .plan's exclusion polygons
    std::optional<geo::LonLat> home;            // planned home / take-off point if the file has one
    // Per route, the kind of aircraft the file was written for when it says (a .plan's vehicleType,
    // a plane's take-off and landing items); may be shorter than routes.
    std::vector<std::optional<fleet::AircraftKind>> kinds;
    // The camera tilt the file's gimbal command sets (a mission of oblique photos), when it says.
    std::optional<double> cameraTiltDeg;
};

// The camera tilt a file's gimbal pitch stands for (degrees, negative down: -90 straight down is a
// tilt of 0): 90 + pitch when that lies within [0, sensor::kMaxCameraTiltDeg], else nothing (a
// pitch this program does not write, kept out of the mission).
std::optional<double> cameraTiltFromPitch(double pitchDeg);

// A context to write imported waypoints out again (the no-fly zones, home and camera tilt are kept). A route the
// file says a plane flies gets an aircraft of that kind (named as the route, at its speed), so that
// it is written again with a plane's take-off and landing and refused by Litchi and .kmz.
ExportContext contextFromImport(const ImportedWaypoints& imported);

// The refusal of a format that cannot fly a plane (Litchi, DJI WPML: DJI multirotors only), naming
// the aircraft, its kind and the format; empty when the route's aircraft is a multirotor.
std::string planeFormatError(const ExportContext& ctx, std::size_t routeIndex, const std::string& format);

} // namespace pf::io
