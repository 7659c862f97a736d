#include "core/plan/sweep/sweep_reach.h"

#include "core/geo/box_buckets.h"
#include "core/geo/polygon_ops.h"
#include "core/plan/coverage_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace pf::plan::sweep_detail {

namespace {

std::string fmt0(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
}

} // namespace

Vec2 interiorPoint(const geo::Polygon& poly) {
    const geo::Box b = geo::bounds(poly);
    Vec2 best = 0.5 * (b.min + b.max);
    double bestW = -1.0;
    for (double f : {0.5, 0.37, 0.63, 0.21, 0.79}) {
        const double y = b.min.y() + f * (b.max.y() - b.min.y());
        std::vector<double> xs;
        auto ring = [&](const geo::Ring& r) {
            for (std::size_t i = 0; i < r.size(); ++i) {
                const Vec2 &p = r[i], &q = r[(i + 1) % r.size()];
                if ((p.y() > y) != (q.y() > y))
                    xs.push_back(p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y()));
            }
        };
        ring(poly.outer);
        for (const auto& h : poly.holes)
            ring(h);
        std::sort(xs.begin(), xs.end());
        for (std::size_t i = 0; i + 1 < xs.size(); i += 2)
            if (xs[i + 1] - xs[i] > bestW) {
                bestW = xs[i + 1] - xs[i];
                best = Vec2(0.5 * (xs[i] + xs[i + 1]), y);
            }
        if (bestW > 0)
            break;
    }
    return best;
}

Pockets::Pockets(const geo::MultiPolygon& grown) {
    for (const auto& g : grown)
        for (const auto& h : g.holes)
            m_holes.push_back(geo::Polygon{h, {}});
    for (const auto& h : m_holes)
        m_areas.push_back(geo::area(h));
}

int Pockets::of(const Vec2& p) const {
    int best = -1;
    for (std::size_t i = 0; i < m_holes.size(); ++i)
        if (geo::contains(m_holes[i], p) && (best < 0 || m_areas[i] < m_areas[static_cast<std::size_t>(best)]))
            best = static_cast<int>(i);
    return best;
}

void reportUnseenGround(const geo::MultiPolygon& ground, const std::vector<geo::Polygon>& noFly,
                        const geo::MultiPolygon& grown, const geo::MultiPolygon& freeSpace, const Pockets& pockets,
                        int anchor, double realAcross, double realAlong, SweepPlan& plan) {
    std::vector<int> pocketIds;
    geo::MultiPolygon reachableFree;
    for (const auto& f : freeSpace) {
        const int id = pockets.of(interiorPoint(f));
        if (id == anchor)
            reachableFree.push_back(f);
        else if (std::find(pocketIds.begin(), pocketIds.end(), id) == pocketIds.end())
            pocketIds.push_back(id);
    }
    // Convex zones each alone in its grown piece hide no ground from the footprints.
    bool hiding = !pocketIds.empty();
    for (const auto& g : grown) {
        int inside = 0;
        for (const auto& z : noFly)
            if (!z.outer.empty() && geo::contains(g, z.outer.front()))
                ++inside;
        hiding = hiding || inside != 1 || !g.holes.empty();
    }
    for (const auto& z : noFly) {
        const std::size_t n = z.outer.size();
        int pos = 0, neg = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2 a = z.outer[(i + 1) % n] - z.outer[i], b = z.outer[(i + 2) % n] - z.outer[(i + 1) % n];
            const double c = a.x() * b.y() - a.y() * b.x();
            pos += c > 1e-9;
            neg += c < -1e-9;
        }
        hiding = hiding || (pos > 0 && neg > 0) || !z.holes.empty();
    }
    if (hiding) {
        // Candidates: ground farther from the reachable free space than half the footprint's short
        // side; what the plan's photos leave of them, by the independent coverage check.
        const double reach = 0.5 * std::min(realAcross, realAlong);
        const geo::MultiPolygon far = geo::difference(ground, geo::buffer(reachableFree, reach, 4));
        double left = 0.0;
        if (!far.empty()) {
            const geo::Box fb = geo::bounds(far);
            const double pad = 0.5 * std::hypot(realAcross, realAlong);
            std::vector<PhotoFootprint> near;
            for (const auto& l : plan.lanes)
                for (const auto& p : l.photos)
                    if (p.x() > fb.min.x() - pad && p.x() < fb.max.x() + pad && p.y() > fb.min.y() - pad &&
                        p.y() < fb.max.y() + pad)
                        near.push_back(PhotoFootprint{p, l.headingDeg, realAcross, realAlong});
            CoverageCheckOptions co;
            co.resolutionM = std::min(0.5, 0.05 * std::min(realAcross, realAlong));
            co.maxPixels = 2'000'000;
            auto cov = checkCoverage(far, near, co);
            left = cov.ok() ? cov->uncoveredAreaM2 : geo::area(far);
        }
        plan.stats.unreachablePockets = static_cast<int>(pocketIds.size());
        plan.stats.unreachableAreaM2 = left;
        if (left >= 1.0 || !pocketIds.empty())
            plan.warnings.push_back(
                "About " + fmt0(left) + " m2 of ground between no-fly zones" +
                (pocketIds.empty() ? std::string()
                                   : " (" + std::to_string(pocketIds.size()) +
                                         (pocketIds.size() == 1 ? " pocket" : " pockets") + " no safe path reaches)") +
                " lies beyond the footprint's reach from anywhere the aircraft may fly without entering a "
                "safety margin: it stays unphotographed; everything else is covered.");
    }
}

void addSpotPhotos(SweepPlan& plan, const geo::MultiPolygon& ground, const std::vector<geo::Polygon>& noFly,
                   const geo::NoFlyField& field, const geo::MultiPolygon& grown, const SweepGround& sweepGround,
                   const geo::MultiPolygon& flyOver, const Pockets& pockets, int anchor, Router& router, const SpotPhotoOptions& options,
                   const FlightTimeModel& time, const std::optional<Vec2>& home, const std::optional<Vec2>& landing) {
    // The lanes leave ground unseen only round the zones (their margins, pockets and notches): each
    // piece of ground within two footprints' reach of a grown zone is checked on its own, with the
    // photos that reach it, so that the check grows with the zones, not with the area.
    if (noFly.empty() || grown.empty())
        return;
    const double reach = 0.5 * std::hypot(options.realAcrossM, options.realAlongM);
    // Outside the grown zones is outside every margin (their polygons circumscribe it); the exact
    // check is kept for the photos chosen.
    auto mayFlyAt = [&](const Vec2& p) {
        return !sweepGround.inGrown(p) && geo::contains(flyOver, p) && pockets.of(p) == anchor;
    };
    struct Piece {
        geo::MultiPolygon near;
        geo::Box reached;                            // its box grown by a footprint's reach
        std::vector<sensor::PhotoFootprint> seeing;  // the photos whose footprint may reach it
        std::vector<std::pair<Vec2, Vec2>> legs;     // the legs flown near it
    };
    std::vector<Piece> pieces;
    // One pass over the photos and the legs, each given to the pieces whose box (grown by the reach
    // and, for the legs, by two more) it meets: the stage grows with the plan, not with the plan
    // times the zones.
    geo::BoxBuckets photoBoxes(8.0 * reach), legBoxes(8.0 * reach);
    auto grow = [](geo::Box b, double d) {
        b.min -= Vec2(d, d);
        b.max += Vec2(d, d);
        return b;
    };
    for (const auto& piece : geo::buffer(grown, 2.0 * reach, 2)) {
        geo::MultiPolygon near = geo::intersection(ground, piece);
        if (near.empty())
            continue;
        const geo::Box b = geo::bounds(near);
        photoBoxes.insert(static_cast<int>(pieces.size()), grow(b, reach));
        legBoxes.insert(static_cast<int>(pieces.size()), grow(b, 3.0 * reach));
        pieces.push_back(Piece{std::move(near), grow(b, reach), {}, {}});
    }
    for (const auto& l : plan.lanes)
        for (const auto& p : l.photos)
            for (int id : photoBoxes.query(geo::Box{p, p}))
                if (pieces[static_cast<std::size_t>(id)].reached.contains(p))
                    pieces[static_cast<std::size_t>(id)].seeing.push_back(
                        sensor::PhotoFootprint{p, l.headingDeg, options.realAcrossM, options.realAlongM});
    const std::vector<Vec2> flight = sweepFlightPath(plan, home, landing, true);
    for (std::size_t k = 0; k + 1 < flight.size(); ++k) {
        const Vec2 &a = flight[k], &c = flight[k + 1];
        const geo::Box lb{a.cwiseMin(c), a.cwiseMax(c)};
        for (int id : legBoxes.query(lb))
            pieces[static_cast<std::size_t>(id)].legs.emplace_back(a, c);
    }
    std::vector<SpotPhoto> spots;
    for (const Piece& piece : pieces) {
        SpotPhotoOptions o = options;
        o.maxPhotos = options.maxPhotos - static_cast<int>(spots.size());
        if (o.maxPhotos <= 0)
            break;
        auto choice = chooseSpotPhotos(piece.near, piece.seeing, mayFlyAt, o, piece.legs);
        if (choice.ok())
            for (const auto& sp : choice->photos)
                if (field.pointIsSafe(sp.pos))
                    spots.push_back(sp);
    }
    if (spots.empty())
        return;
    SpotRouting sr;
    sr.add = [&router](const Vec2& p, const Vec2& in) { return router.add(EndPoint{p, in}); };
    sr.timeS = [&router](int a, int b) { return router.timeS(a, b); };
    sr.way = [&router](int a, int b) { return router.route(a, b).mid; };
    plan.stats.spotPhotos = placeSpotPhotos(plan.lanes, plan.links, plan.homeLink, plan.landingLink, plan.laneCells,
                                            spots, home, landing, sr);
    FlightTimeAccumulator acc(time);
    for (const auto& p : sweepFlightPath(plan, home, landing, true))
        acc.add(p);
    plan.time = acc.result();
}

} // namespace pf::plan::sweep_detail
