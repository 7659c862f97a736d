// The camera and aircraft catalog: reading resources/catalog.json and the user's own catalog.
#include "core/io/catalog.h"

#include "core/data_dir.h"
#include "core/io/json_reader.h"
#include "core/io/json_util.h"

#include "core/io/area_import.h"
#include "core/io/mission_file.h"

#include <cpl_json.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>

#ifndef PF_INSTALL_DATA_DIR
#define PF_INSTALL_DATA_DIR ""
#endif
#ifndef PF_SOURCE_DATA_DIR
#define PF_SOURCE_DATA_DIR ""
#endif

namespace pf::io {

namespace {

constexpr const char* kCatalogFormat = "photoflight-catalog";
constexpr int kCatalogVersion = 1;

bool sameName(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](unsigned char x, unsigned char y) {
               return std::tolower(x) == std::tolower(y);
           });
}

// The catalog's entries on top of the checked JSON reader; the first problem becomes
// "<file>: <entry>: <field>: <what>".
class CatalogReader : public detail::JsonReader {
public:
    explicit CatalogReader(std::string file) : JsonReader(std::move(file), ": ") {}

    // "cameras[3] ("Sony RX1R II")" once the name is known.
    static std::string entryLabel(const char* list, int i, const std::string& name) {
        std::string s = std::string(list) + "[" + std::to_string(i) + "]";
        return name.empty() ? s : s + " (\"" + name + "\")";
    }

    fleet::AircraftSpec aircraft(const CPLJSONObject& o, int i) {
        fleet::AircraftSpec a;
        std::string where = entryLabel("aircraft", i, "");
        if (!expectType(o, where, o.GetType() == CPLJSONObject::Type::Object, "an object"))
            return a;
        a.name = string(o, where, "name", "", true);
        where = entryLabel("aircraft", i, a.name);
        a.kind = kind(o, where);
        const bool plane = fleet::fliesAsPlane(a.kind);
        a.cruiseSpeedMps = number(o, where, "cruise_speed_mps", 0.0, true);
        // A plane's turn is its radius; its turn rate, when not given, is that of its tightest
        // turn.
        a.turnRateDegS = number(o, where, "turn_rate_deg_s", 0.0, !plane);
        a.accelerationMps2 = number(o, where, "acceleration_mps2", a.accelerationMps2);
        a.enduranceMin = number(o, where, "endurance_min", 0.0, true);
        a.maxAltitudeM = number(o, where, "max_altitude_m", 0.0, true);
        if (CPLJSONObject p = member(o, "plane"); p.IsValid() && !failed())
            a.plane = JsonReader::plane(p, where + ": plane");
        a.defaultCamera = string(o, where, "default_camera", "");
        a.notes = string(o, where, "note", "");
        checkKeys(o, where,
                  {"name", "kind", "cruise_speed_mps", "turn_rate_deg_s", "acceleration_mps2",
                   "endurance_min", "max_altitude_m", "plane", "default_camera"});
        if (failed())
            return a;
        if (a.name.empty())
            fail(where, "name: must not be empty");
        checkPlane(a.plane, where + ": plane");
        if (plane && !failed() && !member(o, "turn_rate_deg_s").IsValid() && a.cruiseSpeedMps > 0)
            a.turnRateDegS =
                a.cruiseSpeedMps / fleet::minTurnRadiusM(a.plane, a.cruiseSpeedMps) * 180.0 / M_PI;
        const std::pair<const char*, double> positive[] = {{"cruise_speed_mps", a.cruiseSpeedMps},
                                                           {"turn_rate_deg_s", a.turnRateDegS},
                                                           {"acceleration_mps2", a.accelerationMps2},
                                                           {"endurance_min", a.enduranceMin},
                                                           {"max_altitude_m", a.maxAltitudeM}};
        for (const auto& [key, v] : positive)
            if (v <= 0.0)
                fail(where, std::string(key) + ": must be greater than 0");
        return a;
    }

    fleet::AircraftKind kind(const CPLJSONObject& o, const std::string& where) {
        const std::string id =
            string(o, where, "kind", fleet::aircraftKindId(fleet::AircraftKind::Multirotor));
        const auto k = fleet::aircraftKindFromId(id);
        if (!k && !failed())
            fail(where, "kind: unknown kind \"" + id + "\" (expected " +
                            fleet::aircraftKindIdList() + ")");
        return k.value_or(fleet::AircraftKind::Multirotor);
    }

    // The plane's figures must describe a flyable aircraft (validation repeats these for missions).
    void checkPlane(const fleet::PlanePerformance& p, const std::string& where) {
        if (failed())
            return;
        if (p.minTurnRadiusM && !(*p.minTurnRadiusM > 0))
            fail(where, "turn_radius_m: must be greater than 0");
        else if (p.maxBankDeg && !(*p.maxBankDeg > 0 && *p.maxBankDeg < 90))
            fail(where, "bank_deg: must lie between 0 and 90 degrees");
        else if (!(p.climbRateMps > 0) || !(p.sinkRateMps > 0))
            fail(where, std::string(p.climbRateMps > 0 ? "sink_rate_mps" : "climb_rate_mps") +
                            ": must be greater than 0");
        else if (!(p.runInM >= 0))
            fail(where, "run_in_m: must be 0 or more");
        else if (p.stallSpeedMps && !(*p.stallSpeedMps > 0))
            fail(where, "stall_speed_mps: must be greater than 0");
    }

    Catalog catalog(const CPLJSONObject& root) {
        Catalog cat;
        if (root.GetType() != CPLJSONObject::Type::Object) {
            fail("", "expected a JSON object");
            return cat;
        }
        if (root.GetString("format") != kCatalogFormat) {
            fail("format", std::string("not a Photoflight catalog (expected \"format\": \"") + kCatalogFormat + "\")");
            return cat;
        }
        CPLJSONObject version = root.GetObj("version");
        if (!version.IsValid() || !isNumber(version) || version.ToDouble() != kCatalogVersion) {
            fail("version", "unknown catalog version " +
                                (version.IsValid() ? version.Format(CPLJSONObject::PrettyFormat::Plain) : "(missing)") +
                                " (expected " + std::to_string(kCatalogVersion) + ")");
            return cat;
        }
        for (const char* list : {"cameras", "aircraft"}) {
            CPLJSONObject o = root.GetObj(list);
            if (!o.IsValid())
                continue; // a user catalog may hold only cameras or only aircraft
            CPLJSONArray a = array(o, list);
            for (int i = 0; i < a.Size() && !failed(); ++i) {
                if (std::strcmp(list, "cameras") == 0) {
                    auto c = camera(a[i], entryLabel(list, i, ""), true);
                    if (!failed() && cat.findCamera(c.name))
                        fail(entryLabel(list, i, c.name), "a camera with this name is listed twice");
                    cat.cameras.push_back(std::move(c));
                } else {
                    auto ac = aircraft(a[i], i);
                    if (!failed() && cat.findAircraft(ac.name))
                        fail(entryLabel(list, i, ac.name), "an aircraft with this name is listed twice");
                    cat.aircraft.push_back(std::move(ac));
                }
            }
        }
        return cat;
    }
};


using detail::jsonNumber;

std::string userCatalogPath() {
    if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg && xdg[0] == '/')
        return std::string(xdg) + "/photoflight/catalog.json";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::string(home) + "/.local/share/photoflight/catalog.json";
    return "";
}

} // namespace

const sensor::Camera* Catalog::findCamera(const std::string& name) const {
    for (const auto& c : cameras)
        if (sameName(c.name, name))
            return &c;
    return nullptr;
}

const fleet::AircraftSpec* Catalog::findAircraft(const std::string& name) const {
    for (const auto& a : aircraft)
        if (sameName(a.name, name))
            return &a;
    return nullptr;
}

Result<Catalog> loadCatalog(const std::string& path) {
    initGdal();
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return makeError(ErrorCode::IoError, path + ": cannot open the catalog: " + std::strerror(errno));
    std::ostringstream ss;
    ss << in.rdbuf();
    CPLJSONDocument doc;
    if (auto st = detail::loadJsonText(doc, ss.str(), path); !st)
        return st.error();
    CatalogReader reader(path);
    Catalog cat = reader.catalog(doc.GetRoot());
    if (reader.failed())
        return reader.error();
    return cat;
}

std::string catalogToJson(const Catalog& catalog) {
    CPLJSONDocument doc;
    CPLJSONObject root = doc.GetRoot();
    root.Add("format", kCatalogFormat);
    root.Add("version", kCatalogVersion);
    CPLJSONArray cameras;
    for (const auto& c : catalog.cameras)
        cameras.Add(detail::cameraToJson(c));
    root.Add("cameras", cameras);
    CPLJSONArray aircraft;
    for (const auto& a : catalog.aircraft) {
        CPLJSONObject o;
        o.Add("name", a.name);
        if (a.kind != fleet::AircraftKind::Multirotor)
            o.Add("kind", fleet::aircraftKindId(a.kind));
        o.Add("cruise_speed_mps", jsonNumber(a.cruiseSpeedMps));
        o.Add("turn_rate_deg_s", jsonNumber(a.turnRateDegS));
        if (a.accelerationMps2 != plan::kDefaultAccelerationMps2)
            o.Add("acceleration_mps2", jsonNumber(a.accelerationMps2));
        o.Add("endurance_min", jsonNumber(a.enduranceMin));
        o.Add("max_altitude_m", jsonNumber(a.maxAltitudeM));
        if (fleet::fliesAsPlane(a.kind) || a.plane != fleet::PlanePerformance{})
            o.Add("plane", detail::planeToJson(a.plane));
        if (!a.defaultCamera.empty())
            o.Add("default_camera", a.defaultCamera);
        if (!a.notes.empty())
            o.Add("note", a.notes);
        aircraft.Add(o);
    }
    root.Add("aircraft", aircraft);
    return root.Format(CPLJSONObject::PrettyFormat::Pretty) + "\n";
}

Catalog mergeCatalogs(Catalog base, const Catalog& extra) {
    for (const auto& c : extra.cameras) {
        auto it = std::find_if(base.cameras.begin(), base.cameras.end(),
                               [&](const sensor::Camera& b) { return sameName(b.name, c.name); });
        if (it != base.cameras.end())
            *it = c;
        else
            base.cameras.push_back(c);
    }
    for (const auto& a : extra.aircraft) {
        auto it = std::find_if(base.aircraft.begin(), base.aircraft.end(),
                               [&](const fleet::AircraftSpec& b) { return sameName(b.name, a.name); });
        if (it != base.aircraft.end())
            *it = a;
        else
            base.aircraft.push_back(a);
    }
    return base;
}


Result<Catalog> loadDefaultCatalog() {
    const std::string dir = pf::dataDirectory();
    if (dir.empty()) {
        std::string searched;
        for (const auto& d : pf::dataDirectoryCandidates())
            searched += (searched.empty() ? "" : ", ") + d;
        return makeError(ErrorCode::NotFound, "the bundled catalog.json was not found (searched: " + searched +
                                                  "); set PHOTOFLIGHT_DATA_DIR to the folder holding it");
    }
    const std::string bundledPath = dir + "/catalog.json";
    auto bundled = loadCatalog(bundledPath);
    if (!bundled)
        return bundled.error();
    Catalog cat = std::move(bundled).value();

    const std::string userPath = userCatalogPath();
    std::string defaultsFrom = bundledPath;
    if (!userPath.empty() && pf::isFile(userPath)) {
        auto user = loadCatalog(userPath);
        if (!user)
            return user.error(); // a broken user catalog is reported, not silently ignored
        cat = mergeCatalogs(std::move(cat), *user);
        defaultsFrom = userPath;
    }
    // Default cameras may name a camera from either file, so they are checked after merging.
    for (const auto& a : cat.aircraft)
        if (!a.defaultCamera.empty() && !cat.findCamera(a.defaultCamera))
            return makeError(ErrorCode::NotFound, defaultsFrom + ": aircraft \"" + a.name + "\": default camera \"" +
                                                      a.defaultCamera + "\" is not in the catalog");
    return cat;
}

} // namespace pf::io
