#include "core/fleet/photo_dedup.h"

#include "core/geo/box_buckets.h"
#include "core/geo/polygon_ops.h"
#include "core/sensor/footprint.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pf::fleet {

namespace {

struct Photo {
    int aircraft;
    int index;
    geo::Polygon real;
    geo::Box box;
};

bool straightThrough(const geo::Vec2& a, const geo::Vec2& b, const geo::Vec2& c) {
    const geo::Vec2 u = b - a, v = c - b;
    const double cr = u.x() * v.y() - u.y() * v.x();
    return std::abs(cr) <= 1e-6 * u.norm() * v.norm() && u.dot(v) >= 0;
}

} // namespace

Result<DedupReport> dropDuplicatePhotos(std::vector<AircraftPhotos>& fleet) {
    DedupReport rep;
    rep.photosSaved.assign(fleet.size(), 0);
    double maxSide = 0;
    for (std::size_t k = 0; k < fleet.size(); ++k) {
        const auto& f = fleet[k];
        if (!(f.effectiveAcrossM > 0) || !(f.effectiveAlongM > 0) || !(f.realAcrossM > 0) || !(f.realAlongM > 0))
            return makeError(ErrorCode::InvalidInput,
                             "Aircraft " + std::to_string(k + 1) + " has a photo footprint side that is not positive.");
        maxSide = std::max({maxSide, f.realAcrossM, f.realAlongM});
    }
    if (fleet.size() < 2)
        return rep;

    std::vector<Photo> photos;
    std::vector<std::vector<int>> idOf(fleet.size());
    geo::BoxBuckets buckets(maxSide);
    for (std::size_t k = 0; k < fleet.size(); ++k) {
        idOf[k].assign(fleet[k].waypoints.size(), -1);
        for (std::size_t i = 0; i < fleet[k].waypoints.size(); ++i) {
            const auto& w = fleet[k].waypoints[i];
            if (w.kind != route::WaypointKind::Photo)
                continue;
            Photo p{static_cast<int>(k), static_cast<int>(i),
                    geo::Polygon{sensor::footprintRing({w.pos, w.headingDeg, fleet[k].realAcrossM, fleet[k].realAlongM}), {}},
                    {}};
            p.box = geo::bounds(p.real);
            idOf[k][i] = static_cast<int>(photos.size());
            buckets.insert(static_cast<int>(photos.size()), p.box);
            photos.push_back(std::move(p));
        }
    }
    std::vector<char> kept(photos.size(), 1), pinned(photos.size(), 0);

    std::vector<std::size_t> order(fleet.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return fleet[a].effectiveAcrossM * fleet[a].effectiveAlongM < fleet[b].effectiveAcrossM * fleet[b].effectiveAlongM;
    });
    for (std::size_t k : order) {
        for (std::size_t i = 0; i < fleet[k].waypoints.size(); ++i) {
            const int id = idOf[k][i];
            if (id < 0 || pinned[static_cast<std::size_t>(id)])
                continue;
            const auto& w = fleet[k].waypoints[i];
            const geo::Polygon eff{
                sensor::footprintRing({w.pos, w.headingDeg, fleet[k].effectiveAcrossM, fleet[k].effectiveAlongM}), {}};
            const geo::Box effBox = geo::bounds(eff);
            geo::MultiPolygon cover;
            std::vector<int> coverIds;
            for (int c : buckets.query(effBox)) {
                const auto& p = photos[static_cast<std::size_t>(c)];
                if (p.aircraft == static_cast<int>(k) || !kept[static_cast<std::size_t>(c)] || !p.box.intersects(effBox))
                    continue;
                cover.push_back(p.real);
                coverIds.push_back(c);
            }
            if (cover.empty())
                continue;
            const double effArea = fleet[k].effectiveAcrossM * fleet[k].effectiveAlongM;
            if (geo::area(geo::difference(eff, cover)) > 1e-6 * effArea)
                continue;
            kept[static_cast<std::size_t>(id)] = 0;
            for (int c : coverIds)
                pinned[static_cast<std::size_t>(c)] = 1;
            ++rep.photosSaved[k];
            ++rep.totalSaved;
        }
    }

    // Rewrite each route without the dropped photos.
    for (std::size_t k = 0; k < fleet.size(); ++k) {
        auto& wps = fleet[k].waypoints;
        std::vector<char> dropped(wps.size(), 0);
        for (std::size_t i = 0; i < wps.size(); ++i)
            dropped[i] = idOf[k][i] >= 0 && !kept[static_cast<std::size_t>(idOf[k][i])];
        std::vector<route::LocalWaypoint> out;
        for (std::size_t i = 0; i < wps.size(); ++i) {
            if (!dropped[i]) {
                out.push_back(wps[i]);
                continue;
            }
            const bool interior = !out.empty() && i + 1 < wps.size();
            if (interior && straightThrough(out.back().pos, wps[i].pos, wps[i + 1].pos))
                continue; // the path runs straight through: the waypoint adds nothing
            auto turn = wps[i];
            turn.kind = route::WaypointKind::Turn;
            out.push_back(turn);
        }
        // Nothing to photograph before the first kept photo or after the last: do not fly there.
        const auto isPhoto = [](const route::LocalWaypoint& w) { return w.kind == route::WaypointKind::Photo; };
        const auto first = std::find_if(out.begin(), out.end(), isPhoto);
        if (first == out.end()) {
            if (rep.photosSaved[k] > 0)
                out.clear();
        } else {
            const auto last = std::find_if(out.rbegin(), out.rend(), isPhoto).base();
            if (rep.photosSaved[k] > 0)
                out = std::vector<route::LocalWaypoint>(first, last);
        }
        wps = std::move(out);
    }
    return rep;
}

} // namespace pf::fleet
