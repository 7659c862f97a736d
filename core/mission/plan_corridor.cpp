#include "core/mission/plan_corridor.h"

#include "core/job_scope.h"
#include "core/mission/build_plan.h"
#include "core/mission/corridor.h"
#include "core/mission/plan_region.h"
#include "core/mission/validation.h"
#include "core/plan/corridor/corridor_planner.h"
#include "core/route/photo_waypoints.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

namespace pf::mission {

namespace {

using namespace detail;

// The corridor plan as waypoints: photos and corners along the runs, the safe ways between them.
std::vector<route::LocalWaypoint> corridorWaypoints(const plan::CorridorPlan& cp) {
    std::vector<route::LocalWaypoint> out;
    for (std::size_t i = 0; i < cp.runs.size(); ++i) {
        for (const auto& p : cp.runs[i].points)
            out.push_back({p.pos, p.headingDeg,
                           p.photo ? route::WaypointKind::Photo : route::WaypointKind::Turn, -1});
        if (i + 1 >= cp.runs.size())
            continue;
        const auto& link = cp.links[i];
        for (std::size_t k = 0; k < link.size(); ++k) {
            const geo::Vec2 next =
                k + 1 < link.size() ? link[k + 1] : cp.runs[i + 1].points.front().pos;
            out.push_back({link[k], plan::compassHeadingDeg(next - link[k]),
                           route::WaypointKind::Transit, -1});
        }
    }
    route::dropNearDuplicates(out);
    return out;
}

// The time aircraft k flies its stretch alone, from home and back.
struct Stretches {
    std::vector<double> cuts;  // n - 1 stations
    std::vector<double> times; // per aircraft in the order
    double makespan() const {
        return times.empty() ? 0.0 : *std::max_element(times.begin(), times.end());
    }
    double spread() const {
        const double mean =
            std::accumulate(times.begin(), times.end(), 0.0) / static_cast<double>(times.size());
        return mean > 0 ? makespan() / mean : 1.0;
    }
};

} // namespace

Result<AircraftPlan>
planCorridorStretch(const std::vector<geo::Vec2>& line, double widthM,
                    const std::vector<geo::Polygon>& noFly, const AircraftConfig& aircraft,
                    const PlannerOptions& options, const geo::LocalFrame& frame,
                    const std::optional<geo::Vec2>& home, const std::optional<geo::Vec2>& landing) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::string who = aircraftLabel(aircraft);
    auto alt = resolvedAltitude(aircraft);
    if (!alt)
        return makeError(alt.error().code, who + ": " + alt.error().message);
    auto eff = sensor::effectiveFootprint(aircraft.camera, *alt, aircraft.overlap);
    if (!eff)
        return makeError(eff.error().code, who + ": " + eff.error().message);
    plan::CorridorOptions co;
    co.widthM = widthM;
    co.trackSpacingM = eff->acrossM;
    co.photoSpacingM = eff->alongM;
    co.safetyMarginM = options.safetyMarginM;
    co.time = flightModel(aircraft);
    co.home = home;
    co.landing = landing;
    auto cp = plan::planCorridor(line, noFly, co);
    if (stopRequested())
        return cancelledError();
    if (!cp)
        return makeError(cp.error().code, who + ": " + cp.error().message);
    AircraftPlan p;
    p.aircraft = aircraft.name;
    p.planner = PlannerKind::Auto;
    p.plannerChoice =
        "corridor: " + std::to_string(cp->stats.lanes) + " lane(s) along the line (" +
        metres(cp->stats.lengthM) + " m" +
        (cp->stats.sections > 1 ? ", in " + std::to_string(cp->stats.sections) + " sections" : "") +
        ")";
    p.warnings = cp->warnings;
    p.altitudeM = *alt;
    p.cellSizeM = sensor::cellSizeFor(*eff);
    p.footprint = *eff;
    p.anglesTried = 1;
    p.localWaypoints = corridorWaypoints(*cp);
    routeMetrics(p, co.time);
    p.metrics.photos = static_cast<int>(
        std::count_if(p.localWaypoints.begin(), p.localWaypoints.end(),
                      [](const auto& w) { return w.kind == route::WaypointKind::Photo; }));
    p.route.aircraft = aircraft.name;
    p.route.cruiseSpeedMps = aircraft.cruiseSpeedMps;
    if (home)
        p.route.home = frame.toGeo(*home);
    p.route.waypoints = routeWaypoints(p.localWaypoints, frame, *alt);
    p.metrics.planningMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return p;
}

std::vector<double> snapCuts(const std::vector<geo::Vec2>& line, std::vector<double> cuts,
                             double widthM) {
    const std::vector<double> st = plan::lineStations(line);
    // How far from a bend its lanes reach along the line: the inside lanes' mitre points (at most
    // that of a 150 degree bend), and a metre more.
    std::vector<double> reach(st.size(), 0.0);
    for (std::size_t i = 1; i + 1 < st.size(); ++i) {
        const double a = std::min(std::abs(plan::turnAt(line, i)), 150.0 * M_PI / 180.0);
        reach[i] = 0.5 * widthM * std::tan(0.5 * a) + 1.0;
    }
    for (double& c : cuts) {
        for (std::size_t i = 1; i + 1 < st.size(); ++i) {
            if (std::abs(c - st[i]) >= reach[i])
                continue;
            // Out of the bend's reach on the nearer side when the segment leaves room, else the
            // middle of the longer segment beside the bend.
            const double before = st[i] - reach[i], after = st[i] + reach[i];
            const bool roomBefore = before >= st[i - 1] + reach[i - 1],
                       roomAfter = after <= st[i + 1] - reach[i + 1];
            if (roomBefore && (!roomAfter || c - before <= after - c))
                c = before;
            else if (roomAfter)
                c = after;
            else
                c = st[i + 1] - st[i] >= st[i] - st[i - 1] ? 0.5 * (st[i] + st[i + 1])
                                                           : 0.5 * (st[i - 1] + st[i]);
        }
    }
    std::sort(cuts.begin(), cuts.end());
    return cuts;
}

namespace {

// The split of the line between the aircraft in `order`, balanced on their times alone.
Result<Stretches> balance(const Mission& m, const LocalGeometry& geom,
                          const std::vector<geo::Vec2>& line, const std::vector<std::size_t>& order,
                          const std::vector<std::optional<geo::Vec2>>& homes,
                          const std::optional<geo::Vec2>& landing) {
    const std::size_t n = order.size();
    const double length = plan::lineLength(line);
    // First guess: each aircraft's share of the line in proportion to its speed over its lane
    // count.
    std::vector<double> rate(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& a = m.aircraft[order[i]];
        auto alt = resolvedAltitude(a);
        if (!alt)
            return makeError(alt.error().code, aircraftLabel(a) + ": " + alt.error().message);
        auto eff = sensor::effectiveFootprint(a.camera, *alt, a.overlap);
        if (!eff)
            return makeError(eff.error().code, aircraftLabel(a) + ": " + eff.error().message);
        rate[i] = a.cruiseSpeedMps / plan::laneCount(m.corridor->widthM, eff->acrossM);
    }
    Stretches best;
    best.times.assign(n, std::numeric_limits<double>::infinity());
    for (int round = 0; round < 8; ++round) {
        const double sum = std::accumulate(rate.begin(), rate.end(), 0.0);
        std::vector<double> cuts;
        double at = 0.0;
        for (std::size_t i = 0; i + 1 < n; ++i)
            cuts.push_back(at += length * rate[i] / sum);
        cuts = snapCuts(line, cuts, m.corridor->widthM);
        // Stretches of at least a metre each, else the line is too short for so many aircraft.
        for (std::size_t i = 0; i < cuts.size(); ++i)
            if (cuts[i] - (i == 0 ? 0.0 : cuts[i - 1]) < 1.0 ||
                (i + 1 == cuts.size() && length - cuts[i] < 1.0))
                return makeError(ErrorCode::InvalidInput, "the corridor (" + metres(length) +
                                                              " m) is too short to share between " +
                                                              std::to_string(n) +
                                                              " aircraft: plan it with fewer");
        Stretches s{cuts, {}};
        for (std::size_t i = 0; i < n; ++i) {
            if (stopRequested())
                return cancelledError();
            const double a = i == 0 ? 0.0 : cuts[i - 1], b = i + 1 == n ? length : cuts[i];
            const std::size_t k = order[i];
            auto ap = planCorridorStretch(plan::subLine(line, a, b), m.corridor->widthM, geom.noFly,
                                          m.aircraft[k], m.options, geom.frame, homes[k], landing);
            if (!ap)
                return ap.error();
            const double t =
                aloneRouteTimeS(surveyPart(ap->localWaypoints), m.aircraft[k], homes[k], landing);
            s.times.push_back(t);
            // Metres of line per second flown, for the next round.
            rate[i] = t > 0 ? (b - a) / t : rate[i];
        }
        if (s.makespan() < best.makespan())
            best = s;
        if (s.spread() <= 1.03)
            break;
    }
    return best;
}

} // namespace

Result<MissionPlan> planCorridorMission(const Mission& m) {
    if (m.aircraft.empty())
        return makeError(ErrorCode::InvalidInput,
                         "the mission has no aircraft: add one to plan a flight");
    for (std::size_t i = 0; i < m.aircraft.size(); ++i)
        if (auto e = corridorPlaneError(
                m, m.aircraft[i], aircraftLabel(m.aircraft[i].name, "aircraft " + std::to_string(i + 1)));
            !e.empty())
            return makeError(ErrorCode::InvalidInput, e);
    auto geom = localGeometry(m);
    if (!geom)
        return geom.error();
    const std::vector<geo::Vec2> line = corridorLine(*m.corridor, geom->frame);
    const std::size_t n = m.aircraft.size();
    std::vector<std::optional<geo::Vec2>> homes;
    for (const auto& a : m.aircraft) {
        const std::optional<geo::LonLat> h = a.home ? a.home : m.home;
        homes.push_back(h ? std::optional<geo::Vec2>(geom->frame.toLocal(*h)) : std::nullopt);
    }
    const std::optional<geo::Vec2> landing =
        m.landing ? std::optional<geo::Vec2>(geom->frame.toLocal(*m.landing)) : std::nullopt;
    // The stretch of line each aircraft flies (all of it for one).
    std::vector<std::vector<geo::Vec2>> lines(n);
    if (n == 1) {
        lines[0] = line;
    } else {
        std::vector<std::size_t> order(n);
        std::iota(order.begin(), order.end(), 0);
        auto split = balance(m, *geom, line, order, homes, landing);
        if (!split)
            return split.error();
        std::vector<std::size_t> reversedOrder(order.rbegin(), order.rend());
        if (split->spread() > 1.03) {
            auto other = balance(m, *geom, line, reversedOrder, homes, landing);
            if (!other)
                return other.error();
            if (other->makespan() < split->makespan()) {
                split = std::move(other);
                order = reversedOrder;
            }
        }
        const double length = plan::lineLength(line);
        for (std::size_t i = 0; i < n; ++i)
            lines[order[i]] = plan::subLine(line, i == 0 ? 0.0 : split->cuts[i - 1],
                                            i + 1 == n ? length : split->cuts[i]);
    }
    std::vector<geo::MultiPolygon> regions;
    for (const auto& l : lines)
        regions.push_back(n == 1 ? geo::MultiPolygon{geom->area}
                                 : plan::corridorGround(l, m.corridor->widthM));
    const RegionPlanner planner = [&](std::size_t k, const geo::MultiPolygon&) {
        return planCorridorStretch(lines[k], m.corridor->widthM, geom->noFly, m.aircraft[k],
                                   m.options, geom->frame, homes[k], landing);
    };
    auto out = buildPlan(m, m.options, *geom, regions, homes, landing, true, nullptr, planner);
    if (!out)
        return out;
    std::string choice;
    for (const auto& a : out->aircraft)
        choice += std::string(choice.empty() ? "" : "; ") + (n > 1 ? a.aircraft + ": " : "") +
                  a.plannerChoice;
    out->plannerChoice = choice;
    return out;
}

} // namespace pf::mission
