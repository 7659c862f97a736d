#include "app/cli/mission_args.h"

#include "core/io/area_import.h"
#include "core/io/catalog.h"
#include "core/io/mission_file.h"
#include "core/mission/aircraft_naming.h"
#include "core/mission/corridor.h"
#include "core/mission/planner_kinds.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace pf::cli {

const char* const kMissionOptionsHelp = PF_CLI_MISSION_OPTIONS_HELP;

std::vector<OptionSpec> missionOptionSpecs() {
    return {{"area"},          {"nofly", true, true},
            {"camera"},        {"hfov"},
            {"vfov"},          {"altitude"},
            {"gsd"},           {"overlap"},
            {"front"},         {"side"},
            {"planner"},       {"grid-angle"},
            {"home"},          {"aircraft", true, true},
            {"safety-margin"}, {"max-cells"},
            {"dem"},           {"terrain"},
            {"min-clearance"}, {"corridor"},
            {"width"},         {"double-grid", false},
            {"camera-tilt"}};
}

namespace {

constexpr double kDefaultAltitudeM = 100.0;

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

Error flagError(const std::string& flag, const std::string& what) {
    return makeError(ErrorCode::InvalidInput, "--" + flag + ": " + what);
}

// A numeric flag checked against its range; the error names the flag.
Result<std::optional<double>> numberIn(const Args& args, const std::string& flag, double lo, bool loOpen, double hi,
                                       bool hiOpen, const std::string& range) {
    auto v = args.number(flag);
    if (!v || !*v)
        return v;
    const double x = **v;
    if ((loOpen ? x <= lo : x < lo) || (hiOpen ? x >= hi : x > hi))
        return flagError(flag, "must be " + range + " (got " + num(x) + ")");
    return v;
}

std::string stem(const std::string& path) {
    std::string s = path.substr(path.find_last_of('/') + 1);
    const auto dot = s.find_last_of('.');
    return dot == std::string::npos || dot == 0 ? s : s.substr(0, dot);
}

Result<std::vector<io::ImportedPolygon>> polygonsOf(const std::string& path, const std::string& flag) {
    auto polys = io::importPolygons(path);
    if (!polys)
        return makeError(polys.error().code, (flag.empty() ? "" : "--" + flag + ": ") + polys.error().message);
    if (polys->empty())
        return makeError(ErrorCode::InvalidInput, (flag.empty() ? "" : "--" + flag + ": ") + path + " holds no polygon");
    return polys;
}

// The area of an area file, and its no-fly zones where the file marks them: a file of several
// polygons is an area with zones when exactly one has the attribute role "area" and every other has
// role "nofly" (the files `eval --generate` writes and the sample areas).
struct AreaFile {
    geo::GeoPolygon area;
    std::vector<mission::NoFlyZone> noFly;
};

Result<AreaFile> areaFrom(const std::string& path, const std::string& flag) {
    auto polys = polygonsOf(path, flag);
    if (!polys)
        return polys.error();
    if (polys->size() == 1)
        return AreaFile{polys->front().polygon, {}};
    AreaFile out;
    std::size_t areas = 0;
    bool roles = true;
    for (auto& p : *polys) {
        if (p.role == "area") {
            ++areas;
            out.area = p.polygon;
        } else if (p.role == "nofly") {
            out.noFly.push_back({p.name, p.polygon});
        } else {
            roles = false;
        }
    }
    if (roles && areas == 1)
        return out;
    return makeError(ErrorCode::InvalidInput,
                     (flag.empty() ? "" : "--" + flag + ": ") + path + " holds " + std::to_string(polys->size()) +
                         " polygons, but the area must be a single polygon (give no-fly zones with --nofly FILE, or "
                         "mark one polygon with the attribute role \"area\" and the zones with role \"nofly\")");
}

const io::Catalog* catalogOrError(std::optional<io::Catalog>& cache, Error* err) {
    if (!cache) {
        auto c = io::loadDefaultCatalog();
        if (!c) {
            *err = c.error();
            return nullptr;
        }
        cache = std::move(c).value();
    }
    return &*cache;
}

} // namespace

bool isMissionFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return false;
    std::ostringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    const auto first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    if (first == std::string::npos || text[first] != '{')
        return false; // KML, GML, binary formats...
    if (text.find("photoflight-mission") != std::string::npos)
        return true;
    // GeoJSON always has a "type" naming a geometry or a feature; any other JSON object can only be
    // meant as a mission file, and the mission reader then says what is missing.
    const bool geoJson = text.find("\"type\"") != std::string::npos &&
                         (text.find("\"Feature") != std::string::npos || text.find("Polygon\"") != std::string::npos);
    return !geoJson;
}

namespace {

// --aircraft: the mission's aircraft replaced (each NAME[:ALT_M] from the catalog), or a default
// one when the file gave none.
Status aircraftFromFlags(const Args& args, MissionInput& in, std::optional<io::Catalog>& catalog) {
    mission::Mission& m = in.mission;
    Error err;
    const auto aircraftFlags = args.values("aircraft");
    if (!aircraftFlags.empty()) {
        const io::Catalog* cat = catalogOrError(catalog, &err);
        if (!cat)
            return makeError(err.code, "--aircraft: " + err.message);
        m.aircraft.clear();
        for (const auto& spec : aircraftFlags) {
            std::string name = spec;
            std::optional<double> alt;
            if (const auto colon = spec.find_last_of(':'); colon != std::string::npos) {
                const std::string tail = spec.substr(colon + 1);
                char* end = nullptr;
                const double v = std::strtod(tail.c_str(), &end);
                if (tail.empty() || end != tail.c_str() + tail.size() || !std::isfinite(v))
                    return flagError("aircraft", "'" + tail + "' after ':' in '" + spec + "' is not an altitude in metres");
                if (v <= 0)
                    return flagError("aircraft", "the altitude in '" + spec + "' must be greater than 0 m");
                alt = v;
                name = spec.substr(0, colon);
            }
            const fleet::AircraftSpec* s = cat->findAircraft(name);
            if (!s)
                return flagError("aircraft", "no aircraft named '" + name + "' in the catalog (see: photoflight-cli catalog)");
            mission::AircraftConfig a = mission::aircraftFromCatalog(*s, cat->findCamera(s->defaultCamera));
            a.altitudeM = alt;
            m.aircraft.push_back(std::move(a));
        }
    } else if (m.aircraft.empty()) {
        const io::Catalog* cat = catalogOrError(catalog, &err);
        if (!cat || cat->aircraft.empty()) {
            if (!args.has("hfov") && !args.has("camera"))
                return makeError(ErrorCode::InvalidInput,
                                 "no aircraft: give --aircraft NAME, or a camera with --camera NAME or --hfov/--vfov" +
                                     (cat ? std::string() : " (the catalog could not be loaded: " + err.message + ")"));
            mission::AircraftConfig a;
            a.name = "Aircraft";
            a.model = "custom";
            m.aircraft.push_back(a);
            in.notes.push_back("no aircraft given: using a custom aircraft (maximum altitude " +
                               num(a.maxAltitudeM) + " m)");
        } else {
            const auto& s = cat->aircraft.front();
            m.aircraft.push_back(mission::aircraftFromCatalog(s, cat->findCamera(s.defaultCamera)));
            in.notes.push_back("no aircraft given: using the catalog's " + s.name);
        }
    }
    return {};
}

// Aircraft given with --aircraft: unique labels when the same model flies twice, and the colours in
// their order.
void labelFlagAircraft(mission::Mission& m) {
    for (std::size_t i = 0; i < m.aircraft.size(); ++i) {
        const auto same = std::count_if(m.aircraft.begin(), m.aircraft.end(),
                                        [&](const auto& b) { return b.model == m.aircraft[i].model; });
        if (same > 1) {
            std::vector<std::string> taken;
            for (std::size_t j = 0; j < i; ++j)
                taken.push_back(m.aircraft[j].name);
            m.aircraft[i].name = mission::numberedAircraftName(m.aircraft[i].model, taken);
        }
        m.aircraft[i].colour = mission::aircraftColour(i);
    }
}

// --camera NAME or --hfov/--vfov: one camera for every aircraft.
Status cameraFromFlags(const Args& args, mission::Mission& m, std::optional<io::Catalog>& catalog) {
    Error err;
    if (auto c = args.value("camera")) {
        if (args.has("hfov") || args.has("vfov"))
            return flagError("camera", "give either --camera or --hfov/--vfov, not both");
        const io::Catalog* cat = catalogOrError(catalog, &err);
        if (!cat)
            return makeError(err.code, "--camera: " + err.message);
        const sensor::Camera* cam = cat->findCamera(*c);
        if (!cam)
            return flagError("camera", "no camera named '" + *c + "' in the catalog (see: photoflight-cli catalog)");
        for (auto& a : m.aircraft)
            a.camera = *cam;
    }
    auto hfov = numberIn(args, "hfov", 0, true, 180, true, "between 0 and 180 degrees, exclusive");
    if (!hfov)
        return hfov.error();
    auto vfov = numberIn(args, "vfov", 0, true, 180, true, "between 0 and 180 degrees, exclusive");
    if (!vfov)
        return vfov.error();
    if (hfov->has_value() != vfov->has_value())
        return flagError(hfov->has_value() ? "hfov" : "vfov", "needs --hfov and --vfov together");
    if (hfov->has_value()) {
        if (**vfov > **hfov)
            return flagError("vfov", "the field of view across the short side (" + num(**vfov) +
                                         ") must not exceed --hfov (" + num(**hfov) + ")");
        for (auto& a : m.aircraft) {
            sensor::Camera cam;
            cam.name = "custom (" + num(**hfov) + " x " + num(**vfov) + " degrees)";
            cam.hfovDeg = **hfov;
            cam.vfovDeg = **vfov;
            const bool hasImage = a.camera.imageWidthPx > 0 && a.camera.imageHeightPx > 0;
            cam.imageWidthPx = hasImage ? a.camera.imageWidthPx : 4000;
            cam.imageHeightPx = hasImage ? a.camera.imageHeightPx : 3000;
            a.camera = cam;
        }
    }
    return {};
}

// --altitude or --gsd for every aircraft that has no altitude of its own from --aircraft; the
// default altitude (with a note) for an aircraft that has neither.
Status altitudeFromFlags(const Args& args, MissionInput& in, bool ownAltitudes) {
    mission::Mission& m = in.mission;
    // No upper bound here: validation names the aircraft's maximum altitude an altitude exceeds.
    auto altitude = numberIn(args, "altitude", 0, true, HUGE_VAL, false, "greater than 0 m");
    if (!altitude)
        return altitude.error();
    auto gsd = numberIn(args, "gsd", 0, true, HUGE_VAL, false, "greater than 0 cm/px");
    if (!gsd)
        return gsd.error();
    if (altitude->has_value() && gsd->has_value())
        return flagError("gsd", "give either --altitude or --gsd, not both");
    for (std::size_t i = 0; i < m.aircraft.size(); ++i) {
        auto& a = m.aircraft[i];
        const bool ownAltitude = ownAltitudes && a.altitudeM.has_value();
        if (altitude->has_value() && !ownAltitude) {
            a.altitudeM = **altitude;
            a.gsdCm.reset();
        } else if (gsd->has_value() && !ownAltitude) {
            a.gsdCm = **gsd;
            a.altitudeM.reset();
        } else if (!a.altitudeM && !a.gsdCm) {
            a.altitudeM = std::min(kDefaultAltitudeM, a.maxAltitudeM);
            in.notes.push_back("no altitude given for " + a.name + ": using " + num(*a.altitudeM) + " m");
        }
    }
    return {};
}

// --overlap, or --front and --side apart, for every aircraft.
Status overlapFromFlags(const Args& args, mission::Mission& m) {
    const std::string overlapRange = "in [0, 1), e.g. 0.7 for 70 %";
    auto overlap = numberIn(args, "overlap", 0, false, 1, true, overlapRange);
    if (!overlap)
        return overlap.error();
    auto front = numberIn(args, "front", 0, false, 1, true, overlapRange);
    if (!front)
        return front.error();
    auto side = numberIn(args, "side", 0, false, 1, true, overlapRange);
    if (!side)
        return side.error();
    if (overlap->has_value() && (front->has_value() || side->has_value()))
        return flagError("overlap", "give either --overlap or --front/--side, not both");
    for (auto& a : m.aircraft) {
        if (overlap->has_value())
            a.overlap = {**overlap, **overlap};
        if (front->has_value())
            a.overlap.front = **front;
        if (side->has_value())
            a.overlap.side = **side;
    }
    return {};
}

// Planner options and points: --planner, --grid-angle, --double-grid, --camera-tilt, --home,
// --safety-margin, --max-cells.
Status plannerFromFlags(const Args& args, mission::Mission& m) {
    if (auto p = args.value("planner")) {
        if (auto k = mission::plannerKindFromId(*p))
            m.options.planner = *k;
        else
            return flagError("planner", "unknown planner '" + *p + "' (expected " + mission::plannerKindIdList() + ")");
    }
    if (auto a = args.value("grid-angle")) {
        if (*a == "auto") {
            m.options.gridAngleDeg.reset();
        } else {
            auto v = args.number("grid-angle");
            if (!v)
                return flagError("grid-angle", "'" + *a + "' is neither a number of degrees nor 'auto'");
            m.options.gridAngleDeg = **v;
        }
    }
    if (args.has("double-grid"))
        m.options.doubleGrid = true;
    auto tilt = numberIn(args, "camera-tilt", 0, false, sensor::kMaxCameraTiltDeg, false,
                         "between 0 (straight down) and 45 degrees forward");
    if (!tilt)
        return tilt.error();
    if (tilt->has_value())
        m.options.cameraTiltDeg = **tilt;
    if (auto h = args.value("home")) {
        auto p = parseLonLat(*h, "--home");
        if (!p)
            return p.error();
        m.home = geo::LonLat{p->first, p->second};
    }
    auto margin = numberIn(args, "safety-margin", 0, false, 1e5, false, "0 m or more");
    if (!margin)
        return margin.error();
    if (margin->has_value())
        m.options.safetyMarginM = **margin;
    auto cells = numberIn(args, "max-cells", 1, false, 2147483647.0, false, "a whole number from 1 to 2147483647");
    if (!cells)
        return cells.error();
    if (cells->has_value()) {
        if (std::floor(**cells) != **cells)
            return flagError("max-cells", "must be a whole number of cells (got " + num(**cells) + ")");
        m.options.maxCells = static_cast<std::size_t>(**cells);
    }
    return {};
}

Status terrainFromFlags(const Args& args, mission::Mission& m) {
    // 5. Terrain: a DEM alone turns following on (what a user giving one wants); --terrain off keeps
    // the flat world with the DEM known.
    if (auto d = args.value("dem")) {
        if (d->empty())
            return flagError("dem", "needs the path of a terrain model (GeoTIFF, SRTM .hgt, VRT, ...)");
        m.terrain.demPath = *d;
        if (!args.has("terrain"))
            m.terrain.mode = mission::TerrainMode::Follow;
    }
    if (auto t = args.value("terrain")) {
        if (*t == "follow")
            m.terrain.mode = mission::TerrainMode::Follow;
        else if (*t == "off")
            m.terrain.mode = mission::TerrainMode::Off;
        else
            return flagError("terrain", "expected follow or off but got '" + *t + "'");
        if (m.terrain.follows() && m.terrain.demPath.empty())
            return flagError("terrain", "follow needs a terrain model: give --dem FILE");
    }
    auto clearance = numberIn(args, "min-clearance", 0, false, 1e4, false, "0 m or more");
    if (!clearance)
        return clearance.error();
    if (clearance->has_value())
        m.terrain.minClearanceM = **clearance;
    // The export option --home-elevation is also the take-off point's ground for terrain following.
    if (args.has("home-elevation")) {
        auto e = args.number("home-elevation");
        if (e && *e && m.terrain.follows())
            m.terrain.homeElevationM = **e;
    }
    return {};
}

} // namespace

Status applyMissionFlags(const Args& args, MissionInput& in) {
    std::optional<io::Catalog> catalog;
    if (auto st = aircraftFromFlags(args, in, catalog); !st)
        return st;
    const bool aircraftGiven = args.has("aircraft");
    if (aircraftGiven)
        labelFlagAircraft(in.mission);
    if (auto st = cameraFromFlags(args, in.mission, catalog); !st)
        return st;
    if (auto st = altitudeFromFlags(args, in, aircraftGiven); !st)
        return st;
    if (auto st = overlapFromFlags(args, in.mission); !st)
        return st;
    if (auto st = plannerFromFlags(args, in.mission); !st)
        return st;
    return terrainFromFlags(args, in.mission);
}

namespace {

// --corridor FILE (its one line) and --width M: the mission becomes a survey of that corridor (a
// mission file's corridor gets a new line or width).
Status corridorFromArgs(const Args& args, MissionInput& in) {
    mission::Mission& m = in.mission;
    const auto file = args.value("corridor");
    auto width = numberIn(args, "width", 0, true, mission::kMaxCorridorWidthM, false,
                          "greater than 0 and at most " + num(mission::kMaxCorridorWidthM) + " m");
    if (!width)
        return width.error();
    if (!file && !width->has_value())
        return {};
    if (!file && !m.corridor)
        return flagError("width",
                         "is the width of a corridor: give its centre line with --corridor FILE");
    mission::Corridor c = m.corridor.value_or(mission::Corridor{});
    if (file) {
        auto lines = io::importLines(*file);
        if (!lines)
            return makeError(lines.error().code, "--corridor: " + lines.error().message);
        if (lines->size() != 1) {
            std::string names;
            for (std::size_t i = 0; i < lines->size() && i < 5; ++i)
                names += std::string(i ? ", " : "") + "'" + (*lines)[i].name + "'";
            return flagError(
                "corridor",
                *file + " holds " + std::to_string(lines->size()) + " lines (" + names +
                    (lines->size() > 5 ? ", ..." : "") +
                    "), but a corridor follows one: keep only its centre line in the file");
        }
        c.line = lines->front().line;
        if (in.source.empty()) {
            in.source = *file;
            m.name = stem(*file);
        }
    }
    if (width->has_value())
        c.widthM = **width;
    else if (!m.corridor)
        return flagError("corridor", "needs the corridor's full width: give --width M");
    mission::applyCorridor(m, std::move(c));
    return {};
}

} // namespace

Result<MissionInput> missionFromArgs(const Args& args, std::size_t positional) {
    MissionInput in;
    mission::Mission& m = in.mission;

    // 1. The file: a mission, or an area.
    if (args.positionals().size() > positional + 1)
        return makeError(ErrorCode::InvalidInput, "unexpected argument '" + args.positionals()[positional + 1] +
                                                      "' (one mission or area file only)");
    if (args.positionals().size() > positional) {
        in.source = args.positionals()[positional];
        if (isMissionFile(in.source)) {
            auto mf = io::readMissionFile(in.source);
            if (!mf)
                return mf.error();
            m = std::move(mf).value();
            in.fromMissionFile = true;
        } else {
            auto area = areaFrom(in.source, "");
            if (!area)
                return area.error();
            m.area = std::move(area->area);
            m.noFlyZones = std::move(area->noFly);
            m.name = stem(in.source);
        }
    }
    if (auto a = args.value("area")) {
        auto area = areaFrom(*a, "area");
        if (!area)
            return area.error();
        m.area = std::move(area->area);
        for (auto& z : area->noFly)
            m.noFlyZones.push_back(std::move(z));
        if (in.source.empty()) {
            in.source = *a;
            m.name = stem(*a);
        }
    }
    if (auto st = corridorFromArgs(args, in); !st)
        return st.error();
    if (in.source.empty())
        return makeError(ErrorCode::InvalidInput,
                         "no mission or area file given (nor --corridor: see --help)");
    for (const auto& f : args.values("nofly")) {
        auto polys = polygonsOf(f, "nofly");
        if (!polys)
            return polys.error();
        for (auto& p : *polys)
            m.noFlyZones.push_back({p.name, std::move(p.polygon)});
    }

    if (auto st = applyMissionFlags(args, in); !st)
        return st.error();
    // A mission file written before the catalog knew DJI drone and payload types: the DJI .kmz
    // export needs them, the catalog has them (a catalog that cannot be read changes nothing here).
    if (in.fromMissionFile)
        if (auto cat = io::loadDefaultCatalog(); cat)
            io::addDjiTypesFromCatalog(m, *cat);
    return in;
}

bool printValidationProblems(const mission::ValidationReport& report, std::vector<std::string>* printed) {
    for (const geo::Severity severity : {geo::Severity::Warning, geo::Severity::Error}) {
        for (const auto& p : report.problems) {
            if (p.severity != severity)
                continue;
            std::cerr << "photoflight-cli: " << (severity == geo::Severity::Error ? "error: " : "warning: ")
                      << p.message << '\n';
            if (printed)
                printed->push_back(p.message);
        }
    }
    return !report.hasErrors();
}

} // namespace pf::cli
