#include "core/plan/sweep_planner.h"

#include "core/geo/no_fly_field.h"
#include "tests/core/plan/sweep_test_util.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace pf;
using namespace pf::plan;
using namespace pf::plan::sweeptest;

TEST(SweepExplore, Table) {
    const char* dir = std::getenv("PF_SWEEP_PICTURES");
    Camera cam;
    const unsigned n = std::getenv("PF_SWEEP_N") ? static_cast<unsigned>(std::atoi(std::getenv("PF_SWEEP_N"))) : 12;
    for (unsigned seed = 1; seed <= n; ++seed) {
        if (const char* only = std::getenv("PF_SWEEP_SEED"))
            if (seed != static_cast<unsigned>(std::atoi(only)))
                continue;
        const int zones = seed % 4 == 0 ? 0 : 10 + static_cast<int>(seed % 6);
        Area a = generateArea(seed, zones);
        SweepOptions o = options(cam);
        if (std::getenv("PF_SWEEP_NOMERGE"))
            o.mergeCells = false;
        if (const char* ang = std::getenv("PF_SWEEP_ANGLE"))
            o.anglesDeg = {std::atof(ang)};
        if (const char* k = std::getenv("PF_SWEEP_K"))
            o.plannedDirections = std::atoi(k);
        auto plan = planSweep(a.region, a.zones, o);
        ASSERT_TRUE(plan.ok()) << a.name << ": " << plan.error().message;
        const auto y = yardstick(a, cam, o.time);
        double unc = 0;
        std::vector<UncoveredPatch> holes;
        const double cov = coverage(a, *plan, cam, &unc, &holes);
        const auto v = countNoFlyViolations({sweepFlightPath(*plan, o.home, o.landing)}, a.zones, o.safetyMarginM);
        std::printf("%-22s time %.0f / %.0f = %.3f  photos %d / %d = %.3f  cov %.4f (%.0f m2, unreach %.0f)  viol %d  cells %d->%d  ang %.1f  lanes %zu turns %d len %.0f est %d plan %d constr %.0f moves %d\n",
                    a.name.c_str(), plan->time.totalS, y.timeS, plan->time.totalS / y.timeS, photoCount(*plan),
                    y.photosOutsideZones, double(photoCount(*plan)) / y.photosOutsideZones, cov, unc, plan->stats.unreachableAreaM2, v.total(),
                    plan->stats.cellsBeforeMerge, plan->stats.cellsAfterMerge, plan->stats.angleDeg, plan->lanes.size(),
                    plan->time.turns, plan->time.lengthM, plan->stats.directionsEstimated, plan->stats.directionsPlanned,
                    plan->stats.constructedTimeS, plan->stats.orderMoves);
        if (std::getenv("PF_SWEEP_DETAIL")) {
            double laneS = 0, linkS = 0, stripM = 0, spanM = 0;
            int bigLinks = 0;
            double bigLinkS = 0;
            for (std::size_t i = 0; i < plan->lanes.size(); ++i) {
                const auto& l = plan->lanes[i];
                laneS += (l.photos.back() - l.photos.front()).norm() / o.time.speedMps;
                stripM += (l.stripEnd - l.stripStart).norm();
                spanM += (l.photos.back() - l.photos.front()).norm();
                if (i + 1 < plan->lanes.size()) {
                    std::vector<geo::Vec2> pts{l.photos.back() - (l.photos.back() - l.photos.front()).normalized()};
                    pts.push_back(l.photos.back());
                    pts.insert(pts.end(), plan->links[i].begin(), plan->links[i].end());
                    const auto& n = plan->lanes[i + 1];
                    pts.push_back(n.photos.front());
                    if (n.photos.size() > 1)
                        pts.push_back(n.photos.front() + (n.photos[1] - n.photos.front()).normalized());
                    const double t = flightTime(pts, o.time).totalS - 2.0 / o.time.speedMps - o.time.stopCostS();
                    linkS += t;
                    if (t > 16) {
                        ++bigLinks;
                        bigLinkS += t;
                    }
                }
            }
            std::printf("    lanes %.0f s, links %.0f s (%d dear ones: %.0f s), strips %.0f m, flown %.0f m, photos/strip %.3f\n", laneS,
                        linkS, bigLinks, bigLinkS, stripM, spanM, photoCount(*plan) / (stripM / o.photoSpacingM));
        }
        if (std::getenv("PF_SWEEP_DETAIL"))
            std::printf("    yardstick angle %.1f photos %d\n", y.angleDeg, y.photos);
        if (std::getenv("PF_SWEEP_HOLES"))
            for (const auto& h : holes)
                if (h.areaM2 > 10)
                    std::printf("    hole %.0f m2 at (%.0f, %.0f)\n", h.areaM2, h.centroid.x(), h.centroid.y());
        if (dir)
            writeGeoJson(std::string(dir) + "/" + a.name + ".geojson", a, *plan, o, holes);
    }
}
