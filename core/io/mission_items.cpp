#include "core/io/mission_items.h"

#include "core/fleet/aircraft.h"
#include "core/geo/geodesic.h"
#include "core/geo/local_frame.h"
#include "core/geo/no_fly_field.h"
#include "core/io/trigger_lanes.h"
#include "core/io/waypoint_format_util.h"
#include "core/plan/flight_time.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pf::io {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kMavlinkMinSpacingM = 0.1;

MissionItem nav(int command, double yaw, geo::LonLat at, double alt, double p1 = 0,
                int frame = mav::kFrameGlobalRelativeAlt) {
    return {command, frame, {p1, 0, 0, yaw, at.lat, at.lon, alt}};
}

// The frame a route's waypoints are written in, and each waypoint's altitude in it.
struct Altitudes {
    int frame = mav::kFrameGlobalRelativeAlt;
    double home = 0.0; // the home's elevation (above sea level)
    double of(const route::Waypoint& w) const {
        if (frame == mav::kFrameGlobal)
            return home + w.altitudeM;
        if (frame == mav::kFrameGlobalTerrainAlt)
            return home + w.altitudeM - w.groundM.value_or(home);
        return w.altitudeM;
    }
};

Result<Altitudes> altitudesFor(const ExportContext& ctx, std::size_t routeIndex, const ExportOptions& options) {
    const route::Route& r = ctx.routes[routeIndex];
    AltitudeFrame f = options.altitudeFrame;
    if (f == AltitudeFrame::Auto)
        f = r.hasTerrain() ? AltitudeFrame::AboveSeaLevel : AltitudeFrame::RelativeToHome;
    Altitudes a;
    a.home = homeElevation(r, options).value_or(0.0);
    if (f == AltitudeFrame::AboveSeaLevel) {
        if (!homeElevation(r, options))
            return makeError(ErrorCode::InvalidInput,
                             ctx.routeLabel(routeIndex) + ": altitudes above sea level need the home's elevation "
                                                          "(--home-elevation M, or plan over a terrain model)");
        a.frame = mav::kFrameGlobal;
    } else if (f == AltitudeFrame::AboveTerrain) {
        if (!r.hasTerrain())
            return makeError(ErrorCode::InvalidInput,
                             ctx.routeLabel(routeIndex) + ": altitudes above terrain need a route planned over a "
                                                          "terrain model (--dem FILE --terrain follow)");
        a.frame = mav::kFrameGlobalTerrainAlt;
    }
    return a;
}

MissionItem action(int command, std::array<double, 7> params) {
    return {command, mav::kFrameMission, params};
}

MissionItem capture(CaptureCommand c) {
    if (c == CaptureCommand::ImageStartCapture)
        return action(mav::kImageStartCapture, {0, 0, 1, 0, 0, 0, 0}); // all cameras, one image
    return action(mav::kDoDigicamControl, {0, 0, 0, 0, 1, 0, 0});     // param 5 = 1: shoot
}

// Distance triggering: param 1 the distance, param 3 = 1 takes one photo at once.
MissionItem triggerDistance(double d, bool now) {
    return action(mav::kDoSetCamTriggDist, {d, 0, now ? 1.0 : 0.0, 0, 0, 0, 0});
}

// A waypoint flown as the flight-time model counted its corner (plan::isStopCorner). A stop: param
// 1 (hold, seconds) = the model's hold. ArduCopter stops at a waypoint with a delay and flies
// through one without when the next navigation command is a waypoint (ModeAuto::set_next_wp; the
// delay is kept in whole seconds, so 1 s is the shortest that stops); PX4 pauses at a waypoint with
// a hold time and otherwise sets the next setpoint and flies through (MissionBlock). A corner flown
// through: hold 0 and param 2 (acceptance radius) the corner cut, which PX4 takes as the distance
// from the waypoint where its corner curve begins (its corner speed follows from it); ArduCopter
// ignores param 2 ("Hit Rad - not supported", its WPNAV_RADIUS applies). A plane's waypoints keep
// the autopilot's own radius (0).
MissionItem waypointItem(const route::Waypoint& w, double altitude, int frame, bool stop,
                         const plan::FlightTimeModel& model) {
    MissionItem it = nav(mav::kNavWaypoint, detail::normaliseHeading(w.headingDeg), w.position,
                         altitude, stop ? model.stopHoldS : 0.0, frame);
    it.params[1] = stop || model.fixedWing() ? 0.0 : model.cornerCutM;
    return it;
}

// The flight-time model of the route's aircraft (a default multirotor at the route's speed when the
// route has none, e.g. imported waypoints).
plan::FlightTimeModel routeModel(const ExportContext& ctx, std::size_t routeIndex) {
    if (const auto* a = ctx.aircraftFor(routeIndex))
        return mission::flightModel(*a);
    plan::FlightTimeModel m;
    m.speedMps = ctx.routes[routeIndex].cruiseSpeedMps;
    return m;
}

// The take-off of the kind (MAVLink mission protocol, MAV_CMD): a multirotor NAV_TAKEOFF to the
// altitude; a fixed-wing NAV_TAKEOFF with param 1 the pitch (ArduPlane and PX4 climb out at it to
// the altitude); a VTOL NAV_VTOL_TAKEOFF, climbing vertically and then transitioning, param 2 = 1
// (VTOL_TRANSITION_HEADING_NEXT_WAYPOINT: what PX4 does whatever param 2 says).
MissionItem takeoffItem(fleet::AircraftKind kind, double yaw, geo::LonLat home, double altitude, int frame) {
    switch (kind) {
    case fleet::AircraftKind::FixedWing:
        return nav(mav::kNavTakeoff, kNaN, home, altitude, kPlaneTakeoffPitchDeg, frame);
    case fleet::AircraftKind::Vtol: {
        MissionItem it = nav(mav::kNavVtolTakeoff, kNaN, home, altitude, 0, frame);
        it.params[1] = 1;
        return it;
    }
    case fleet::AircraftKind::Multirotor:
        break;
    }
    return nav(mav::kNavTakeoff, yaw, home, altitude, 0, frame);
}

// The heading of the route's first lane (the first photo with a photo after it), else of its last
// waypoint: a plane's default landing direction.
double firstLaneHeadingDeg(const std::vector<route::Waypoint>& wps) {
    for (std::size_t i = 0; i + 1 < wps.size(); ++i)
        if (wps[i].kind == route::WaypointKind::Photo && wps[i + 1].kind == route::WaypointKind::Photo)
            return wps[i].headingDeg;
    return wps.back().headingDeg;
}

// Whether a fixed-wing's way down towards a heading keeps every no-fly zone's safety margin: the
// leg from the last waypoint to the approach waypoint and the final approach from there to the
// landing point (the checks' threshold, as the route check measures). The zones are put in a frame
// at the landing point once; each heading tried only measures its two legs.
class ApproachCheck {
public:
    ApproachCheck(const mission::Mission& m, const geo::LonLat& last, const geo::LonLat& landing)
        : m_landing(landing) {
        auto frame = geo::LocalFrame::create(landing);
        if (m.noFlyZones.empty() || !frame)
            return; // no zone; or a landing point the frame cannot hold, refused elsewhere
        std::vector<geo::Polygon> zones;
        for (const auto& z : m.noFlyZones)
            zones.push_back(frame->toLocal(z.polygon));
        m_field.emplace(geo::NoFlyField::forCheck(std::move(zones), m.options.safetyMarginM));
        m_last = frame->toLocal(last);
        m_end = frame->toLocal(landing);
        m_frame.emplace(std::move(*frame));
    }
    bool keepsMargins(double heading) const {
        if (!m_field)
            return true;
        const geo::Vec2 a = m_frame->toLocal(geo::geodesicDirect(m_landing, heading + 180.0, kApproachDistanceM));
        return m_field->segmentIsSafe(m_last, a) && m_field->segmentIsSafe(a, m_end);
    }

private:
    geo::LonLat m_landing;
    std::optional<geo::LocalFrame> m_frame;
    std::optional<geo::NoFlyField> m_field;
    geo::Vec2 m_last{0, 0}; // the last waypoint, local
    geo::Vec2 m_end{0, 0};  // the landing point, local
};

// A plane's landing sequence. Fixed-wing: DO_LAND_START (its position, optional in the protocol,
// set to the landing point so that an autopilot choosing the nearest landing sequence finds it),
// the approach waypoint kApproachDistanceM before the landing point against the landing direction,
// and NAV_LAND at the point (param 1 abort altitude 0: the autopilot's default). VTOL: NAV_VTOL_LAND
// at the point (it flies there as a plane, transitions and descends vertically; param 3 approach
// altitude unset).
void appendPlaneLanding(std::vector<MissionItem>& items, fleet::AircraftKind kind, double heading,
                        geo::LonLat landing, double routeAltitude, int frame) {
    if (kind == fleet::AircraftKind::Vtol) {
        MissionItem it = nav(mav::kNavVtolLand, heading, landing, 0.0, 0, frame);
        it.params[2] = kNaN;
        items.push_back(it);
        return;
    }
    items.push_back({mav::kDoLandStart, mav::kFrameGlobalRelativeAlt, {0, 0, 0, 0, landing.lat, landing.lon, 0}});
    const geo::LonLat approach = geo::geodesicDirect(landing, heading + 180.0, kApproachDistanceM);
    items.push_back(nav(mav::kNavWaypoint, heading, approach, std::min(kApproachAltitudeM, routeAltitude), 0, frame));
    items.push_back(nav(mav::kNavLand, heading, landing, 0.0, 0, frame));
}

} // namespace

Result<double> planeLandingHeadingDeg(const ExportContext& ctx, std::size_t routeIndex,
                                      const ExportOptions& options) {
    const route::Route& r = ctx.routes[routeIndex];
    const double lane = firstLaneHeadingDeg(r.waypoints);
    if (ctx.kindFor(routeIndex) == fleet::AircraftKind::Vtol)
        return options.landingHeadingDeg.value_or(lane); // it descends vertically: no approach
    const geo::LonLat home = ctx.homeFor(routeIndex).value_or(r.waypoints.front().position);
    const geo::LonLat landing = ctx.landingFor(routeIndex).value_or(home);
    const ApproachCheck check(ctx.mission, r.waypoints.back().position, landing);
    const auto name = [](double h) { return std::to_string(static_cast<int>(std::lround(h))); };
    if (options.landingHeadingDeg) {
        if (check.keepsMargins(*options.landingHeadingDeg))
            return *options.landingHeadingDeg;
        return makeError(ErrorCode::InvalidInput,
                         ctx.routeLabel(routeIndex) + ": the landing approach towards " +
                             name(*options.landingHeadingDeg) + " degrees (from " +
                             name(kApproachDistanceM) +
                             " m before the landing point) comes within a no-fly zone's safety "
                             "margin: choose another landing heading or landing point");
    }
    // The first lane's heading, else the nearest heading in steps of kStep either way that keeps
    // the margins.
    constexpr double kStep = 15.0;
    for (int k = 0; k * kStep <= 180.0; ++k)
        for (double h : {lane + k * kStep, lane - k * kStep})
            if (check.keepsMargins(std::fmod(h + 360.0, 360.0)))
                return std::fmod(h + 360.0, 360.0);
    return makeError(ErrorCode::InvalidInput,
                     ctx.routeLabel(routeIndex) +
                         ": no landing approach of " + name(kApproachDistanceM) +
                         " m keeps the no-fly zones' safety margins from any direction: move the "
                         "landing point away from the zones");
}

Result<std::vector<geo::LonLat>> planeLandingLeg(const ExportContext& ctx, std::size_t routeIndex,
                                                 const ExportOptions& options) {
    const fleet::AircraftKind kind = ctx.kindFor(routeIndex);
    const route::Route& r = ctx.routes[routeIndex];
    if (!fleet::fliesAsPlane(kind) || r.waypoints.empty())
        return std::vector<geo::LonLat>{};
    const geo::LonLat landing =
        ctx.landingFor(routeIndex).value_or(ctx.homeFor(routeIndex).value_or(r.waypoints.front().position));
    if (kind == fleet::AircraftKind::Vtol)
        return std::vector<geo::LonLat>{landing};
    auto heading = planeLandingHeadingDeg(ctx, routeIndex, options);
    if (!heading)
        return heading.error();
    return std::vector<geo::LonLat>{geo::geodesicDirect(landing, *heading + 180.0, kApproachDistanceM), landing};
}

int mavVehicleType(fleet::AircraftKind kind) {
    switch (kind) {
    case fleet::AircraftKind::FixedWing:
        return 1; // MAV_TYPE_FIXED_WING
    case fleet::AircraftKind::Vtol:
        return 22; // MAV_TYPE_VTOL_FIXEDROTOR
    case fleet::AircraftKind::Multirotor:
        break;
    }
    return 2; // MAV_TYPE_QUADROTOR
}

std::vector<double> cornerAnglesDeg(const std::vector<route::Waypoint>& wps,
                                    const geo::LonLat& home, const geo::LonLat& landing) {
    // Legs shorter than this have no direction worth the name (a waypoint on the home point).
    constexpr double kNoDirectionM = 0.05;
    std::vector<double> out(wps.size(), 0.0);
    for (std::size_t i = 0; i < wps.size(); ++i) {
        const geo::LonLat& a = i == 0 ? home : wps[i - 1].position;
        const geo::LonLat& b = wps[i].position;
        const geo::LonLat& c = i + 1 < wps.size() ? wps[i + 1].position : landing;
        if (geo::geodesicDistance(a, b) < kNoDirectionM ||
            geo::geodesicDistance(b, c) < kNoDirectionM)
            continue;
        out[i] = std::abs(
            std::remainder(geo::initialBearingDeg(b, c) - geo::initialBearingDeg(a, b), 360.0));
    }
    return out;
}

namespace {} // namespace

double rallyAltitude(const route::Route& r) {
    double alt = 0;
    for (const auto& w : r.waypoints)
        alt = std::max(alt, w.altitudeM);
    return alt;
}

Result<std::vector<MissionItem>> missionItems(const ExportContext& ctx, std::size_t routeIndex,
                                              const ExportOptions& options) {
    if (routeIndex >= ctx.routes.size())
        return makeError(ErrorCode::InvalidInput,
                         "there is no route " + std::to_string(routeIndex + 1) + " to export");
    const route::Route& r = ctx.routes[routeIndex];
    if (r.waypoints.empty())
        return makeError(ErrorCode::InvalidInput,
                         ctx.routeLabel(routeIndex) + ": the route has no waypoints to export");
    const std::vector<route::Waypoint> wps = mergeCloseWaypoints(r.waypoints, kMavlinkMinSpacingM);
    const geo::LonLat home = ctx.homeFor(routeIndex).value_or(wps.front().position);
    const geo::LonLat landing = ctx.landingFor(routeIndex).value_or(home);

    auto alt = altitudesFor(ctx, routeIndex, options);
    if (!alt)
        return alt.error();
    std::vector<MissionItem> items;
    const route::Waypoint& first = wps.front();
    const fleet::AircraftKind kind = ctx.kindFor(routeIndex);
    const bool plane = fleet::fliesAsPlane(kind);
    // The climb at home goes to the first waypoint's altitude (above home, or above sea level; above
    // the terrain: the height over the first waypoint's ground, reached over home's ground).
    items.push_back(takeoffItem(kind, first.headingDeg, home, alt->of(first), alt->frame));
    // Ground speed (param 1 = 1) to the planned cruise speed, throttle unchanged (-1); a plane's as
    // airspeed (param 1 = 0), the speed its autopilot holds (ArduPlane AIRSPEED_CRUISE, PX4
    // FW_AIRSPD_TRIM).
    items.push_back(action(mav::kDoChangeSpeed, {plane ? 0.0 : 1.0, r.cruiseSpeedMps, -1, 0, 0, 0, 0}));
    // The pitch: -90 straight down, -90 + the tilt for oblique photos (MAV_CMD_DO_MOUNT_CONTROL param
    // 1 and MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW param 1, in degrees, negative down). The camera then
    // looks ahead along each lane, as the vehicle faces each waypoint's yaw (param 4).
    const double pitch = ctx.gimbalPitchDeg(routeIndex);
    if (options.gimbal == GimbalCommand::MountControl)
        // Roll 0, yaw 0 (ahead); param 7 = MAV_MOUNT_MODE_MAVLINK_TARGETING.
        items.push_back(action(mav::kDoMountControl, {pitch, 0, 0, 0, 0, 0, 2}));
    else if (options.gimbal == GimbalCommand::GimbalManagerPitchYaw)
        // Yaw 0 (ahead); rates not used; flags 0 (yaw follows the vehicle); primary gimbal.
        items.push_back(action(mav::kDoGimbalManagerPitchYaw, {pitch, 0, kNaN, kNaN, 0, 0, 0}));

    std::vector<TriggerLane> lanes;
    if (options.trigger == CameraTrigger::Distance || plane)
        lanes = findTriggerLanes(wps);
    const plan::FlightTimeModel model = routeModel(ctx, routeIndex);
    const std::vector<double> corners = cornerAnglesDeg(wps, home, landing);
    const auto waypoint = [&](std::size_t i) {
        return waypointItem(wps[i], alt->of(wps[i]), alt->frame,
                            plan::isStopCorner(corners[i], model), model);
    };
    std::size_t lane = 0;
    for (std::size_t i = 0; i < wps.size(); ++i) {
        const auto& w = wps[i];
        items.push_back(waypoint(i));
        if (lane < lanes.size() && lanes[lane].first == i) {
            // The camera fires here at once and then every spacing; at the lane's last photo the
            // trigger is switched off with one last photo. A vehicle counts the last waypoint as
            // reached within its acceptance radius, before it has flown the full spacing, so the
            // distance trigger does not fire there a second time.
            items.push_back(triggerDistance(lanes[lane].spacingM, true));
            items.push_back(waypoint(lanes[lane].last));
            items.push_back(triggerDistance(0, true));
            i = lanes[lane].last;
            ++lane;
            continue;
        }
        if (w.kind == route::WaypointKind::Photo)
            items.push_back(capture(options.capture));
    }
    if (plane) {
        auto heading = planeLandingHeadingDeg(ctx, routeIndex, options);
        if (!heading)
            return heading.error();
        appendPlaneLanding(items, kind, *heading, landing, alt->of(wps.back()), alt->frame);
    }
    else if (options.end == MissionEnd::ReturnToLaunch)
        items.push_back(action(mav::kNavReturnToLaunch, {0, 0, 0, 0, 0, 0, 0}));
    else
        items.push_back(nav(mav::kNavLand, wps.back().headingDeg, landing, 0.0));
    return items;
}

MissionItem homeItem(const ExportContext& ctx, std::size_t routeIndex, const ExportOptions& options) {
    geo::LonLat home{0, 0};
    if (auto h = ctx.homeFor(routeIndex))
        home = *h;
    else if (routeIndex < ctx.routes.size() && !ctx.routes[routeIndex].waypoints.empty())
        home = ctx.routes[routeIndex].waypoints.front().position;
    return {mav::kNavWaypoint, mav::kFrameGlobal,
            {0, 0, 0, 0, home.lat, home.lon,
             routeIndex < ctx.routes.size() ? homeElevation(ctx.routes[routeIndex], options).value_or(0.0)
                                            : options.homeElevationM.value_or(0.0)}};
}

std::vector<MissionItem> fenceItems(const ExportContext& ctx) {
    std::vector<MissionItem> items;
    for (const auto& z : ctx.mission.noFlyZones) {
        const auto n = static_cast<double>(z.polygon.outer.size());
        for (const auto& v : z.polygon.outer)
            items.push_back({mav::kFenceVertexExclusion, mav::kFrameGlobal, {n, 0, 0, 0, v.lat, v.lon, 0}});
    }
    return items;
}

std::vector<MissionItem> rallyItems(const ExportContext& ctx, std::size_t routeIndex) {
    if (routeIndex >= ctx.routes.size() || ctx.routes[routeIndex].waypoints.empty())
        return {};
    const geo::LonLat home =
        ctx.homeFor(routeIndex).value_or(ctx.routes[routeIndex].waypoints.front().position);
    return {{mav::kRallyPoint, mav::kFrameGlobalRelativeAlt,
             {0, 0, 0, 0, home.lat, home.lon, rallyAltitude(ctx.routes[routeIndex])}}};
}

namespace {

// The most waypoints a mission read back may become once its distance-triggered lanes are expanded
// into photos: ten times the largest mission an autopilot's SD card holds (a few 10,000 items),
// 64 MB of waypoints. A trigger distance of millimetres over kilometres (a damaged or hostile file)
// is refused by name instead of filling the memory.
constexpr std::size_t kMaxReadWaypoints = 1'000'000;

// Rebuilds the photos of a distance-triggered stretch: `path` are the waypoints flown with the
// trigger on (the first takes a photo at once), photos every `d` metres along them, and at the end
// one more photo when the trigger is switched off with "photo now".
Status expandTriggered(std::vector<route::Waypoint>& out, std::vector<bool>& photo,
                       const std::vector<route::Waypoint>& path, double d, bool photoAtEnd) {
    double total = 0;
    for (std::size_t k = 1; k < path.size(); ++k)
        total += geo::geodesicDistance(path[k - 1].position, path[k].position);
    if (total / d + static_cast<double>(out.size() + path.size()) > static_cast<double>(kMaxReadWaypoints))
        return makeError(ErrorCode::TooLarge,
                         "a camera trigger distance of " + detail::formatNumber(d, 6) + " m over " +
                             detail::formatNumber(total, 0) + " m of lane would make more than " +
                             std::to_string(kMaxReadWaypoints) +
                             " photo waypoints (MAV_CMD_DO_SET_CAM_TRIGG_DIST): not a survey");
    // A photo due within a quarter spacing of the end is the end photo itself.
    const double limit = photoAtEnd ? total - 0.25 * d : total + 0.01;
    constexpr double kAtWaypointM = 0.01;
    out.push_back(path.front());
    photo.push_back(true);
    double legStart = 0;
    double next = d;
    for (std::size_t k = 1; k < path.size(); ++k) {
        const auto& a = path[k - 1];
        const auto& b = path[k];
        const double len = geo::geodesicDistance(a.position, b.position);
        const double az = geo::initialBearingDeg(a.position, b.position);
        while (next < limit && next < legStart + len - kAtWaypointM) {
            const double s = next - legStart;
            route::Waypoint w = a;
            w.position = geo::geodesicDirect(a.position, az, s);
            w.altitudeM = a.altitudeM + (b.altitudeM - a.altitudeM) * s / len;
            out.push_back(w);
            photo.push_back(true);
            next += d;
        }
        legStart += len;
        const bool last = k + 1 == path.size();
        bool here = last && photoAtEnd;
        if (!here && next < limit && std::abs(next - legStart) <= kAtWaypointM) {
            here = true; // the camera fires just at this waypoint
            next += d;
        }
        out.push_back(b);
        photo.push_back(here);
    }
    return {};
}

} // namespace

std::optional<double> cameraTiltFromItems(const std::vector<MissionItem>& items) {
    const auto gimbal = std::find_if(items.begin(), items.end(), [](const MissionItem& it) {
        return it.command == mav::kDoMountControl || it.command == mav::kDoGimbalManagerPitchYaw;
    });
    if (gimbal == items.end())
        return std::nullopt;
    return cameraTiltFromPitch(gimbal->params[0]); // param 1: the pitch, negative down
}

std::optional<fleet::AircraftKind> kindFromItems(const std::vector<MissionItem>& items) {
    std::optional<fleet::AircraftKind> kind;
    for (const auto& it : items) {
        if (it.command == mav::kNavVtolTakeoff || it.command == mav::kNavVtolLand)
            return fleet::AircraftKind::Vtol;
        if (it.command == mav::kDoLandStart)
            kind = fleet::AircraftKind::FixedWing;
    }
    return kind;
}

Result<route::Route> routeFromItems(const std::vector<MissionItem>& items) {
    route::Route r;
    std::vector<route::Waypoint> wps;
    std::vector<bool> photo;
    double triggerD = 0;
    std::vector<route::Waypoint> triggered; // waypoints flown with the trigger on
    bool inLanding = false;
    for (const auto& it : items) {
        const auto& p = it.params;
        if (it.command == mav::kImageStartCapture || it.command == mav::kDoDigicamControl) {
            if (triggerD > 0 && !triggered.empty())
                continue; // the distance trigger takes the photos here
            if (!photo.empty())
                photo.back() = true;
            continue;
        }
        if (it.command == mav::kDoChangeSpeed) {
            if (std::isfinite(p[1]) && p[1] > 0)
                r.cruiseSpeedMps = p[1];
            continue;
        }
        if (it.command == mav::kDoSetCamTriggDist) {
            const double d = std::isfinite(p[0]) ? p[0] : 0;
            const bool now = p[2] == 1.0;
            if (triggerD > 0 && !triggered.empty()) {
                if (auto s = expandTriggered(wps, photo, triggered, triggerD, now); !s)
                    return s.error();
                triggered.clear();
            } else if (now && !photo.empty()) {
                photo.back() = true;
            }
            triggerD = d;
            if (d > 0 && !wps.empty()) {
                // The lane starts at the last waypoint: it moves into the triggered stretch.
                triggered.push_back(wps.back());
                wps.pop_back();
                photo.pop_back();
            }
            continue;
        }
        if (it.command == mav::kDoLandStart)
            inLanding = true; // a plane's landing sequence follows: made again on export
        if (it.command != mav::kNavWaypoint || inLanding)
            continue; // take-off, gimbal, return and land are made again on export
        route::Waypoint w;
        w.position = {p[5], p[4]};
        w.altitudeM = p[6];
        w.headingDeg = std::isfinite(p[3])
                           ? detail::normaliseHeading(p[3])
                           : (wps.empty() ? 0.0 : wps.back().headingDeg);
        if (triggerD > 0 && !triggered.empty()) {
            triggered.push_back(w);
            continue;
        }
        wps.push_back(w);
        photo.push_back(false);
    }
    if (triggerD > 0 && !triggered.empty())
        if (auto s = expandTriggered(wps, photo, triggered, triggerD, false); !s)
            return s.error();
    detail::inferNonPhotoKinds(wps, photo);
    r.waypoints = std::move(wps);
    return r;
}

} // namespace pf::io
