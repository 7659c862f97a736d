#include "core/plan/corridor/corridor_planner.h"

#include "core/geo/no_fly_field.h"
#include "core/geo/polygon_ops.h"
#include "core/job_scope.h"
#include "core/plan/corridor/corridor_order.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pf::plan {

namespace {

using geo::Vec2;
using namespace corridor_detail;

bool positive(double v) {
    return std::isfinite(v) && v > 0;
}

Status checkOptions(const Polyline& line, const CorridorOptions& o) {
    if (!positive(o.widthM))
        return makeError(ErrorCode::InvalidInput,
                         "the corridor's width must be a positive number of metres");
    if (!positive(o.trackSpacingM) || !positive(o.photoSpacingM))
        return makeError(ErrorCode::InvalidInput, "the track and photo spacings must be positive");
    if (!std::isfinite(o.safetyMarginM) || o.safetyMarginM < 0)
        return makeError(ErrorCode::InvalidInput, "the safety margin must be zero or more metres");
    if (!positive(o.time.speedMps) || !positive(o.time.turnRateDegS))
        return makeError(ErrorCode::InvalidInput,
                         "the aircraft's speed and turn rate must be positive");
    if (line.size() < 2)
        return makeError(ErrorCode::InvalidGeometry,
                         "the corridor's line needs at least two distinct points");
    return {};
}

// The zones grown by a little more than the margin, as polygons: lanes are cut where they enter
// one. The extra (1 % and 5 cm) keeps the polygon, whose edges are chords of the margin's circles,
// outside the margin everywhere.
geo::MultiPolygon grownZones(const std::vector<geo::Polygon>& noFly, double marginM) {
    if (noFly.empty())
        return {};
    geo::MultiPolygon grown;
    for (const auto& z : noFly) {
        const geo::MultiPolygon g = geo::buffer(z, 1.01 * marginM + 0.05, 8);
        grown.insert(grown.end(), g.begin(), g.end());
    }
    return geo::unite(grown);
}

// Every lane's runs, and the stations where zones cut lanes (merged).
struct Lanes {
    std::vector<CorridorRun> runs;
    std::vector<std::pair<double, double>> cuts;
    int count = 0;
};

Lanes buildLanes(const Polyline& line, const geo::MultiPolygon& blocked, const CorridorOptions& o) {
    Lanes out;
    const int k = laneCount(o.widthM, o.trackSpacingM);
    out.count = k;
    const double tol = o.arcToleranceM > 0 ? o.arcToleranceM : 0.25 * o.trackSpacingM;
    for (int j = 0; j < k && !stopRequested(); ++j) {
        const OffsetLine lane = offsetLine(
            line, laneOffsets(o.widthM, o.trackSpacingM, k)[static_cast<std::size_t>(j)], tol);
        if (lane.points.size() < 2)
            continue;
        const std::vector<Interval> cut = blockedIntervals(lane.points, blocked);
        std::vector<double> along{0.0};
        for (std::size_t i = 1; i < lane.points.size(); ++i)
            along.push_back(along.back() + (lane.points[i] - lane.points[i - 1]).norm());
        for (const auto& [a, b] : cut) {
            const auto station = [&](double x) {
                const auto it = std::upper_bound(along.begin(), along.end(), x);
                const std::size_t i = std::min<std::size_t>(
                    it == along.begin() ? 0 : it - along.begin() - 1, along.size() - 2);
                const double span = along[i + 1] - along[i];
                const double f = span > 0 ? std::clamp((x - along[i]) / span, 0.0, 1.0) : 0.0;
                return lane.stations[i] + f * (lane.stations[i + 1] - lane.stations[i]);
            };
            out.cuts.push_back({station(a), station(b)});
        }
        auto runs = laneRuns(lane, j, lanePhotos(lane, o.photoSpacingM, o.trackSpacingM), cut);
        out.runs.insert(out.runs.end(), runs.begin(), runs.end());
    }
    std::sort(out.cuts.begin(), out.cuts.end());
    std::vector<std::pair<double, double>> merged;
    for (const auto& c : out.cuts) {
        if (!merged.empty() && c.first <= merged.back().second)
            merged.back().second = std::max(merged.back().second, c.second);
        else
            merged.push_back(c);
    }
    out.cuts = std::move(merged);
    return out;
}

// Runs whose way in has no safe path are left out (ground enclosed by zones whose margins merge):
// the order is chosen again without them. Errors: no safe way between home and the corridor.
Result<FlightOrder> orderReachable(OrderInput in, CorridorStats& stats,
                                   std::vector<std::string>& warnings) {
    FlightOrder order = chooseOrder(in);
    int dropped = 0, photos = 0;
    while (!std::isfinite(order.timeS) && !in.runs.empty()) {
        // The first run of the order whose way in (from home or from the run before) fails.
        std::size_t bad = order.runs.size();
        std::optional<Vec2> from = in.home;
        for (std::size_t i = 0; i < order.runs.size(); ++i) {
            if (from && !in.link(*from, order.runs[i].points.front().pos)) {
                bad = i;
                break;
            }
            from = order.runs[i].points.back().pos;
        }
        if (bad == order.runs.size() || order.runs.empty())
            break;
        const CorridorRun& r = order.runs[bad];
        const double s0 = std::min(r.firstStation(), r.lastStation()),
                     s1 = std::max(r.firstStation(), r.lastStation());
        const auto same = [&](const CorridorRun& x) {
            return x.lane == r.lane && std::min(x.firstStation(), x.lastStation()) <= s1 + 1e-6 &&
                   std::max(x.firstStation(), x.lastStation()) >= s0 - 1e-6;
        };
        const auto it = std::find_if(in.runs.begin(), in.runs.end(), same);
        if (it == in.runs.end())
            break;
        photos += static_cast<int>(std::count_if(it->points.begin(), it->points.end(),
                                                 [](const auto& p) { return p.photo; }));
        in.runs.erase(it);
        ++dropped;
        order = chooseOrder(in);
    }
    stats.droppedRuns = dropped;
    if (!std::isfinite(order.timeS))
        return makeError(ErrorCode::NoPath,
                         "no safe way leads from home to the corridor and back: the no-fly "
                         "zones' margins enclose one of them");
    if (dropped > 0) {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "%d stretch(es) of the corridor's lanes (%d photos) lie where no safe path "
                      "leads (ground enclosed "
                      "by no-fly margins): they are not flown",
                      dropped, photos);
        warnings.push_back(buf);
    }
    return order;
}

} // namespace

Result<CorridorPlan> planCorridor(const Polyline& raw, const std::vector<geo::Polygon>& noFly,
                                  const CorridorOptions& o) {
    const Polyline line = cleanLine(raw);
    if (auto ok = checkOptions(line, o); !ok)
        return ok.error();
    const geo::NoFlyField field(noFly, o.safetyMarginM);
    if (o.home && !field.pointIsSafe(*o.home))
        return makeError(ErrorCode::InvalidInput,
                         "the home point lies within a no-fly zone's safety margin");
    if (o.landing && !field.pointIsSafe(*o.landing))
        return makeError(ErrorCode::InvalidInput,
                         "the landing point lies within a no-fly zone's safety margin");
    reportProgress(0.0, "corridor lanes");
    const Lanes lanes = buildLanes(line, grownZones(noFly, o.safetyMarginM), o);
    if (stopRequested())
        return makeError(ErrorCode::Cancelled, "planning cancelled");
    const geo::SafePathFinder finder(field);
    OrderInput in;
    in.runs = lanes.runs;
    in.lanes = lanes.count;
    in.cuts = lanes.cuts;
    in.home = o.home;
    in.landing = o.landing;
    in.time = o.time;
    in.link = [&finder](const Vec2& a, const Vec2& b) -> std::optional<std::vector<Vec2>> {
        auto d = finder.detour(a, b);
        if (!d)
            return std::nullopt;
        return *d;
    };
    reportProgress(0.5, "corridor order");
    CorridorPlan plan;
    auto reached = orderReachable(std::move(in), plan.stats, plan.warnings);
    if (!reached)
        return reached.error();
    FlightOrder& order = *reached;
    if (order.runs.empty())
        return makeError(ErrorCode::InvalidInput,
                         "no part of the corridor can be flown: the no-fly zones and "
                         "their margins cover all of it");
    plan.runs = std::move(order.runs);
    plan.links = std::move(order.links);
    plan.homeLink = std::move(order.homeLink);
    plan.landingLink = std::move(order.landingLink);
    plan.stats.lanes = lanes.count;
    plan.stats.runs = static_cast<int>(plan.runs.size());
    plan.stats.sections = order.sections;
    plan.stats.lengthM = lineLength(line);
    for (const auto& r : plan.runs)
        plan.stats.photos += static_cast<int>(
            std::count_if(r.points.begin(), r.points.end(), [](const auto& p) { return p.photo; }));
    plan.time = flightTime(corridorFlightPath(plan, o.home, o.landing), o.time);
    return plan;
}

std::vector<Vec2> corridorFlightPath(const CorridorPlan& plan, const std::optional<Vec2>& home,
                                     const std::optional<Vec2>& landing) {
    std::vector<Vec2> out;
    if (home)
        out.push_back(*home);
    if (home)
        out.insert(out.end(), plan.homeLink.begin(), plan.homeLink.end());
    for (std::size_t i = 0; i < plan.runs.size(); ++i) {
        if (i > 0 && i - 1 < plan.links.size())
            out.insert(out.end(), plan.links[i - 1].begin(), plan.links[i - 1].end());
        for (const auto& p : plan.runs[i].points)
            out.push_back(p.pos);
    }
    if (home) {
        out.insert(out.end(), plan.landingLink.begin(), plan.landingLink.end());
        out.push_back(landing ? *landing : *home);
    }
    return out;
}

} // namespace pf::plan
