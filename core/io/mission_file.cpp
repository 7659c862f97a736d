// Mission file writer: versioned JSON (GDAL's CPLJSON), the oldest version that holds the mission,
// written atomically. The reader is mission_reader.cpp.
#include "core/io/mission_file.h"

#include "core/io/json_util.h"
#include "core/mission/planner_kinds.h"

#include <cpl_json.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include <unistd.h>

namespace pf::io {

namespace {

using detail::jsonNumber;
using detail::kMissionFormatName;

CPLJSONArray jsonPosition(const geo::LonLat& p) {
    CPLJSONArray a;
    a.Add(jsonNumber(p.lon));
    a.Add(jsonNumber(p.lat));
    return a;
}

CPLJSONArray jsonRing(const geo::GeoRing& ring) {
    CPLJSONArray a;
    for (const auto& p : ring)
        a.Add(jsonPosition(p));
    return a;
}

CPLJSONObject jsonPolygon(const geo::GeoPolygon& poly) {
    CPLJSONObject o;
    o.Add("outer", jsonRing(poly.outer));
    CPLJSONArray holes;
    for (const auto& h : poly.holes)
        holes.Add(jsonRing(h));
    o.Add("holes", holes);
    return o;
}


const char* kindName(route::WaypointKind k) {
    switch (k) {
    case route::WaypointKind::Photo: return "photo";
    case route::WaypointKind::Turn: return "turn";
    case route::WaypointKind::Transit: return "transit";
    }
    return "photo";
}

CPLJSONObject jsonRoute(const route::Route& r) {
    CPLJSONObject o;
    o.Add("aircraft", r.aircraft);
    if (r.home)
        o.Add("home", jsonPosition(*r.home));
    o.Add("cruise_speed_mps", jsonNumber(r.cruiseSpeedMps));
    if (r.homeElevationM)
        o.Add("home_elevation_m", jsonNumber(*r.homeElevationM));
    CPLJSONArray wps;
    for (const auto& w : r.waypoints) {
        CPLJSONObject wo;
        wo.Add("position", jsonPosition(w.position));
        wo.Add("altitude_m", jsonNumber(w.altitudeM));
        wo.Add("heading_deg", jsonNumber(w.headingDeg));
        wo.Add("kind", kindName(w.kind));
        if (w.groundM)
            wo.Add("ground_m", jsonNumber(*w.groundM));
        wps.Add(wo);
    }
    o.Add("waypoints", wps);
    return o;
}

const char* plannerName(mission::PlannerKind k) { return mission::plannerKindInfo(k).id; }


// Every double of the mission must be finite, or the file could not be read back.
std::optional<std::string> firstNonFinite(const mission::Mission& m) {
    auto bad = [](double v) { return !std::isfinite(v); };
    auto ringBad = [&](const geo::GeoRing& r) {
        for (const auto& p : r)
            if (bad(p.lon) || bad(p.lat))
                return true;
        return false;
    };
    auto polyBad = [&](const geo::GeoPolygon& p) {
        if (ringBad(p.outer))
            return true;
        for (const auto& h : p.holes)
            if (ringBad(h))
                return true;
        return false;
    };
    if (polyBad(m.area))
        return std::string("area");
    if (m.corridor && (ringBad(m.corridor->line) || bad(m.corridor->widthM)))
        return std::string("corridor");
    for (std::size_t i = 0; i < m.noFlyZones.size(); ++i)
        if (polyBad(m.noFlyZones[i].polygon))
            return "no_fly_zones[" + std::to_string(i) + "].polygon";
    if (m.home && (bad(m.home->lon) || bad(m.home->lat)))
        return std::string("home");
    if (m.landing && (bad(m.landing->lon) || bad(m.landing->lat)))
        return std::string("landing");
    for (std::size_t i = 0; i < m.aircraft.size(); ++i) {
        const auto& a = m.aircraft[i];
        const std::string p = "aircraft[" + std::to_string(i) + "]";
        const auto& c = a.camera;
        const std::pair<const char*, double> fields[] = {
            {"camera.sensor_width_mm", c.sensorWidthMm}, {"camera.sensor_height_mm", c.sensorHeightMm},
            {"camera.focal_length_mm", c.focalLengthMm}, {"camera.hfov_deg", c.hfovDeg},
            {"camera.vfov_deg", c.vfovDeg},              {"altitude_m", a.altitudeM.value_or(0.0)},
            {"gsd_cm", a.gsdCm.value_or(0.0)},           {"front_overlap", a.overlap.front},
            {"side_overlap", a.overlap.side},            {"cruise_speed_mps", a.cruiseSpeedMps},
            {"turn_rate_deg_s", a.turnRateDegS},         {"acceleration_mps2", a.accelerationMps2},
            {"endurance_min", a.enduranceMin},
            {"max_altitude_m", a.maxAltitudeM},          {"home[0]", a.home ? a.home->lon : 0.0},
            {"home[1]", a.home ? a.home->lat : 0.0}};
        for (const auto& [name, v] : fields)
            if (bad(v))
                return p + "." + name;
        const auto& pl = a.plane;
        const std::pair<const char*, double> plane[] = {
            {"plane.turn_radius_m", pl.minTurnRadiusM.value_or(0.0)},
            {"plane.bank_deg", pl.maxBankDeg.value_or(0.0)},
            {"plane.climb_rate_mps", pl.climbRateMps},
            {"plane.sink_rate_mps", pl.sinkRateMps},
            {"plane.run_in_m", pl.runInM},
            {"plane.stall_speed_mps", pl.stallSpeedMps.value_or(0.0)}};
        for (const auto& [name, v] : plane)
            if (bad(v))
                return p + "." + name;
    }
    const auto& o = m.options;
    const std::pair<const char*, double> opts[] = {{"grid_angle_deg", o.gridAngleDeg.value_or(0.0)},
                                                   {"safety_margin_m", o.safetyMarginM},
                                                   {"inside_margin_m", o.insideMarginM},
                                                   {"altitude_separation_m", o.altitudeSeparationM},
                                                   {"battery_reserve", o.batteryReserve}};
    for (const auto& [name, v] : opts)
        if (bad(v))
            return std::string("planner.") + name;
    if (bad(m.terrain.minClearanceM))
        return std::string("terrain.min_clearance_m");
    if (m.terrain.homeElevationM && bad(*m.terrain.homeElevationM))
        return std::string("terrain.home_elevation_m");
    return std::nullopt;
}

// What the reader would refuse in the edited routes, as "<where> <what>"; a file that cannot be read
// back must never replace a good one.
std::optional<std::string> firstUnreadableRoute(const mission::Mission& m) {
    auto badPos = [](const geo::LonLat& p) {
        return !std::isfinite(p.lon) || !std::isfinite(p.lat) || std::abs(p.lon) > 180.0 || std::abs(p.lat) > 90.0;
    };
    for (std::size_t i = 0; i < m.editedRoutes.size(); ++i) {
        const auto& r = m.editedRoutes[i];
        const std::string label = "routes[" + std::to_string(i) + "] (\"" + r.aircraft + "\")";
        if (r.home && badPos(*r.home))
            return label + ": the home is not a valid longitude/latitude";
        if (!std::isfinite(r.cruiseSpeedMps) || !(r.cruiseSpeedMps > 0.0))
            return label + ": the cruise speed is not a number greater than 0";
        if (r.homeElevationM && !std::isfinite(*r.homeElevationM))
            return label + ": the home elevation is not a finite number";
        for (std::size_t k = 0; k < r.waypoints.size(); ++k) {
            const auto& w = r.waypoints[k];
            const std::string wp = label + ": waypoint " + std::to_string(k + 1);
            if (badPos(w.position))
                return wp + ": the position is not a valid longitude/latitude";
            if (!std::isfinite(w.altitudeM))
                return wp + ": the altitude is not a finite number";
            if (!std::isfinite(w.headingDeg))
                return wp + ": the heading is not a finite number";
            if (w.groundM && !std::isfinite(*w.groundM))
                return wp + ": the ground height is not a finite number";
        }
    }
    return std::nullopt;
}

// Whether an aircraft needs its "kind" and "plane" (version 5): a plane, or a multirotor keeping
// plane figures the user set before changing its kind (so that the file gives back exactly what it
// saved).
bool writesPlane(const mission::AircraftConfig& a) {
    return a.kind != fleet::AircraftKind::Multirotor || a.plane != fleet::PlanePerformance{};
}

// The oldest file version that holds everything in `m`, so that older releases (which refuse
// unknown fields) keep opening files that use nothing newer.
// Each feature raises the version to the one that introduced it; the file gets the highest.
int requiredVersion(const mission::Mission& m) {
    int v = m.editedRoutes.empty() ? 1 : 2;
    for (const auto& a : m.aircraft)
        if (a.accelerationMps2 != plan::kDefaultAccelerationMps2)
            v = std::max(v, 3);
    // Older releases know only the three grid planners.
    const auto k = m.options.planner;
    if (k == mission::PlannerKind::Auto || k == mission::PlannerKind::Sweep || k == mission::PlannerKind::Lawnmower)
        v = std::max(v, 3);
    if (!m.terrain.isDefault())
        v = std::max(v, 4);
    for (const auto& a : m.aircraft) {
        if (writesPlane(a))
            v = std::max(v, 5);
        if (a.dji || a.camera.djiPayloadEnum)
            v = std::max(v, 6);
    }
    if (m.corridor || m.options.doubleGrid)
        v = std::max(v, 5);
    if (m.options.cameraTiltDeg != 0.0)
        v = std::max(v, 7);
    for (const auto& r : m.editedRoutes) {
        if (r.homeElevationM)
            v = std::max(v, 4);
        for (const auto& w : r.waypoints)
            if (w.groundM)
                v = std::max(v, 4);
    }
    return v;
}

} // namespace

std::string missionToJson(const mission::Mission& m) {
    CPLJSONDocument doc;
    CPLJSONObject root = doc.GetRoot();
    root.Add("format", kMissionFormatName);
    root.Add("version", requiredVersion(m));
    root.Add("name", m.name);
    // A corridor's ground is derived from its line and width (mission::applyCorridor): only they
    // are kept.
    if (m.corridor) {
        CPLJSONObject c;
        CPLJSONArray line;
        for (const auto& p : m.corridor->line)
            line.Add(jsonPosition(p));
        c.Add("line", line);
        c.Add("width_m", jsonNumber(m.corridor->widthM));
        root.Add("corridor", c);
    } else {
        root.Add("area", jsonPolygon(m.area));
    }
    CPLJSONArray zones;
    for (const auto& z : m.noFlyZones) {
        CPLJSONObject o;
        o.Add("name", z.name);
        o.Add("polygon", jsonPolygon(z.polygon));
        zones.Add(o);
    }
    root.Add("no_fly_zones", zones);
    if (m.home)
        root.Add("home", jsonPosition(*m.home));
    if (m.landing)
        root.Add("landing", jsonPosition(*m.landing));
    CPLJSONArray aircraft;
    for (const auto& a : m.aircraft) {
        CPLJSONObject o;
        o.Add("name", a.name);
        o.Add("model", a.model);
        if (writesPlane(a))
            o.Add("kind", fleet::aircraftKindId(a.kind));
        o.Add("camera", detail::cameraToJson(a.camera));
        if (a.altitudeM)
            o.Add("altitude_m", jsonNumber(*a.altitudeM));
        if (a.gsdCm)
            o.Add("gsd_cm", jsonNumber(*a.gsdCm));
        o.Add("front_overlap", jsonNumber(a.overlap.front));
        o.Add("side_overlap", jsonNumber(a.overlap.side));
        o.Add("cruise_speed_mps", jsonNumber(a.cruiseSpeedMps));
        o.Add("turn_rate_deg_s", jsonNumber(a.turnRateDegS));
        if (a.accelerationMps2 != plan::kDefaultAccelerationMps2)
            o.Add("acceleration_mps2", jsonNumber(a.accelerationMps2));
        o.Add("endurance_min", jsonNumber(a.enduranceMin));
        o.Add("max_altitude_m", jsonNumber(a.maxAltitudeM));
        detail::addDjiDroneType(o, a.dji);
        if (writesPlane(a))
            o.Add("plane", detail::planeToJson(a.plane));
        o.Add("colour", a.colour);
        if (a.home)
            o.Add("home", jsonPosition(*a.home));
        aircraft.Add(o);
    }
    root.Add("aircraft", aircraft);
    CPLJSONObject planner;
    planner.Add("planner", plannerName(m.options.planner));
    if (m.options.gridAngleDeg)
        planner.Add("grid_angle_deg", jsonNumber(*m.options.gridAngleDeg));
    else
        planner.Add("grid_angle_deg", "auto");
    planner.Add("safety_margin_m", jsonNumber(m.options.safetyMarginM));
    planner.Add("keep_inside_area", m.options.keepInsideArea);
    planner.Add("inside_margin_m", jsonNumber(m.options.insideMarginM));
    planner.Add("altitude_separation_m", jsonNumber(m.options.altitudeSeparationM));
    planner.Add("battery_reserve", jsonNumber(m.options.batteryReserve));
    planner.Add("max_cells", static_cast<GInt64>(m.options.maxCells));
    if (m.options.doubleGrid)
        planner.Add("double_grid", true);
    if (m.options.cameraTiltDeg != 0.0)
        planner.Add("camera_tilt_deg", jsonNumber(m.options.cameraTiltDeg));
    root.Add("planner", planner);
    if (!m.terrain.isDefault()) {
        CPLJSONObject t;
        t.Add("mode", m.terrain.follows() ? "follow" : "off");
        t.Add("dem", m.terrain.demPath);
        t.Add("min_clearance_m", jsonNumber(m.terrain.minClearanceM));
        if (m.terrain.homeElevationM)
            t.Add("home_elevation_m", jsonNumber(*m.terrain.homeElevationM));
        root.Add("terrain", t);
    }
    if (!m.editedRoutes.empty()) {
        CPLJSONArray routes;
        for (const auto& r : m.editedRoutes)
            routes.Add(jsonRoute(r));
        root.Add("routes", routes);
    }
    return root.Format(CPLJSONObject::PrettyFormat::Pretty) + "\n";
}

Status checkWritable(const mission::Mission& m, const std::string& path) {
    if (auto field = firstNonFinite(m))
        return makeError(ErrorCode::InvalidInput, path + ": not saved: " + *field + " is not a finite number");
    if (auto problem = firstUnreadableRoute(m))
        return makeError(ErrorCode::InvalidInput, path + ": not saved: " + *problem);
    return {};
}

Status writeMissionFile(const mission::Mission& m, const std::string& path) {
    if (auto s = checkWritable(m, path); !s)
        return s;
    const std::string text = missionToJson(m);

    // Write beside the target and rename over it: a crash or a full disk leaves either the old file
    // or the new one, never a truncated mix. The name is unique per process and attempt.
    static std::atomic<int> counter{0};
    const std::string tmp = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(++counter);
    std::FILE* f = std::fopen(tmp.c_str(), "wbx");
    if (!f)
        return makeError(ErrorCode::IoError, path + ": cannot save the mission: cannot create a temporary file "
                                                    "beside it (" + std::strerror(errno) + ")");
    bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    ok = std::fflush(f) == 0 && ok;
    ok = ::fsync(::fileno(f)) == 0 && ok; // the data must be on disk before the rename makes it the file
    const int writeErrno = errno;
    ok = std::fclose(f) == 0 && ok;
    if (!ok) {
        std::remove(tmp.c_str());
        return makeError(ErrorCode::IoError,
                         path + ": cannot save the mission: writing failed (" + std::strerror(writeErrno) + ")");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int e = errno;
        std::remove(tmp.c_str());
        return makeError(ErrorCode::IoError, path + ": cannot save the mission: " + std::strerror(e));
    }
    return {};
}

} // namespace pf::io
