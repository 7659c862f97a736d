#include "core/mission/double_grid.h"

#include "core/job_scope.h"
#include "core/mission/plan_region.h"
#include "core/mission/planner_kinds.h"
#include "core/route/photo_waypoints.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace pf::mission {

namespace {

bool facesALane(const route::LocalWaypoint& w) {
    return w.kind == route::WaypointKind::Photo || w.kind == route::WaypointKind::Turn;
}

std::string degrees(double a) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", a);
    return buf;
}

// The second pass after the first: as planned, or flown from its other end, whichever brings the
// aircraft home sooner.
std::vector<route::LocalWaypoint> joined(const std::vector<route::LocalWaypoint>& first,
                                         std::vector<route::LocalWaypoint> second,
                                         const AircraftConfig& a,
                                         const std::optional<geo::Vec2>& home,
                                         const std::optional<geo::Vec2>& landing) {
    for (auto& w : second)
        w.pass = 1;
    std::vector<route::LocalWaypoint> forward = first, backward = first;
    forward.insert(forward.end(), second.begin(), second.end());
    const auto rev = reversedFlight(std::move(second));
    backward.insert(backward.end(), rev.begin(), rev.end());
    return aloneRouteTimeS(backward, a, home, landing) < aloneRouteTimeS(forward, a, home, landing)
               ? backward
               : forward;
}

} // namespace

double dominantLaneAngleDeg(const std::vector<route::LocalWaypoint>& w) {
    // Photo headings (clockwise from north) folded onto lane directions (counter-clockwise from
    // east, [0, 180)) in whole degrees; the most frequent wins.
    std::array<int, 180> votes{};
    for (const auto& p : w) {
        if (p.kind != route::WaypointKind::Photo)
            continue;
        double a = std::fmod(90.0 - p.headingDeg, 180.0);
        if (a < 0)
            a += 180.0;
        ++votes[static_cast<std::size_t>(std::lround(a)) % 180];
    }
    return static_cast<double>(std::max_element(votes.begin(), votes.end()) - votes.begin());
}

std::vector<route::LocalWaypoint> reversedFlight(std::vector<route::LocalWaypoint> w) {
    std::reverse(w.begin(), w.end());
    for (std::size_t i = 0; i < w.size(); ++i) {
        if (facesALane(w[i]))
            w[i].headingDeg = std::fmod(w[i].headingDeg + 180.0, 360.0);
        else if (i + 1 < w.size())
            w[i].headingDeg = route::headingDeg(w[i + 1].pos - w[i].pos);
    }
    return w;
}

Result<AircraftPlan>
planDoubleGrid(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
               const AircraftConfig& aircraft, const PlannerOptions& options,
               const std::optional<geo::Vec2>& home,
               const std::optional<geo::Vec2>& landing, const route::LaneSpacingFn& laneSpacing) {
    PlannerOptions single = options;
    single.doubleGrid = false;
    JobScope firstHalf(0.0, 0.5);
    auto first = planRegion(region, noFly, aircraft, single, home, landing, laneSpacing);
    if (!first)
        return first;
    // The second pass: straight lanes across the first's.
    const double across = std::fmod(dominantLaneAngleDeg(first->localWaypoints) + 90.0, 180.0);
    PlannerOptions crossing = single;
    crossing.planner =
        first->planner == PlannerKind::Lawnmower ? PlannerKind::Lawnmower : PlannerKind::Sweep;
    crossing.gridAngleDeg = across;
    JobScope secondHalf(0.5, 1.0);
    auto second = planRegion(region, noFly, aircraft, crossing, home, landing, laneSpacing);
    if (!second)
        return second;
    AircraftPlan p = std::move(*first);
    const int firstPhotos = p.metrics.photos;
    const std::string firstChoice =
        p.plannerChoice.empty() ? plannerKindInfo(p.planner).id : p.plannerChoice;
    p.localWaypoints = joined(surveyPart(p.localWaypoints), surveyPart(second->localWaypoints),
                              aircraft, home, landing);
    routeMetrics(p, flightModel(aircraft));
    p.metrics.photos = firstPhotos + second->metrics.photos;
    p.warnings.insert(p.warnings.end(), second->warnings.begin(), second->warnings.end());
    p.anglesTried += second->anglesTried;
    p.plannerChoice = "double grid: " + firstChoice + ", then " +
                      plannerKindInfo(crossing.planner).id + " at " + degrees(across) +
                      " degrees, across its lanes";
    return p;
}

Result<fleet::DedupReport> dropDuplicatePhotosPerPass(std::vector<fleet::AircraftPhotos>& fleet) {
    fleet::DedupReport total;
    total.photosSaved.assign(fleet.size(), 0);
    std::vector<std::vector<route::LocalWaypoint>> kept(fleet.size());
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<fleet::AircraftPhotos> these = fleet;
        for (auto& a : these)
            a.waypoints.erase(
                std::remove_if(a.waypoints.begin(), a.waypoints.end(),
                               [pass](const route::LocalWaypoint& w) { return w.pass != pass; }),
                a.waypoints.end());
        auto r = fleet::dropDuplicatePhotos(these);
        if (!r)
            return r.error();
        for (std::size_t k = 0; k < fleet.size(); ++k) {
            kept[k].insert(kept[k].end(), these[k].waypoints.begin(), these[k].waypoints.end());
            total.photosSaved[k] += r->photosSaved[k];
        }
        total.totalSaved += r->totalSaved;
    }
    for (std::size_t k = 0; k < fleet.size(); ++k)
        fleet[k].waypoints = std::move(kept[k]);
    return total;
}

Result<plan::CoverageReport> checkPassCoverage(const geo::MultiPolygon& admissible,
                                               const std::vector<plan::PhotoFootprint>& photos,
                                               const std::vector<int>& passes,
                                               const std::vector<geo::Ring>* outlines,
                                               std::vector<double>& perPass) {
    perPass.clear();
    std::optional<plan::CoverageReport> worst;
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<plan::PhotoFootprint> these;
        std::vector<geo::Ring> theirOutlines;
        for (std::size_t i = 0; i < photos.size(); ++i) {
            if (passes[i] != pass)
                continue;
            these.push_back(photos[i]);
            if (outlines && i < outlines->size())
                theirOutlines.push_back((*outlines)[i]);
        }
        auto cov = plan::checkCoverage(admissible, these, {}, outlines ? &theirOutlines : nullptr);
        if (!cov)
            return cov.error();
        perPass.push_back(cov->coveredFraction);
        if (!worst || cov->coveredFraction < worst->coveredFraction)
            worst = std::move(*cov);
    }
    return std::move(*worst);
}

} // namespace pf::mission
