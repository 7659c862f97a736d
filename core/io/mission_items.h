// The MAVLink mission items of one route, made in one place for the .plan and .waypoints files and
// the upload to a vehicle (so a file and an upload can never differ), and read back into a route.
#pragma once

#include "core/io/export_context.h"
#include "core/result.h"
#include "core/route/waypoint.h"

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace pf::io {

// MAVLink commands and frames used in .plan and .waypoints files and uploads.
namespace mav {
constexpr int kNavWaypoint = 16;
constexpr int kNavReturnToLaunch = 20;
constexpr int kNavLand = 21;
constexpr int kNavTakeoff = 22;
constexpr int kNavVtolTakeoff = 84;
constexpr int kNavVtolLand = 85;
constexpr int kDoLandStart = 189;
constexpr int kDoChangeSpeed = 178;
constexpr int kDoDigicamControl = 203;
constexpr int kDoMountControl = 205;
constexpr int kDoSetCamTriggDist = 206;
constexpr int kDoGimbalManagerPitchYaw = 1000;
constexpr int kImageStartCapture = 2000;
constexpr int kFenceVertexExclusion = 5002; // MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION
constexpr int kRallyPoint = 5100;           // MAV_CMD_NAV_RALLY_POINT
constexpr int kFrameGlobal = 0;             // altitude above mean sea level
constexpr int kFrameMission = 2;            // command without a position
constexpr int kFrameGlobalRelativeAlt = 3;  // altitude above home
constexpr int kFrameGlobalTerrainAlt = 10;  // altitude above the terrain under the position
} // namespace mav

// One item as the formats write it: params 5-7 are latitude, longitude and altitude for items
// with a position (frame 0, 3 or 10), zero otherwise. A NaN param means "not used" (written as null in
// a .plan).
struct MissionItem {
    int command = mav::kNavWaypoint;
    int frame = mav::kFrameGlobalRelativeAlt;
    std::array<double, 7> params{0, 0, 0, 0, 0, 0, 0};
    bool hasPosition() const { return frame != mav::kFrameMission; }
};

// A plane's take-off pitch (NAV_TAKEOFF param 1: the minimum pitch with an airspeed sensor, the pitch
// held without one; ArduPlane and PX4 fixed-wing) and its landing approach: a waypoint
// kApproachDistanceM before the landing point against the landing direction at kApproachAltitudeM
// (or the route's altitude when lower), a glide slope of 5.7 degrees, inside the 3-6 degrees the
// autopilots' landing controllers fly (ArduPlane's documentation recommends a shallow approach).
constexpr double kPlaneTakeoffPitchDeg = 15.0;
constexpr double kApproachDistanceM = 400.0;
constexpr double kApproachAltitudeM = 40.0;
// MAV_TYPE of the .plan's vehicleType: 2 quadrotor (a multirotor), 1 fixed wing, 22 VTOL with
// separate fixed rotors for hover and cruise (MAV_TYPE_VTOL_FIXEDROTOR, a quadplane such as the
// DeltaQuad; QGroundControl treats 19-25 as VTOL).
int mavVehicleType(fleet::AircraftKind kind);

// The direction a plane of route `routeIndex` lands towards (degrees from north): the user's
// (options.landingHeadingDeg: into the wind, the direction the wind blows from), else the heading of
// the route's first lane, else the nearest heading to it in 15-degree steps. A fixed-wing's approach
// (the leg from the last waypoint to the approach waypoint kApproachDistanceM out, and from there to
// the landing point) must keep every no-fly zone's safety margin: an error names the route when the
// user's heading does not, or no heading does. A VTOL descends vertically: its heading is not checked.
Result<double> planeLandingHeadingDeg(const ExportContext& ctx, std::size_t routeIndex,
                                      const ExportOptions& options = {});
// Where a plane of route `routeIndex` flies after its last waypoint, as its mission items fly it: a
// fixed-wing the approach waypoint and the landing point, a VTOL the landing point; empty for a
// multirotor (it returns home or lands as options.end says). Errors: planeLandingHeadingDeg's.
Result<std::vector<geo::LonLat>> planeLandingLeg(const ExportContext& ctx, std::size_t routeIndex,
                                                 const ExportOptions& options = {});

// The route's mission: take-off at home, speed, gimbal straight down, the waypoints (a capture
// after each photo, or with CameraTrigger::Distance only the lane ends with the trigger distance),
// and return to launch or land. Without the home item (see homeItem()). Waypoints closer than 0.1 m
// are merged first. Each waypoint is a stop or flown through as the flight-time model of the
// route's aircraft counted its corner (plan::isStopCorner on cornerAnglesDeg): a stop holds
// FlightTimeModel::stopHoldS (param 1), a corner flown through has hold 0 and the corner cut as its
// acceptance radius (param 2). The last waypoint is always a stop in practice: neither ArduCopter
// nor PX4 flies through into a return or a landing.
// A plane (fixed-wing, or VTOL in cruise) flies through every waypoint (its turns are waypoints of
// their own): NAV_TAKEOFF with kPlaneTakeoffPitchDeg for a fixed-wing, NAV_VTOL_TAKEOFF for a VTOL;
// the speed as airspeed; the camera triggered by distance on each lane whatever options.trigger says
// (a plane cannot stop for a photo); and its landing whatever options.end says: a fixed-wing
// DO_LAND_START at the landing point, the approach waypoint and NAV_LAND (towards
// planeLandingHeadingDeg); a VTOL NAV_VTOL_LAND. ArduPlane's RTL with RTL_AUTOLAND
// jumps to that DO_LAND_START. Altitudes in options.altitudeFrame (Auto: above
// sea level for a route over a terrain model); errors: above sea level without a home elevation,
// above terrain for a route not planned over a terrain model.
Result<std::vector<MissionItem>> missionItems(const ExportContext& ctx, std::size_t routeIndex,
                                              const ExportOptions& options = {});
// The home position as MAVLink item 0 of ArduPilot and Mission Planner: a waypoint in frame 0 at the
// home's elevation above sea level (homeElevation(): the route's, the options', else 0).
MissionItem homeItem(const ExportContext& ctx, std::size_t routeIndex,
                     const ExportOptions& options = {});
// Every no-fly zone as an exclusion polygon: one vertex item per corner (param 1 = the count).
std::vector<MissionItem> fenceItems(const ExportContext& ctx);
// The rally point: the home at the route's highest altitude (relative to home).
std::vector<MissionItem> rallyItems(const ExportContext& ctx, std::size_t routeIndex);
// The altitude of the rally point (and of the .plan's rally point): the route's highest waypoint.
double rallyAltitude(const route::Route& route);

// The heading change in degrees [0, 180] at each waypoint of the flight home -> waypoints ->
// landing (as the flight-time model sees it: the first waypoint's corner is between the leg from
// home and the next leg); 0 where a leg is shorter than 5 cm. The exports decide stop or
// fly-through on it.
std::vector<double> cornerAnglesDeg(const std::vector<route::Waypoint>& waypoints,
                                    const geo::LonLat& home, const geo::LonLat& landing);

// A mission read back from a file or a vehicle, items without home, altitudes relative to home:
// the waypoints, photo where a capture command follows or the camera fires by distance along
// the lanes (the photos of a distance-triggered lane are put back where the camera fires), speed
// from DO_CHANGE_SPEED. Other items (take-off, gimbal, return, land, and a plane's landing sequence
// from DO_LAND_START on) are dropped: they are made again on export. Refused: distance-triggered
// lanes that would become more than a million photo waypoints.
Result<route::Route> routeFromItems(const std::vector<MissionItem>& items);
// The kind of aircraft a mission read back was written for, from the items only a plane's mission
// holds: NAV_VTOL_TAKEOFF or NAV_VTOL_LAND a VTOL, DO_LAND_START a fixed-wing; nothing otherwise.
std::optional<fleet::AircraftKind> kindFromItems(const std::vector<MissionItem>& items);
// The camera tilt a mission read back was written for (PlannerOptions::cameraTiltDeg), from the
// pitch of its first DO_MOUNT_CONTROL or DO_GIMBAL_MANAGER_PITCHYAW: 90 + the pitch when it tilts the
// camera forward within [0, sensor::kMaxCameraTiltDeg]; nothing without such an item or another
// pitch.
std::optional<double> cameraTiltFromItems(const std::vector<MissionItem>& items);

} // namespace pf::io
