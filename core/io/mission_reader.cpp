// The mission file's reader: the checked JSON reader taught the mission's objects and the older
// file versions (see mission_file.h).
#include "core/io/mission_file.h"

#include "core/io/area_import.h"
#include "core/io/json_reader.h"
#include "core/io/json_util.h"
#include "core/mission/corridor.h"
#include "core/mission/planner_kinds.h"

#include <cpl_json.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace pf::io {

namespace {

using detail::kMissionFormatName;

// The mission file's own objects on top of the checked JSON reader.
class Reader : public detail::JsonReader {
public:
    explicit Reader(std::string source) : JsonReader(std::move(source)) {}

    // The aircraft's camera: required, an object.
    sensor::Camera aircraftCamera(const CPLJSONObject& parent, const std::string& path) {
        CPLJSONObject o = object(parent, path, "camera", true);
        if (failed())
            return {};
        return camera(o, join(path, "camera"));
    }

    std::string colour(const CPLJSONObject& parent, const std::string& path, const std::string& def) {
        std::string c = string(parent, path, "colour", def);
        bool ok = c.size() == 7 && c[0] == '#';
        for (std::size_t i = 1; ok && i < c.size(); ++i)
            ok = std::isxdigit(static_cast<unsigned char>(c[i])) != 0;
        if (!failed() && !ok)
            fail(join(path, "colour"), "expected a colour like \"#e6194b\" but found \"" + c + "\"");
        return c;
    }

    mission::AircraftConfig aircraft(const CPLJSONObject& o, const std::string& path) {
        mission::AircraftConfig a;
        if (!expectType(o, path, o.GetType() == CPLJSONObject::Type::Object, "an object"))
            return a;
        a.name = string(o, path, "name", "", true);
        a.model = string(o, path, "model", "custom");
        aircraftKind(o, path, a);
        a.camera = aircraftCamera(o, path);
        a.altitudeM = optionalNumber(o, path, "altitude_m");
        a.gsdCm = optionalNumber(o, path, "gsd_cm");
        if (!failed() && !a.altitudeM && !a.gsdCm)
            fail(path, "needs altitude_m or gsd_cm (the flight altitude or the wanted ground sample distance)");
        a.overlap.front = number(o, path, "front_overlap", a.overlap.front);
        a.overlap.side = number(o, path, "side_overlap", a.overlap.side);
        a.cruiseSpeedMps = number(o, path, "cruise_speed_mps", a.cruiseSpeedMps);
        a.turnRateDegS = number(o, path, "turn_rate_deg_s", a.turnRateDegS);
        a.accelerationMps2 = number(o, path, "acceleration_mps2", a.accelerationMps2);
        a.enduranceMin = number(o, path, "endurance_min", a.enduranceMin);
        a.maxAltitudeM = number(o, path, "max_altitude_m", a.maxAltitudeM);
        a.colour = colour(o, path, a.colour);
        a.home = optionalPosition(o, path, "home");
        a.dji = detail::djiDroneType(*this, o, path);
        checkKeys(o, path,
                  {"name", "model", "kind", "camera", "altitude_m", "gsd_cm", "front_overlap",
                   "side_overlap", "cruise_speed_mps", "turn_rate_deg_s", "acceleration_mps2",
                   "endurance_min", "max_altitude_m", "plane", "colour", "home", "dji_drone_enum",
                   "dji_drone_sub_enum"});
        if (!failed() && m_version < 6 && (a.dji || a.camera.djiPayloadEnum))
            fail(path, "DJI drone and payload types (dji_drone_enum, dji_payload_enum) need "
                       "version 6 of the mission file, but the file says version " +
                           std::to_string(m_version));
        return a;
    }

    // The aircraft's kind and plane figures (version 5); a multirotor without them before.
    void aircraftKind(const CPLJSONObject& o, const std::string& path, mission::AircraftConfig& a) {
        const CPLJSONObject kind = member(o, "kind"), plane = member(o, "plane");
        if (failed() || (!kind.IsValid() && !plane.IsValid()))
            return;
        if (m_version < 5) {
            fail(join(path, kind.IsValid() ? "kind" : "plane"),
                 "the aircraft's kind and plane figures need version 5 of the mission file, but "
                 "the file says "
                 "version " +
                     std::to_string(m_version));
            return;
        }
        const std::string id = string(o, path, "kind", fleet::aircraftKindId(a.kind));
        if (auto k = fleet::aircraftKindFromId(id))
            a.kind = *k;
        else if (!failed())
            fail(join(path, "kind"),
                 "unknown kind \"" + id + "\" (expected " + fleet::aircraftKindIdList() + ")");
        if (plane.IsValid() && !failed())
            a.plane = JsonReader::plane(plane, join(path, "plane"));
    }

    mission::PlannerOptions planner(const CPLJSONObject& root) {
        mission::PlannerOptions opt;
        CPLJSONObject o = object(root, "", "planner", false);
        if (failed() || !o.IsValid())
            return opt;
        const std::string p = "planner";
        const std::string kind = string(o, p, "planner", mission::plannerKindInfo(mission::PlannerOptions{}.planner).id);
        if (auto k = mission::plannerKindFromId(kind))
            opt.planner = *k;
        else if (!failed())
            fail("planner.planner",
                 "unknown planner \"" + kind + "\" (expected " + mission::plannerKindIdList() + ")");

        CPLJSONObject angle = member(o, "grid_angle_deg");
        if (angle.IsValid()) {
            if (angle.GetType() == CPLJSONObject::Type::String) {
                if (angle.ToString() != "auto")
                    fail("planner.grid_angle_deg",
                         "expected a number of degrees or \"auto\" but found \"" + angle.ToString() + "\"");
            } else if (isNumber(angle)) {
                opt.gridAngleDeg = number(angle, "planner.grid_angle_deg");
            } else {
                fail("planner.grid_angle_deg",
                     std::string("expected a number of degrees or \"auto\" but found ") + typeName(angle));
            }
        }
        opt.safetyMarginM = number(o, p, "safety_margin_m", opt.safetyMarginM);
        opt.keepInsideArea = boolean(o, p, "keep_inside_area", opt.keepInsideArea);
        opt.insideMarginM = number(o, p, "inside_margin_m", opt.insideMarginM);
        opt.altitudeSeparationM = number(o, p, "altitude_separation_m", opt.altitudeSeparationM);
        opt.batteryReserve = number(o, p, "battery_reserve", opt.batteryReserve);
        opt.maxCells = static_cast<std::size_t>(integer(o, p, "max_cells", static_cast<long long>(opt.maxCells),
                                                        false, 1, 1'000'000'000'000LL));
        opt.doubleGrid = boolean(o, p, "double_grid", false);
        if (!failed() && opt.doubleGrid && m_version < 5)
            fail("planner.double_grid",
                 "a double grid needs version 5 of the mission file, but the file says "
                 "version " +
                     std::to_string(m_version));
        opt.cameraTiltDeg = number(o, p, "camera_tilt_deg", 0.0);
        if (!failed() && member(o, "camera_tilt_deg").IsValid() && m_version < 7)
            fail("planner.camera_tilt_deg",
                 "a camera tilt needs version 7 of the mission file, but the file says version " +
                     std::to_string(m_version));
        checkKeys(o, p,
                  {"planner", "grid_angle_deg", "safety_margin_m", "keep_inside_area",
                   "inside_margin_m", "altitude_separation_m", "battery_reserve", "max_cells",
                   "double_grid", "camera_tilt_deg"});
        return opt;
    }

    // One waypoint; `wp` reads like "routes[1] (\"Falcon 8\"): waypoint 12" (counted from 1, as the
    // waypoint table and the problem list count them).
    route::Waypoint waypoint(const CPLJSONObject& o, const std::string& wp) {
        route::Waypoint w;
        if (!expectType(o, wp, o.GetType() == CPLJSONObject::Type::Object, "an object"))
            return w;
        auto field = [&](const char* key) { return wp + ": " + key; };
        auto required = [&](const char* key) {
            CPLJSONObject v = member(o, key);
            if (!v.IsValid() && !failed())
                fail(field(key), "missing required field");
            return v;
        };
        if (CPLJSONObject pos = required("position"); pos.IsValid() && !failed())
            w.position = position(pos, field("position"));
        if (CPLJSONObject alt = required("altitude_m"); alt.IsValid() && !failed())
            w.altitudeM = number(alt, field("altitude_m"));
        if (CPLJSONObject heading = member(o, "heading_deg"); heading.IsValid() && !failed())
            w.headingDeg = number(heading, field("heading_deg"));
        if (CPLJSONObject kind = required("kind"); kind.IsValid() && !failed()) {
            if (expectType(kind, field("kind"), kind.GetType() == CPLJSONObject::Type::String, "a string")) {
                const std::string k = kind.ToString();
                if (k == "photo")
                    w.kind = route::WaypointKind::Photo;
                else if (k == "turn")
                    w.kind = route::WaypointKind::Turn;
                else if (k == "transit")
                    w.kind = route::WaypointKind::Transit;
                else
                    fail(field("kind"), "unknown kind \"" + k + "\" (expected photo, turn or transit)");
            }
        }
        if (CPLJSONObject ground = member(o, "ground_m"); ground.IsValid() && !failed())
            w.groundM = number(ground, field("ground_m"));
        checkKeys(o, wp, {"position", "altitude_m", "heading_deg", "kind", "ground_m"}, ": ");
        return w;
    }

    route::Route editedRoute(const CPLJSONObject& o, const std::string& path) {
        route::Route r;
        if (!expectType(o, path, o.GetType() == CPLJSONObject::Type::Object, "an object"))
            return r;
        r.aircraft = string(o, path, "aircraft", "", true);
        if (failed())
            return r;
        // The aircraft's name goes into every message: "routes[1]" alone is hard to find in a file.
        const std::string label = path + " (\"" + r.aircraft + "\")";
        r.home = optionalPosition(o, label, "home");
        r.cruiseSpeedMps = number(o, label, "cruise_speed_mps", r.cruiseSpeedMps);
        if (!failed() && !(r.cruiseSpeedMps > 0.0))
            fail(join(label, "cruise_speed_mps"),
                 "the cruise speed must be greater than 0 but is " + member(o, "cruise_speed_mps").ToString());
        CPLJSONObject wps = member(o, "waypoints");
        if (!wps.IsValid()) {
            fail(join(label, "waypoints"), "missing required field");
        } else if (!failed()) {
            CPLJSONArray a = array(wps, join(label, "waypoints"));
            r.waypoints.reserve(static_cast<std::size_t>(a.Size()));
            for (int i = 0; i < a.Size() && !failed(); ++i)
                r.waypoints.push_back(waypoint(a[i], label + ": waypoint " + std::to_string(i + 1)));
        }
        r.homeElevationM = optionalNumber(o, label, "home_elevation_m");
        checkKeys(o, label, {"aircraft", "home", "cruise_speed_mps", "waypoints", "home_elevation_m"});
        if (!failed() && m_version < 4 && (r.homeElevationM || std::any_of(r.waypoints.begin(), r.waypoints.end(),
                                                                          [](const auto& w) { return w.groundM.has_value(); })))
            fail(label, "heights of the ground (home_elevation_m, ground_m) need version 4 of the mission file, but "
                        "the file says version " + std::to_string(m_version));
        return r;
    }

    mission::TerrainOptions terrain(const CPLJSONObject& root) {
        mission::TerrainOptions t;
        if (failed() || !member(root, "terrain").IsValid()) // object() gives an empty object when absent
            return t;
        CPLJSONObject o = object(root, "", "terrain", false);
        if (failed())
            return t;
        const std::string p = "terrain";
        if (m_version < 4) {
            fail(p, "terrain following needs version 4 of the mission file, but the file says version " +
                        std::to_string(m_version));
            return t;
        }
        const std::string mode = string(o, p, "mode", "off");
        if (mode == "follow")
            t.mode = mission::TerrainMode::Follow;
        else if (mode != "off" && !failed())
            fail("terrain.mode", "unknown terrain mode \"" + mode + "\" (expected off or follow)");
        t.demPath = string(o, p, "dem", "");
        t.minClearanceM = number(o, p, "min_clearance_m", t.minClearanceM);
        if (!failed() && !(t.minClearanceM >= 0))
            fail("terrain.min_clearance_m", "the minimum clearance must be 0 m or more");
        t.homeElevationM = optionalNumber(o, p, "home_elevation_m");
        if (!failed() && t.follows() && t.demPath.empty())
            fail("terrain.dem", "terrain following needs a terrain model (DEM) file");
        checkKeys(o, p, {"mode", "dem", "min_clearance_m", "home_elevation_m"});
        return t;
    }

    // {"line": [[lon, lat], ...], "width_m": W}: the centre line as drawn (a line ending where it
    // started is a loop, kept so), the width checked by validation like an altitude.
    mission::Corridor corridor(const CPLJSONObject& root) {
        mission::Corridor c;
        const std::string p = "corridor";
        if (m_version < 5) {
            fail(p, "a corridor needs version 5 of the mission file, but the file says version " +
                        std::to_string(m_version));
            return c;
        }
        CPLJSONObject o = object(root, "", "corridor", true);
        if (failed())
            return c;
        CPLJSONObject line = member(o, "line");
        if (!line.IsValid()) {
            fail("corridor.line", "missing required field");
            return c;
        }
        CPLJSONArray a = array(line, "corridor.line");
        for (int i = 0; i < a.Size() && !failed(); ++i)
            c.line.push_back(position(a[i], "corridor.line[" + std::to_string(i) + "]"));
        c.widthM = number(o, p, "width_m", 0.0, true);
        checkKeys(o, p, {"line", "width_m"});
        return c;
    }

    std::vector<route::Route> editedRoutes(const CPLJSONObject& root, long long version) {
        std::vector<route::Route> out;
        CPLJSONObject routes = member(root, "routes");
        if (!routes.IsValid() || failed())
            return out;
        if (version < 2) {
            // A version 1 reader refuses the field; a file claiming version 1 with routes was not
            // written by Photoflight and would be refused by the releases it claims to suit.
            fail("routes", "hand-edited routes need version 2 of the mission file, but the file says version " +
                               std::to_string(version));
            return out;
        }
        CPLJSONArray a = array(routes, "routes");
        for (int i = 0; i < a.Size() && !failed(); ++i)
            out.push_back(editedRoute(a[i], "routes[" + std::to_string(i) + "]"));
        return out;
    }

    mission::Mission mission(const CPLJSONObject& root) {
        mission::Mission m;
        if (!expectType(root, "", root.GetType() == CPLJSONObject::Type::Object, "a JSON object"))
            return m;
        CPLJSONObject format = member(root, "format");
        if (!format.IsValid()) {
            fail("", "not a Photoflight mission file (no \"format\" field; expected \"" + std::string(kMissionFormatName) +
                         "\")");
            return m;
        }
        if (format.GetType() != CPLJSONObject::Type::String || format.ToString() != kMissionFormatName) {
            fail("format", "not a Photoflight mission file (format is " + format.Format(CPLJSONObject::PrettyFormat::Plain) +
                               ", expected \"" + kMissionFormatName + "\")");
            return m;
        }
        const long long version = integer(root, "", "version", 0, true, -1'000'000, 1'000'000);
        if (failed())
            return m;
        if (version > mission::kMissionFileVersion) {
            fail("version", "the file has version " + std::to_string(version) + ", newer than the version " +
                                std::to_string(mission::kMissionFileVersion) +
                                " this Photoflight reads; please update Photoflight");
            return m;
        }
        if (version < 1) {
            fail("version", "unknown version " + std::to_string(version) + " (expected 1 to " +
                                std::to_string(mission::kMissionFileVersion) + ")");
            return m;
        }
        m_version = version;

        m.name = string(root, "", "name", "");
        if (member(root, "corridor").IsValid()) {
            if (member(root, "area").IsValid())
                fail("area", "a corridor mission has no area of its own (its ground is the "
                             "corridor's): give \"area\" or \"corridor\", not both");
            mission::Corridor c = corridor(root);
            if (!failed())
                mission::applyCorridor(m, std::move(c));
        } else {
            m.area = polygon(root, "", "area");
        }

        CPLJSONObject zones = member(root, "no_fly_zones");
        if (zones.IsValid() && !failed()) {
            CPLJSONArray a = array(zones, "no_fly_zones");
            for (int i = 0; i < a.Size() && !failed(); ++i) {
                const std::string p = "no_fly_zones[" + std::to_string(i) + "]";
                if (!expectType(a[i], p, a[i].GetType() == CPLJSONObject::Type::Object, "an object"))
                    break;
                mission::NoFlyZone z;
                z.name = string(a[i], p, "name", "");
                z.polygon = polygon(a[i], p, "polygon");
                checkKeys(a[i], p, {"name", "polygon"});
                m.noFlyZones.push_back(std::move(z));
            }
        }
        m.home = optionalPosition(root, "", "home");
        m.landing = optionalPosition(root, "", "landing");

        CPLJSONObject aircraft = member(root, "aircraft");
        if (!aircraft.IsValid()) {
            fail("aircraft", "missing required field");
        } else if (!failed()) {
            CPLJSONArray a = array(aircraft, "aircraft");
            for (int i = 0; i < a.Size() && !failed(); ++i)
                m.aircraft.push_back(this->aircraft(a[i], "aircraft[" + std::to_string(i) + "]"));
        }
        if (!failed())
            m.options = planner(root);
        if (!failed())
            m.terrain = terrain(root);
        if (!failed())
            m.editedRoutes = editedRoutes(root, version);
        checkKeys(root, "",
                  {"format", "version", "name", "area", "corridor", "no_fly_zones", "home",
                   "landing", "aircraft", "planner", "terrain", "routes"});
        return m;
    }

private:
    long long m_version = mission::kMissionFileVersion;
};

} // namespace

Result<mission::Mission> parseMissionJson(const std::string& rawText, const std::string& sourceName) {
    initGdal();
    // Editors on Windows save UTF-8 with a byte-order mark; JSON readers must accept it (RFC 8259).
    CPLJSONDocument doc;
    if (auto st = detail::loadJsonText(doc, rawText, sourceName); !st)
        return st.error();
    Reader reader(sourceName);
    mission::Mission m = reader.mission(doc.GetRoot());
    if (reader.failed())
        return reader.error();
    return m;
}

Result<mission::Mission> readMissionFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return makeError(ErrorCode::IoError, path + ": cannot open the mission file: " + std::strerror(errno));
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad())
        return makeError(ErrorCode::IoError, path + ": cannot read the mission file: " + std::strerror(errno));
    auto m = parseMissionJson(ss.str(), path);
    // A relative DEM path names a file beside the mission file (as the mission was saved); a bare name
    // not found there is left for the terrain stage to look up among the bundled maps (the demo's).
    if (m && !m->terrain.demPath.empty()) {
        const std::filesystem::path dem(m->terrain.demPath);
        const std::filesystem::path beside = std::filesystem::path(path).parent_path() / dem;
        std::error_code ec;
        if (dem.is_relative() && std::filesystem::exists(beside, ec))
            m->terrain.demPath = beside.lexically_normal().string();
    }
    return m;
}

} // namespace pf::io
