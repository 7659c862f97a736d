#include "core/fleet/photo_dedup.h"

#include "core/geo/box_buckets.h"
#include "core/geo/polygon_ops.h"
#include "core/sensor/footprint.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

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

// The part of the convex ring `in` on the inner side of edge j -> i of the convex ring `b` whose
// orientation is `orient` (+1 counter-clockwise), or on its outer side (`inner` false), into `out`.
void clipByEdge(const geo::Ring& in, geo::Ring& out, const geo::Vec2& p, const geo::Vec2& d, double orient, bool inner) {
    const double s = inner ? orient : -orient;
    const auto side = [&](const geo::Vec2& q) { return s * (d.x() * (q.y() - p.y()) - d.y() * (q.x() - p.x())); };
    out.clear();
    for (std::size_t k = 0, l = in.size() - 1; k < in.size(); l = k++) {
        const double sl = side(in[l]), sk = side(in[k]);
        if ((sl >= 0) != (sk >= 0))
            out.push_back(in[l] + (sl / (sl - sk)) * (in[k] - in[l]));
        if (sk >= 0)
            out.push_back(in[k]);
    }
}

// The area of the intersection of two convex rings (Sutherland-Hodgman: `a` clipped by each edge
// of `b`). The footprints are rectangles, so this is exact up to rounding.
double convexOverlapArea(const geo::Ring& a, const geo::Ring& b) {
    const double orient = geo::signedArea(b) >= 0 ? 1.0 : -1.0;
    geo::Ring cur = a, next;
    for (std::size_t i = 0, j = b.size() - 1; i < b.size() && !cur.empty(); j = i++) {
        clipByEdge(cur, next, b[j], b[i] - b[j], orient, true);
        std::swap(cur, next);
    }
    return cur.size() < 3 ? 0.0 : std::abs(geo::signedArea(cur));
}

// The area of the convex ring `a` that none of the convex rings `covers` sees: `a` minus each cover
// in turn, what is left kept as convex pieces (a piece minus a convex ring is its parts outside
// each of the ring's edges, one after the other). Slivers below `ignore` m2 are dropped. Empty when
// the pieces grow past a bound (the caller then asks GEOS).
std::optional<double> uncoveredArea(const geo::Ring& a, const std::vector<const geo::Ring*>& covers, double ignore) {
    constexpr std::size_t kMaxPieces = 256;
    std::vector<geo::Ring> pieces{a}, next;
    geo::Ring rest, part, tmp;
    for (const geo::Ring* c : covers) {
        const geo::Ring& b = *c;
        const double orient = geo::signedArea(b) >= 0 ? 1.0 : -1.0;
        next.clear();
        for (const geo::Ring& piece : pieces) {
            rest = piece;
            for (std::size_t i = 0, j = b.size() - 1; i < b.size() && rest.size() >= 3; j = i++) {
                clipByEdge(rest, part, b[j], b[i] - b[j], orient, false);
                if (part.size() >= 3 && std::abs(geo::signedArea(part)) > ignore)
                    next.push_back(part);
                clipByEdge(rest, tmp, b[j], b[i] - b[j], orient, true);
                std::swap(rest, tmp);
            }
        }
        if (next.size() > kMaxPieces)
            return std::nullopt;
        std::swap(pieces, next);
        if (pieces.empty())
            return 0.0;
    }
    double sum = 0;
    for (const auto& piece : pieces)
        sum += std::abs(geo::signedArea(piece));
    return sum;
}

// Whether every corner of `a` lies inside the convex ring `b` (within `tol` metres of its edges).
bool convexContains(const geo::Ring& b, const geo::Ring& a, double tol) {
    const double orient = geo::signedArea(b) >= 0 ? 1.0 : -1.0;
    for (std::size_t i = 0, j = b.size() - 1; i < b.size(); j = i++) {
        const geo::Vec2 p = b[j], d = b[i] - b[j];
        const double len = d.norm();
        for (const auto& q : a)
            if (orient * (d.x() * (q.y() - p.y()) - d.y() * (q.x() - p.x())) < -tol * len)
                return false;
    }
    return true;
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
            // Exact tests, cheapest first: inside one photo of the neighbour, it is covered; if the
            // overlaps with the neighbours' photos do not even add up to the photo's area, it is
            // not; otherwise what the neighbours leave of it is measured piece by piece (convex
            // rectangles), with GEOS's difference only should the pieces multiply.
            const bool inOne = std::any_of(cover.begin(), cover.end(),
                                           [&](const geo::Polygon& c) { return convexContains(c.outer, eff.outer, 1e-9); });
            if (!inOne) {
                double overlaps = 0;
                for (const auto& c : cover)
                    overlaps += convexOverlapArea(eff.outer, c.outer);
                if (overlaps < (1.0 - 1e-5) * effArea)
                    continue;
                std::vector<const geo::Ring*> rings;
                for (const auto& c : cover)
                    rings.push_back(&c.outer);
                const std::optional<double> left = uncoveredArea(eff.outer, rings, 1e-9 * effArea);
                if ((left ? *left : geo::area(geo::difference(eff, cover))) > 1e-6 * effArea)
                    continue;
            }
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
