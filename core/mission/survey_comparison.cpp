#include "core/mission/survey_comparison.h"
#include "core/mission/planner_kinds.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/mission/plan_mission.h"
#include "core/mission/validation.h"
#include "core/plan/coverage_check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace pf::mission {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The lanes issue's second simple measure: what a multirotor loses stopping and starting at a turn.
constexpr double kSimpleStopS = 3.0;
// No plan of the comparison is cut into sorties: the lawnmower is one flight.
constexpr double kUnlimitedEnduranceMin = 1e7;

void measurePath(SurveyMeasures& s, const plan::FlightTimeModel& model) {
    const plan::FlightTime t = plan::flightTime(s.path, model);
    s.timeS = t.totalS;
    // Paper 004's measure: every metre at V, every degree of heading change at omega.
    s.simpleTimeS = (model.speedMps > 0 ? t.lengthM / model.speedMps : 0.0) +
                    (model.turnRateDegS > 0 ? t.turnAngleDeg / model.turnRateDegS : 0.0);
    s.simpleStopsTimeS = s.simpleTimeS + kSimpleStopS * t.turns;
    s.pathM = t.lengthM;
    s.turns = t.turns;
    s.turnAngleDeg = t.turnAngleDeg;
}

double ratio(double a, double b) { return b > 0 && std::isfinite(a) ? a / b : kNaN; }

bool inSet(const SurveyComparison& c, AreaSet set) {
    return set == AreaSet::All || (set == AreaSet::WithZones) == (c.zones > 0);
}

std::string fmt(const char* f, double v) {
    if (!std::isfinite(v))
        return "-";
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

// A table column: `s` padded to `w` characters (right-aligned unless `left`), then a space.
std::string pad(std::string s, std::size_t w, bool left = false) {
    if (s.size() < w)
        s = left ? s + std::string(w - s.size(), ' ') : std::string(w - s.size(), ' ') + s;
    return s + ' ';
}

} // namespace

AircraftConfig surveyAircraft() {
    AircraftConfig a;
    a.name = "Survey aircraft";
    a.model = "custom";
    a.camera.name = "60 x 45 degrees";
    a.camera.hfovDeg = 60.0;
    a.camera.vfovDeg = 45.0;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = 30.0;
    a.overlap = {0.2, 0.2};
    a.cruiseSpeedMps = 10.0;
    a.turnRateDegS = 60.0;
    a.accelerationMps2 = plan::kDefaultAccelerationMps2;
    return a;
}

Result<geo::LonLat> surveyHome(const plan::EvalArea& area, double marginM) {
    auto frame = geo::LocalFrame::forArea(area.area);
    if (!frame)
        return frame.error();
    const geo::Ring ring = frame->toLocal(area.area.outer);
    if (ring.empty())
        return makeError(ErrorCode::InvalidGeometry, area.name + ": the area has no vertex");
    std::vector<geo::Polygon> zones;
    for (const auto& z : area.noFly)
        zones.push_back(frame->toLocal(z));
    const geo::Vec2 sw = geo::bounds(ring).min;
    std::vector<std::size_t> order(ring.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return (ring[a] - sw).norm() < (ring[b] - sw).norm(); });
    for (std::size_t i : order) {
        bool clear = true;
        for (const auto& z : zones)
            if (geo::distanceTo(z, ring[i]) <= marginM + 1.0) {
                clear = false;
                break;
            }
        if (clear)
            return frame->toGeo(ring[i]);
    }
    return frame->toGeo(ring[order.front()]);
}

Result<Mission> surveyMission(const plan::EvalArea& area, const AircraftConfig& aircraft, const PlannerOptions& options) {
    Mission m;
    m.name = area.name;
    m.area = area.area;
    for (std::size_t i = 0; i < area.noFly.size(); ++i)
        m.noFlyZones.push_back({"zone " + std::to_string(i + 1), area.noFly[i]});
    m.aircraft.push_back(aircraft);
    m.options = options;
    auto home = surveyHome(area, options.safetyMarginM);
    if (!home)
        return makeError(home.error().code, area.name + ": " + home.error().message);
    m.home = *home;
    return m;
}

Result<SurveyComparison> compareOnMission(const Mission& mission, const std::string& areaName,
                                          const std::vector<PlannerKind>& kinds) {
    if (mission.aircraft.size() != 1)
        return makeError(ErrorCode::InvalidInput, areaName + ": the comparison flies one aircraft (the mission has " +
                                                      std::to_string(mission.aircraft.size()) + ")");
    if (!mission.home)
        return makeError(ErrorCode::InvalidInput, areaName + ": the comparison needs a home point");
    Mission m = mission;
    m.aircraft.front().enduranceMin = kUnlimitedEnduranceMin;
    m.landing.reset();
    const AircraftConfig& a = m.aircraft.front();
    auto geom = localGeometry(m);
    if (!geom)
        return makeError(geom.error().code, areaName + ": " + geom.error().message);
    auto alt = resolvedAltitude(a);
    if (!alt)
        return makeError(alt.error().code, areaName + ": " + alt.error().message);
    auto eff = sensor::effectiveFootprint(a.camera, *alt, a.overlap);
    if (!eff)
        return makeError(eff.error().code, areaName + ": " + eff.error().message);
    const plan::FlightTimeModel model = flightModel(a);

    SurveyComparison c;
    c.area = areaName;
    c.zones = static_cast<int>(geom->noFly.size());
    c.localArea = {geom->area};
    c.localZones = geom->noFly;
    c.marginM = m.options.safetyMarginM;
    c.margins = c.localZones.empty() ? geo::MultiPolygon{} : geo::buffer(geo::unite(c.localZones), c.marginM);
    c.areaM2 = geo::area(c.localArea);
    const geo::MultiPolygon admissible =
        c.localZones.empty() ? c.localArea : geo::difference(geom->area, c.localZones);
    c.admissibleM2 = geo::area(admissible);
    c.home = geom->frame.toLocal(*m.home);
    c.trackSpacingM = eff->acrossM;
    c.photoSpacingM = eff->alongM;

    // The lawnmower.
    plan::LawnmowerOptions lo;
    lo.trackSpacingM = eff->acrossM;
    lo.photoSpacingM = eff->alongM;
    lo.time = model;
    lo.home = c.home;
    lo.footprintAcrossM = eff->real.longSideM;
    lo.footprintAlongM = eff->real.shortSideM;
    const auto t0 = std::chrono::steady_clock::now();
    auto lm = plan::planLawnmower(c.localArea, lo);
    if (!lm)
        return makeError(lm.error().code, areaName + ": " + lm.error().message);
    SurveyMeasures& L = c.lawnmower;
    L.planningMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    L.ok = true;
    L.path = plan::flownPath(*lm);
    measurePath(L, model);
    L.timeS = lm->time.totalS;
    L.photos = lm->photos;
    L.angleDeg = lm->angleDeg;
    std::vector<plan::PhotoFootprint> fps;
    for (const auto& lane : lm->transects)
        for (const auto& p : lane.photos) {
            L.photoPoints.push_back(p);
            fps.push_back({p, lane.headingDeg, eff->real.longSideM, eff->real.shortSideM});
        }
    auto cov = plan::checkCoverage(admissible, fps);
    if (!cov)
        return makeError(cov.error().code, areaName + ": lawnmower coverage: " + cov.error().message);
    L.coverage = cov->coveredFraction;
    c.crossings = plan::countNoFlyCrossings(*lm, c.localZones, c.marginM);
    L.violations = c.crossings.photosInZones + c.crossings.legsCrossing;

    // Every planner, through the mission pipeline.
    for (PlannerKind k : kinds) {
        Mission mk = m;
        mk.options.planner = k;
        PlannerRun run;
        run.kind = k;
        const auto s0 = std::chrono::steady_clock::now();
        auto plan = planMission(mk);
        run.m.planningMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s0).count();
        if (!plan) {
            run.m.error = plan.error().message;
            c.planners.push_back(std::move(run));
            continue;
        }
        const AircraftPlan& ap = plan->aircraft.front();
        run.m.ok = true;
        run.m.path.push_back(c.home);
        for (const auto& w : ap.localWaypoints) {
            run.m.path.push_back(w.pos);
            if (w.kind == route::WaypointKind::Photo)
                run.m.photoPoints.push_back(w.pos);
        }
        run.m.path.push_back(c.home);
        measurePath(run.m, model);
        run.m.photos = static_cast<int>(run.m.photoPoints.size());
        run.m.coverage = plan->coverageRatio;
        run.m.violations = plan->noFlyViolations;
        run.m.angleDeg = ap.gridAngleDeg;
        c.planners.push_back(std::move(run));
    }
    return c;
}

SurveyRatios ratiosTo(const SurveyMeasures& p, const SurveyComparison& c) {
    SurveyRatios r;
    const SurveyMeasures& L = c.lawnmower;
    if (!p.ok || !L.ok)
        return {kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
    r.time = ratio(p.timeS, L.timeS);
    r.simpleTime = ratio(p.simpleTimeS, L.simpleTimeS);
    r.simpleStopsTime = ratio(p.simpleStopsTimeS, L.simpleStopsTimeS);
    r.photos = ratio(p.photos, L.photos);
    r.path = ratio(p.pathM, L.pathM);
    r.turns = ratio(p.turns, L.turns);
    r.photosOutside = ratio(p.photos, c.crossings.photosOutsideZones);
    return r;
}

double median(std::vector<double> v) {
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
    if (v.empty())
        return kNaN;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<SurveySummary> summariseSurvey(const std::vector<SurveyComparison>& areas, AreaSet set) {
    std::vector<PlannerKind> order;
    for (const auto& c : areas)
        for (const auto& r : c.planners)
            if (std::find(order.begin(), order.end(), r.kind) == order.end())
                order.push_back(r.kind);
    std::vector<SurveySummary> out;
    for (PlannerKind k : order) {
        SurveySummary s;
        s.kind = k;
        s.minCoverage = kNaN;
        std::vector<double> t, st, sst, ph, po, pa, tu;
        for (const auto& c : areas) {
            if (!inSet(c, set))
                continue;
            for (const auto& r : c.planners) {
                if (r.kind != k)
                    continue;
                if (!r.m.ok) {
                    ++s.failed;
                    continue;
                }
                ++s.areas;
                const SurveyRatios q = ratiosTo(r.m, c);
                t.push_back(q.time);
                st.push_back(q.simpleTime);
                sst.push_back(q.simpleStopsTime);
                ph.push_back(q.photos);
                po.push_back(q.photosOutside);
                pa.push_back(q.path);
                tu.push_back(q.turns);
                s.minCoverage = std::isnan(s.minCoverage) ? r.m.coverage : std::min(s.minCoverage, r.m.coverage);
                s.violations += r.m.violations;
            }
        }
        s.medians = {median(t), median(st), median(sst), median(ph), median(pa), median(tu), median(po)};
        if (s.areas + s.failed > 0)
            out.push_back(s);
    }
    return out;
}

LawnmowerSummary summariseLawnmower(const std::vector<SurveyComparison>& areas, AreaSet set) {
    LawnmowerSummary s;
    s.minCoverage = kNaN;
    std::vector<double> pz, lc;
    for (const auto& c : areas) {
        if (!inSet(c, set) || !c.lawnmower.ok)
            continue;
        ++s.areas;
        s.minCoverage = std::isnan(s.minCoverage) ? c.lawnmower.coverage : std::min(s.minCoverage, c.lawnmower.coverage);
        pz.push_back(c.crossings.photosInZones);
        lc.push_back(c.crossings.legsCrossing);
        s.photosInZones += c.crossings.photosInZones;
        s.legsCrossing += c.crossings.legsCrossing;
    }
    s.medianPhotosInZones = median(pz);
    s.medianLegsCrossing = median(lc);
    return s;
}

std::string surveyTable(const std::vector<SurveyComparison>& areas) {
    std::string out;
    out += "Each planner beside the lawnmower (a Survey at its fastest angle, flying straight over the no-fly "
           "zones),\nhome to home by the one flight-time model; x = planner / lawnmower.\n\n";
    out += pad("area", 26, true) + pad("zones", 6) + pad("planner", 11, true) + pad("time s", 9) + pad("x", 6) +
           pad("photos", 7) + pad("x", 6) + pad("x out", 6) + pad("path m", 8) + pad("x", 6) + pad("turns", 6) +
           pad("x", 6) + pad("cover", 7) + pad("nofly", 6) + "\n";
    for (const auto& c : areas) {
        const auto& L = c.lawnmower;
        out += pad(c.area, 26, true) + pad(std::to_string(c.zones), 6) + pad("lawnmower", 11, true) +
               pad(fmt("%.0f", L.timeS), 9) + pad("1", 6) + pad(std::to_string(L.photos), 7) + pad("1", 6) +
               pad(c.zones ? std::to_string(c.crossings.photosOutsideZones) : std::string("-"), 6) +
               pad(fmt("%.0f", L.pathM), 8) + pad("1", 6) + pad(std::to_string(L.turns), 6) + pad("1", 6) +
               pad(fmt("%.4f", L.coverage), 7) +
               pad(std::to_string(c.crossings.photosInZones) + "/" + std::to_string(c.crossings.legsCrossing), 6) +
               "\n";
        for (const auto& r : c.planners) {
            const char* name = plannerKindInfo(r.kind).id;
            if (!r.m.ok) {
                out += pad("", 26, true) + pad("", 6) + pad(name, 11, true) + "no plan: " + r.m.error + "\n";
                continue;
            }
            const SurveyRatios q = ratiosTo(r.m, c);
            out += pad("", 26, true) + pad("", 6) + pad(name, 11, true) + pad(fmt("%.0f", r.m.timeS), 9) +
                   pad(fmt("%.2f", q.time), 6) + pad(std::to_string(r.m.photos), 7) + pad(fmt("%.2f", q.photos), 6) +
                   pad(c.zones ? fmt("%.2f", q.photosOutside) : std::string("-"), 6) + pad(fmt("%.0f", r.m.pathM), 8) +
                   pad(fmt("%.2f", q.path), 6) + pad(std::to_string(r.m.turns), 6) + pad(fmt("%.1f", q.turns), 6) +
                   pad(fmt("%.4f", r.m.coverage), 7) + pad(std::to_string(r.m.violations), 6) + "\n";
        }
    }
    out += "\n(lawnmower nofly: photos in zones / legs crossing a zone or its margin; x out: photos over the "
           "lawnmower's\nphotos outside the zones)\n";

    struct Named {
        AreaSet set;
        const char* what;
    };
    for (const Named& n : {Named{AreaSet::All, "all %d area%s"}, Named{AreaSet::WithoutZones, "the %d area%s without no-fly zones"},
                           Named{AreaSet::WithZones, "the %d area%s with no-fly zones"}}) {
        const auto sum = summariseSurvey(areas, n.set);
        const auto lm = summariseLawnmower(areas, n.set);
        if (lm.areas == 0 || (n.set != AreaSet::All && lm.areas == static_cast<int>(areas.size())))
            continue;
        char title[128];
        std::snprintf(title, sizeof title, n.what, lm.areas, lm.areas == 1 ? "" : "s");
        out += std::string("\nMedian over ") + title + ", planner / lawnmower:\n";
        out += pad("", 44, true);
        for (const auto& s : sum)
            out += pad(plannerKindInfo(s.kind).id, 11);
        out += "\n";
        auto row = [&](const char* label, auto get, const char* f) {
            out += pad(label, 44, true);
            for (const auto& s : sum)
                out += pad(fmt(f, get(s)), 11);
            out += "\n";
        };
        row("flight time (one model, stops included)", [](const SurveySummary& s) { return s.medians.time; }, "%.2f");
        row("flight time, path/V + turn angle/omega", [](const SurveySummary& s) { return s.medians.simpleTime; },
            "%.2f");
        row("the same + 3 s per turn", [](const SurveySummary& s) { return s.medians.simpleStopsTime; }, "%.2f");
        row("photos", [](const SurveySummary& s) { return s.medians.photos; }, "%.2f");
        const bool zonesInSet = std::any_of(areas.begin(), areas.end(), [&](const SurveyComparison& c) {
            return inSet(c, n.set) && c.zones > 0;
        });
        if (zonesInSet)
            row("photos / lawnmower's photos outside zones",
                [](const SurveySummary& s) { return s.medians.photosOutside; }, "%.2f");
        row("path length", [](const SurveySummary& s) { return s.medians.path; }, "%.2f");
        row("turns", [](const SurveySummary& s) { return s.medians.turns; }, "%.1f");
        row("lowest coverage", [](const SurveySummary& s) { return s.minCoverage; }, "%.4f");
        row("no-fly violations (sum)", [](const SurveySummary& s) { return double(s.violations); }, "%.0f");
        row("areas without a plan", [](const SurveySummary& s) { return double(s.failed); }, "%.0f");
        char line[256];
        std::snprintf(line, sizeof line,
                      "lawnmower: lowest coverage %.4f; photos in zones %d, legs crossing a zone or margin %d "
                      "(median %s and %s per area)\n",
                      lm.minCoverage, lm.photosInZones, lm.legsCrossing, fmt("%.1f", lm.medianPhotosInZones).c_str(),
                      fmt("%.1f", lm.medianLegsCrossing).c_str());
        out += line;
    }
    // The columns end in a space: none at the end of a line.
    std::string trimmed, line;
    for (char ch : out) {
        if (ch != '\n') {
            line += ch;
            continue;
        }
        line.erase(line.find_last_not_of(' ') + 1);
        trimmed += line + '\n';
        line.clear();
    }
    return trimmed + line;
}

std::string surveyCsv(const std::vector<SurveyComparison>& areas) {
    std::string out = "area,zones,area_m2,planner,ok,time_s,simple_time_s,simple_stops_time_s,photos,path_m,turns,"
                      "turn_angle_deg,coverage,violations,angle_deg,planning_ms,time_ratio,simple_time_ratio,"
                      "simple_stops_time_ratio,photos_ratio,photos_outside_ratio,path_ratio,turns_ratio,"
                      "lawnmower_photos_in_zones,lawnmower_legs_crossing,error\n";
    auto csvNum = [](double v, const char* f) { return std::isfinite(v) ? fmt(f, v) : std::string(); };
    auto quoted = [](std::string s) {
        std::string q = "\"";
        for (char ch : s)
            q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        return q + "\"";
    };
    for (const auto& c : areas) {
        auto line = [&](const char* planner, const SurveyMeasures& m, const SurveyRatios& q) {
            out += quoted(c.area) + "," + std::to_string(c.zones) + "," + csvNum(c.areaM2, "%.1f") + "," + planner +
                   "," + (m.ok ? "1" : "0") + "," + csvNum(m.timeS, "%.3f") + "," + csvNum(m.simpleTimeS, "%.3f") + "," +
                   csvNum(m.simpleStopsTimeS, "%.3f") + "," + std::to_string(m.photos) + "," +
                   csvNum(m.pathM, "%.3f") + "," + std::to_string(m.turns) + "," + csvNum(m.turnAngleDeg, "%.3f") +
                   "," + csvNum(m.coverage, "%.5f") + "," + std::to_string(m.violations) + "," +
                   csvNum(m.angleDeg, "%.3f") + "," + csvNum(m.planningMs, "%.2f") + "," + csvNum(q.time, "%.4f") +
                   "," + csvNum(q.simpleTime, "%.4f") + "," + csvNum(q.simpleStopsTime, "%.4f") + "," +
                   csvNum(q.photos, "%.4f") + "," + csvNum(q.photosOutside, "%.4f") + "," + csvNum(q.path, "%.4f") +
                   "," + csvNum(q.turns, "%.4f") + "," + std::to_string(c.crossings.photosInZones) + "," +
                   std::to_string(c.crossings.legsCrossing) + "," + (m.error.empty() ? "" : quoted(m.error)) + "\n";
        };
        line("lawnmower", c.lawnmower, ratiosTo(c.lawnmower, c));
        for (const auto& r : c.planners)
            line(plannerKindInfo(r.kind).id, r.m, ratiosTo(r.m, c));
    }
    return out;
}

} // namespace pf::mission
