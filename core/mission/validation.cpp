#include "core/mission/validation.h"

#include "core/geo/polygon_ops.h"
#include "core/mission/aircraft_naming.h"
#include "core/mission/corridor.h"
#include "core/mission/oblique.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/simplify_input.h"

#include <cmath>
#include <cstdio>
#include <tuple>

namespace pf::mission {

std::string pocketWarning(const geo::MultiPolygon& pockets) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%d pocket(s) with %.0f m² of the area",
                  static_cast<int>(pockets.size()), geo::area(pockets));
    return std::string(buf) +
           " lie enclosed by no-fly margins that merge round them: no safe path leads in, so they are not "
           "entered; their ground is photographed from outside as far as the footprints reach (the plan's "
           "coverage check reports what stays unseen)";
}

namespace {

using geo::Problem;
using geo::Severity;

std::string num(const char* f, double v) {
    char buf[64];
    // Absurd values (1e300 m) in scientific notation rather than three hundred digits.
    std::snprintf(buf, sizeof buf, std::abs(v) >= 1e9 ? "%g" : f, v);
    return buf;
}

std::string zoneName(const NoFlyZone& z, std::size_t i) {
    return z.name.empty() ? "no-fly zone " + std::to_string(i + 1) : "no-fly zone \"" + z.name + "\"";
}

std::string aircraftName(const AircraftConfig& a, std::size_t i) {
    return aircraftLabel(a.name, "aircraft " + std::to_string(i + 1));
}

std::string count(double n) {
    std::string s = num("%.0f", n), out;
    const int len = static_cast<int>(s.size());
    for (int i = 0; i < len; ++i) {
        out += s[i];
        if ((len - i - 1) % 3 == 0 && i + 1 < len)
            out += ',';
    }
    return out;
}

void error(std::vector<Problem>& out, std::string msg) { out.push_back({Severity::Error, std::move(msg)}); }

// The area's problems; with a corridor, the corridor's, then those of its ground.
std::vector<Problem> areaProblemsOf(const Mission& m) {
    if (!m.corridor)
        return geo::validatePolygon(m.area, "the area");
    auto problems = validateCorridor(*m.corridor);
    if (!geo::hasError(problems)) {
        const auto ground = geo::validatePolygon(m.area, "the corridor's ground");
        problems.insert(problems.end(), ground.begin(), ground.end());
    }
    return problems;
}
void warning(std::vector<Problem>& out, std::string msg) { out.push_back({Severity::Warning, std::move(msg)}); }

// The altitude's own limits: a number at or above the minimum safe altitude, at most the aircraft's
// maximum, and photos at least kMinFootprintM on the ground.
std::vector<std::string> altitudeLimitErrors(const std::string& who, const AircraftConfig& a, double alt,
                                             bool fromGsd) {
    std::vector<std::string> out;
    const std::string given = fromGsd ? " (from the wanted GSD)" : "";
    if (!std::isfinite(alt) || alt <= 0) {
        out.push_back(who + ": the flight altitude must be greater than 0 m (got " + num("%g", alt) +
                      " m): the altitude is measured above the take-off point, so 0 m is on the ground; the "
                      "lowest allowed is " + num("%g", kMinSafeAltitudeM) + " m");
        return out;
    }
    if (alt < kMinSafeAltitudeM) {
        out.push_back(who + ": the flight altitude of " + num("%.1f", alt) + " m" + given +
                      " is below the minimum safe altitude of " + num("%.1f", kMinSafeAltitudeM) + " m");
        return out;
    }
    if (alt > a.maxAltitudeM) {
        out.push_back(who + ": the flight altitude of " + num("%.1f", alt) + " m is above its maximum of " +
                      num("%.1f", a.maxAltitudeM) + " m" + given);
        return out;
    }
    if (auto fp = sensor::effectiveFootprint(a.camera, alt, a.overlap); fp && fp->real.shortSideM < kMinFootprintM) {
        // The footprint grows in proportion to the altitude.
        const double needed = std::ceil(alt * kMinFootprintM / fp->real.shortSideM * 10.0) / 10.0;
        out.push_back(who + ": at " + num("%.1f", alt) + " m" + given + " a photo covers only " +
                      num("%.1f", fp->real.longSideM) + " x " + num("%.1f", fp->real.shortSideM) +
                      " m, below the smallest footprint of " + num("%g", kMinFootprintM) +
                      " m (planning and flying would take far too long): fly at " + num("%.1f", needed) +
                      " m or higher");
    }
    return out;
}

// The grid of cells of `cellSizeM` over `admissible` against the cell budget: the error says how many
// cells and which altitude and cell size would fit; empty when it fits.
std::string cellBudgetError(const std::string& who, const AircraftConfig& a, double alt, double cellSizeM,
                            const geo::MultiPolygon& admissible, double angleDeg, std::size_t maxCells,
                            grid::Grid::Size* sizeOut = nullptr) {
    const auto size = grid::Grid::sizeFor(admissible, cellSizeM, angleDeg);
    if (sizeOut)
        *sizeOut = size;
    if (size.cells() <= static_cast<double>(maxCells))
        return {};
    const double fit = grid::Grid::cellSizeToFit(admissible, cellSizeM, angleDeg, maxCells);
    // The footprint, and with it the cell, grows in proportion to the altitude.
    const double fitAlt = std::ceil(alt * fit / cellSizeM * 10.0) / 10.0;
    std::string msg = who + ": the area is too large for the cell budget: at " + num("%.1f", alt) + " m (cell size " +
                      num("%.2f", cellSizeM) + " m) its grid would need " + count(static_cast<double>(size.cols)) +
                      " x " + count(static_cast<double>(size.rows)) + " = " + count(size.cells()) +
                      " cells, more than the budget of " + count(static_cast<double>(maxCells)) +
                      "; an altitude of at least " + num("%.1f", fitAlt) + " m (cell size " + num("%.2f", fit) +
                      " m) would fit";
    if (fitAlt > a.maxAltitudeM)
        msg += ", but that is above its maximum altitude of " + num("%.1f", a.maxAltitudeM) +
               " m: raise the cell budget or split the area";
    return msg;
}

// A turn radius given for a plane that its cruise speed would need a steeper bank than this for is
// suspicious: survey planes are limited to 45-60 degrees (ArduPlane ROLL_LIMIT_DEG 45, PX4 FW_R_LIM
// 50).
constexpr double kSteepBankDeg = 60.0;

} // namespace

std::vector<std::string> planeErrors(const AircraftConfig& a, const std::string& who) {
    std::vector<std::string> out;
    if (!fleet::fliesAsPlane(a.kind))
        return out;
    const auto& p = a.plane;
    const auto positive = [&](double v, const char* what, const char* unit, const char* why) {
        if (!std::isfinite(v) || v <= 0.0)
            out.push_back(who + ": the " + what + " must be greater than 0 " + unit + " (got " +
                          num("%g", v) + " " + unit + ")" + why);
    };
    if (p.minTurnRadiusM)
        positive(*p.minTurnRadiusM, "minimum turn radius", "m",
                 ": a plane cannot turn on the spot");
    else if (p.maxBankDeg &&
             !(std::isfinite(*p.maxBankDeg) && *p.maxBankDeg > 0 && *p.maxBankDeg < 90))
        out.push_back(who + ": the bank limit must lie between 0 and 90 degrees (got " +
                      num("%g", *p.maxBankDeg) +
                      "): the turn radius follows from it, V^2 / (g tan bank)");
    positive(p.climbRateMps, "climb rate", "m/s", "");
    positive(p.sinkRateMps, "sink rate", "m/s", "");
    if (!std::isfinite(p.runInM) || p.runInM < 0)
        out.push_back(who + ": the run-in before each lane must be 0 m or more (got " +
                      num("%g", p.runInM) + " m)");
    if (p.stallSpeedMps) {
        positive(*p.stallSpeedMps, "stall speed", "m/s", "");
        const double least = fleet::kStallMargin * *p.stallSpeedMps;
        if (*p.stallSpeedMps > 0 && std::isfinite(least) && a.cruiseSpeedMps < least)
            out.push_back(who + ": the cruise speed of " + num("%.1f", a.cruiseSpeedMps) +
                          " m/s is below the stall-safe minimum of " + num("%.1f", least) +
                          " m/s (" + num("%g", fleet::kStallMargin) + " x its stall speed of " +
                          num("%.1f", *p.stallSpeedMps) + " m/s): fly faster");
    }
    return out;
}

std::string planeRoutingError(const AircraftConfig& a, PlannerKind planner,
                              const std::string& who) {
    if (!fleet::fliesAsPlane(a.kind))
        return {};
    const PlannerKindInfo& k = plannerKindInfo(planner);
    if (servesPlanes(k))
        return {};
    const std::string kind = a.kind == fleet::AircraftKind::Vtol
                                 ? "a VTOL aircraft (it flies its survey as a plane)"
                                 : "a fixed-wing aircraft";
    return who + " is " + kind + ": the " + k.id + " planner cannot plan for a plane (" +
           k.notForPlanes + "); choose " + planePlannerIdList();
}

std::string corridorPlaneError(const Mission& m, const AircraftConfig& a, const std::string& who) {
    if (!fleet::fliesAsPlane(a.kind) || !plansCorridorLanes(m))
        return {};
    return who + " flies as a plane: lanes along a corridor are planned for multirotors only (each "
                 "lane end turns on the spot, which a plane cannot fly); choose the sweep planner "
                 "to plan the corridor's ground as an area with the plane's turns";
}

std::vector<std::string> altitudeErrors(const Mission& m, const AircraftConfig& a, double altitudeM) {
    std::string who = aircraftLabel(a.name);
    for (std::size_t i = 0; i < m.aircraft.size(); ++i)
        if (m.aircraft[i].name == a.name)
            who = aircraftName(a, i);
    auto out = altitudeLimitErrors(who, a, altitudeM, false);
    if (!out.empty() || m.options.maxCells == 0 || plansCorridorLanes(m))
        return out;
    auto eff = sensor::effectiveFootprint(a.camera, altitudeM, a.overlap);
    auto geom = localGeometry(m);
    if (!eff || !geom)
        return out; // the camera or the shapes are reported where they are edited
    const geo::MultiPolygon admissible =
        geom->noFly.empty() ? geo::MultiPolygon{geom->area}
                            : geo::difference(geom->area, geo::MultiPolygon(geom->noFly.begin(), geom->noFly.end()));
    if (geo::area(admissible) <= 0.0)
        return out;
    if (auto budget = cellBudgetError(who, a, altitudeM, sensor::cellSizeFor(*eff), admissible,
                                      m.options.gridAngleDeg.value_or(0.0), m.options.maxCells);
        !budget.empty())
        out.push_back(budget);
    return out;
}

std::string ValidationReport::errorSummary() const {
    std::string s;
    for (const auto& p : problems)
        if (p.severity == Severity::Error)
            s += (s.empty() ? "" : "; ") + p.message;
    return s;
}

Result<double> resolvedAltitude(const AircraftConfig& a) {
    if (a.altitudeM)
        return *a.altitudeM;
    if (a.gsdCm)
        return sensor::altitudeForGsd(a.camera, *a.gsdCm);
    return makeError(ErrorCode::InvalidInput, "neither a flight altitude nor a ground sample distance is set");
}

Result<LocalGeometry> localGeometry(const Mission& m) {
    const auto areaProblems = areaProblemsOf(m);
    if (geo::hasError(areaProblems))
        return makeError(ErrorCode::InvalidGeometry, areaProblems.front().message);
    const geo::GeoPolygon area = geo::cleanPolygon(m.area);
    auto frame = geo::LocalFrame::forArea(area);
    if (!frame)
        return frame.error();
    LocalGeometry g{*frame, frame->toLocal(area), {}, {}};
    for (std::size_t i = 0; i < m.noFlyZones.size(); ++i) {
        const auto& z = m.noFlyZones[i];
        const auto problems = geo::validatePolygon(z.polygon, zoneName(z, i));
        for (const auto& p : problems)
            if (p.severity == Severity::Error)
                return makeError(ErrorCode::InvalidGeometry, p.message);
        geo::Polygon local = frame->toLocal(geo::cleanPolygon(z.polygon));
        if (geo::intersection(g.area, local).empty())
            continue; // outside the area: ignored (validateMission warns about it)
        g.noFly.push_back(std::move(local));
        g.noFlyNames.push_back(z.name);
    }
    return g;
}

Result<grid::GridOptions> gridOptionsFor(const Mission& m, std::size_t aircraftIndex, double autoAngleDeg) {
    if (aircraftIndex >= m.aircraft.size())
        return makeError(ErrorCode::NotFound, "the mission has no aircraft number " + std::to_string(aircraftIndex + 1));
    const auto& a = m.aircraft[aircraftIndex];
    const std::string who = aircraftName(a, aircraftIndex);
    auto alt = resolvedAltitude(a);
    if (!alt)
        return makeError(alt.error().code, who + ": " + alt.error().message);
    auto eff = sensor::effectiveFootprint(pointedCamera(a, m.options), *alt, a.overlap);
    if (!eff)
        return makeError(eff.error().code, who + ": " + eff.error().message);
    grid::GridOptions opt;
    opt.cellSize = sensor::cellSizeFor(*eff);
    opt.angleDeg = m.options.gridAngleDeg.value_or(autoAngleDeg);
    opt.safetyMarginM = m.options.safetyMarginM;
    opt.maxCells = m.options.maxCells;
    return opt;
}

namespace {

// Which of the given shapes hold an error.
struct ShapeChecks {
    std::vector<Problem> areaProblems;
    bool zonesOk = true;
};

// The given shapes: the area (or the corridor), then each no-fly zone, each as a polygon of its
// own, as given (vertex numbers as the user knows them).
ShapeChecks validateShapes(const Mission& given, std::vector<Problem>& out) {
    ShapeChecks c;
    c.areaProblems = areaProblemsOf(given);
    out.insert(out.end(), c.areaProblems.begin(), c.areaProblems.end());
    for (std::size_t i = 0; i < given.noFlyZones.size(); ++i) {
        const auto zp =
            geo::validatePolygon(given.noFlyZones[i].polygon, zoneName(given.noFlyZones[i], i));
        c.zonesOk = c.zonesOk && !geo::hasError(zp);
        out.insert(out.end(), zp.begin(), zp.end());
    }
    return c;
}

// The mission's ground as planned, for the checks that need it: the frame, the area and the zones
// that touch it (none when the area has no frame), and the ground outside the zones.
struct PlannedGround {
    std::optional<LocalGeometry> geom;
    geo::MultiPolygon admissible;
};

// Each valid zone in the frame: one outside the area is ignored (a warning), one covering all of
// it is an error.
void addZonesInArea(const Mission& m, LocalGeometry& geom, std::vector<Problem>& out) {
    for (std::size_t i = 0; i < m.noFlyZones.size(); ++i) {
        const auto& z = m.noFlyZones[i];
        if (geo::hasError(geo::validatePolygon(z.polygon, zoneName(z, i))))
            continue;
        geo::Polygon local = geom.frame.toLocal(geo::cleanPolygon(z.polygon));
        const geo::MultiPolygon common = geo::intersection(geom.area, local);
        if (geo::area(common) <= 0.0) {
            warning(out, zoneName(z, i) + " lies entirely outside the area; it is ignored");
            continue;
        }
        if (geo::difference(geom.area, geo::MultiPolygon{local}).empty())
            error(out, zoneName(z, i) +
                           " covers the whole area: nothing admissible is left to photograph");
        geom.noFly.push_back(std::move(local));
        geom.noFlyNames.push_back(z.name);
    }
}

// The valid area in its frame with the zones in it; the area and the admissible ground measured.
PlannedGround validateGround(const Mission& m, ValidationReport& r) {
    auto& out = r.problems;
    PlannedGround g;
    auto frame = geo::LocalFrame::forArea(geo::cleanPolygon(m.area));
    if (!frame) {
        error(out, frame.error().message);
        return g;
    }
    g.geom = LocalGeometry{*frame, frame->toLocal(geo::cleanPolygon(m.area)), {}, {}};
    r.areaM2 = geo::area(g.geom->area);
    addZonesInArea(m, *g.geom, out);
    g.admissible = g.geom->noFly.empty()
                       ? geo::MultiPolygon{g.geom->area}
                       : geo::difference(g.geom->area, geo::MultiPolygon(g.geom->noFly.begin(),
                                                                         g.geom->noFly.end()));
    r.admissibleAreaM2 = geo::area(g.admissible);
    if (r.admissibleAreaM2 <= 0.0 && !geo::hasError(out))
        error(out, "the no-fly zones together cover the whole area: nothing admissible is left "
                   "to photograph");
    return g;
}

// A point of the mission (home, landing): a real position, and (with the area's frame) warnings
// when it lies in a zone or far from the area.
void validatePoint(const std::optional<geo::LonLat>& p, const std::string& what,
                   const std::optional<LocalGeometry>& geom, std::vector<Problem>& out) {
    if (!p)
        return;
    if (!std::isfinite(p->lon) || !std::isfinite(p->lat) || std::abs(p->lon) > 180 ||
        std::abs(p->lat) > 90) {
        error(out, what + " (" + num("%.6f", p->lon) + ", " + num("%.6f", p->lat) +
                       ") is out of range: longitude must lie within ±180 and latitude within ±90 "
                       "degrees");
        return;
    }
    if (!geom)
        return;
    const geo::Vec2 q = geom->frame.toLocal(*p);
    for (std::size_t k = 0; k < geom->noFly.size(); ++k)
        if (geo::contains(geom->noFly[k], q))
            warning(out, what + " lies inside no-fly zone \"" + geom->noFlyNames[k] + "\"");
    if ((q - 0.5 * (geo::bounds(geom->area).min + geo::bounds(geom->area).max)).norm() > 20000)
        warning(out, what + " is more than 20 km from the area");
}

// The planner options, and the fleet as a whole: at least one aircraft, each with its own name.
void validateOptions(const Mission& m, std::vector<Problem>& out) {
    const auto& o = m.options;
    if (!std::isfinite(o.safetyMarginM) || o.safetyMarginM < 0)
        error(out, "the safety margin must be zero or a positive number of metres (got " +
                       num("%g", o.safetyMarginM) + ")");
    if (o.gridAngleDeg && !std::isfinite(*o.gridAngleDeg))
        error(out, "the grid angle must be a finite number of degrees");
    if (o.maxCells == 0)
        error(out, "the cell budget must be at least 1 cell");
    if (o.doubleGrid && plansCorridorLanes(m))
        warning(out, "the double grid is for area surveys: the corridor is flown once, with lanes "
                     "along its line");
    if (m.aircraft.empty())
        error(out, "the mission has no aircraft: add at least one");
    // Names label each aircraft's route and files: a second "Falcon 8" would overwrite the first's.
    for (std::size_t i = 0; i < m.aircraft.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
            if (m.aircraft[i].name == m.aircraft[k].name) {
                error(out, "aircraft " + std::to_string(i + 1) + " has the same name as aircraft " +
                               std::to_string(k + 1) + " (\"" + m.aircraft[i].name +
                               "\"): give each aircraft its own name, as it names its route and "
                               "its files");
                break;
            }
}

// An aircraft's own settings: camera, overlaps, a plane's figures and planner, speeds. False when
// one of them leaves its figures unknown (a planner unfit for it does not).
bool validateSettings(const Mission& m, const AircraftConfig& a, const std::string& who,
                      std::vector<Problem>& out) {
    bool ok = true;
    if (auto s = sensor::validate(a.camera); !s) {
        error(out, who + ": " + s.error().message);
        ok = false;
    }
    for (auto [v, side] : {std::pair{a.overlap.front, "front"}, std::pair{a.overlap.side, "side"}})
        if (!std::isfinite(v) || v < 0.0 || v >= 1.0) {
            error(out, who + ": the " + std::string(side) +
                           " overlap must lie in [0, 1), e.g. 0.7 for 70 % (got " + num("%g", v) +
                           ")");
            ok = false;
        }
    for (auto& e : planeErrors(a, who)) {
        error(out, std::move(e));
        ok = false;
    }
    if (auto e = planeRoutingError(a, m.options.planner, who); !e.empty())
        error(out, std::move(e));
    else if (auto c = corridorPlaneError(m, a, who); !c.empty())
        error(out, std::move(c));
    if (auto t = cameraTiltError(m, a, who); !t.empty())
        error(out, std::move(t));
    if (fleet::fliesAsPlane(a.kind) && a.plane.minTurnRadiusM && *a.plane.minTurnRadiusM > 0 &&
        fleet::bankAngleDeg(a.plane, a.cruiseSpeedMps) > kSteepBankDeg)
        warning(out, who + ": a turn radius of " + num("%.0f", *a.plane.minTurnRadiusM) + " m at " +
                         num("%.1f", a.cruiseSpeedMps) + " m/s needs a bank of " +
                         num("%.0f", fleet::bankAngleDeg(a.plane, a.cruiseSpeedMps)) +
                         " degrees; survey planes bank 45-60 degrees at most: check the turn "
                         "radius");
    // The flight-time model divides by these: a zero or negative figure would give nonsense times.
    for (auto [v, what, unit] : {std::tuple{a.cruiseSpeedMps, "cruise speed", "m/s"},
                                 std::tuple{a.turnRateDegS, "turn rate", "deg/s"},
                                 std::tuple{a.accelerationMps2, "acceleration", "m/s2"}})
        if (!std::isfinite(v) || v <= 0.0) {
            error(out, who + ": the " + std::string(what) + " must be greater than 0 " + unit +
                           " (got " + num("%g", v) + ")");
            ok = false;
        }
    return ok;
}

// The flight altitude, given or derived from the GSD (with settings `ok`), within its limits.
// False when it is missing or unusable (or the settings were).
bool resolveFlightAltitude(const AircraftConfig& a, const std::string& who, bool ok,
                           AircraftFigures& f, std::vector<Problem>& out) {
    if (a.altitudeM) {
        f.altitudeM = *a.altitudeM;
    } else if (a.gsdCm) {
        if (!std::isfinite(*a.gsdCm) || *a.gsdCm <= 0) {
            error(out, who + ": the ground sample distance must be greater than 0 cm/px (got " +
                           num("%g", *a.gsdCm) + ")");
            ok = false;
        } else if (ok) {
            auto alt = sensor::altitudeForGsd(a.camera, *a.gsdCm);
            if (alt)
                f.altitudeM = *alt;
        }
    } else {
        error(out, who + ": neither a flight altitude nor a ground sample distance is set");
        ok = false;
    }
    if ((a.altitudeM || a.gsdCm) && ok) {
        for (auto& e : altitudeLimitErrors(who, a, f.altitudeM, !a.altitudeM)) {
            error(out, std::move(e));
            ok = false;
        }
    }
    return ok;
}

// The photo at that altitude: its footprints, the cell size and the GSD; false when the camera
// gives none.
bool addFootprint(const Mission& m, const AircraftConfig& a, const std::string& who,
                  AircraftFigures& f, std::vector<Problem>& out) {
    // The footprint of the camera as the mission points it (tilted: oblique photos); the GSD is
    // the camera's straight down.
    auto eff = sensor::effectiveFootprint(pointedCamera(a, m.options), f.altitudeM, a.overlap);
    auto gsd = sensor::gsdCmAt(a.camera, f.altitudeM);
    if (!eff) {
        error(out, who + ": " + eff.error().message);
        return false;
    }
    f.effective = *eff;
    f.footprint = eff->real;
    f.cellSizeM = sensor::cellSizeFor(*eff);
    f.gsdCm = gsd ? *gsd : 0.0;
    if (eff->alongM > eff->acrossM)
        warning(out, who + ": the photo spacing along the track (" + num("%.1f", eff->alongM) +
                         " m) exceeds the track spacing (" + num("%.1f", eff->acrossM) +
                         " m): raise the front overlap or lower the side overlap");
    return true;
}

// The grid the aircraft would get: its extent against the cell budget, then (when `build`: the
// shapes are sound) the grid itself, its cells counted and its unflyable cells and pockets named.
void addGrid(const Mission& m, const AircraftConfig& a, const std::string& who,
             const PlannedGround& ground, bool build, AircraftFigures& f,
             std::vector<Problem>& out) {
    const auto& o = m.options;
    grid::Grid::Size size;
    const std::string budget = cellBudgetError(who, a, f.altitudeM, f.cellSizeM, ground.admissible,
                                               f.gridAngleDeg, o.maxCells, &size);
    f.cols = size.cols;
    f.rows = size.rows;
    if (!budget.empty()) {
        error(out, budget);
        return;
    }
    if (!build)
        return;
    grid::GridOptions gopt{f.cellSizeM, f.gridAngleDeg, std::max(0.0, o.safetyMarginM), o.maxCells};
    auto g = grid::Grid::build(ground.geom->area, ground.geom->noFly, gopt);
    if (!g) {
        error(out, who + ": " + g.error().message);
        return;
    }
    f.gridBuilt = true;
    f.cellsToVisit = g->visitCount();
    for (int c = 0; c < g->cellCount(); ++c) {
        f.shiftedCells += g->state(c) == grid::CellState::Shifted;
        f.unflyableCells += g->state(c) == grid::CellState::Unflyable;
    }
    if (f.unflyableCells > 0)
        warning(out, who + ": " + std::to_string(f.unflyableCells) +
                         " cell(s) of the area lie wholly within the safety margin of a no-fly "
                         "zone: they are not flown over, and their ground is photographed from "
                         "the neighbouring cells (the plan's coverage check reports any part left "
                         "unseen)");
    if (!g->pockets().empty())
        warning(out, pocketWarning(g->pockets()));
}

// Aircraft i: its settings, footprint, cell size and the grid it would get (built when
// `buildGrid`).
AircraftFigures validateAircraft(const Mission& m, std::size_t i, const PlannedGround& ground,
                                 double admissibleAreaM2, bool buildGrid,
                                 std::vector<Problem>& out) {
    const auto& a = m.aircraft[i];
    const auto& o = m.options;
    const std::string who = aircraftName(a, i);
    AircraftFigures f;
    f.name = a.name;
    bool ok = validateSettings(m, a, who, out);
    ok = resolveFlightAltitude(a, who, ok, f, out);
    if (ok)
        ok = addFootprint(m, a, who, f, out);
    f.gridAngleDeg = o.gridAngleDeg.value_or(0.0);
    if (ok && ground.geom && admissibleAreaM2 > 0 && o.maxCells > 0 &&
        std::isfinite(f.gridAngleDeg) && !plansCorridorLanes(m))
        addGrid(m, a, who, ground, buildGrid, f, out);
    return f;
}

} // namespace

ValidationReport validateMission(const Mission& given) {
    ValidationReport r;
    auto& out = r.problems;

    const ShapeChecks shapes = validateShapes(given, out);
    // The rest on the mission as planMission plans it: a traced boundary simplified
    // (simplify_input.h).
    const bool shapesOk = !geo::hasError(out);
    const InputSimplification simple =
        shapesOk ? simplifyInput(given, true) : InputSimplification{};
    if (!simple.note.empty())
        warning(out, simple.note);
    if (!simple.error.empty())
        error(out, simple.error);
    const Mission& m = shapesOk ? simple.mission : given;

    PlannedGround ground;
    if (!geo::hasError(shapes.areaProblems))
        ground = validateGround(m, r);

    validatePoint(m.home, "the home point", ground.geom, out);
    validatePoint(m.landing, "the landing point", ground.geom, out);
    validateOptions(m, out);

    const bool buildGrids = shapes.zonesOk && simple.error.empty();
    for (std::size_t i = 0; i < m.aircraft.size(); ++i)
        r.aircraft.push_back(validateAircraft(m, i, ground, r.admissibleAreaM2, buildGrids, out));
    return r;
}

} // namespace pf::mission
