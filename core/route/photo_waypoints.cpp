#include "core/route/photo_waypoints.h"

#include "core/job_scope.h"

#include "core/geo/polygon_ops.h"
#include "core/sensor/footprint.h"
#include "core/route/lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace pf::route {

using geo::Vec2;

PhotosPerCell photosPerCell(double cellSizeM, const sensor::EffectiveFootprint& fp) {
    // A tolerance keeps a cell exactly one footprint long at one photo despite rounding.
    auto count = [cellSizeM](double len) {
        if (len <= 0)
            return 1;
        return std::max(1, static_cast<int>(std::ceil(cellSizeM / len - 1e-9)));
    };
    return {count(fp.alongM), count(fp.acrossM)};
}

double headingDeg(const Vec2& dir) {
    double h = std::atan2(dir.x(), dir.y()) * 180.0 / M_PI;
    if (h < 0)
        h += 360.0;
    if (h >= 360.0)
        h -= 360.0;
    return h;
}

namespace {

// A waypoint before safe placement: where it would go, and the safe point it may slide back to.
struct Slot {
    LocalWaypoint w;  // kind, heading, cell and the planned position
    Vec2 anchor{0, 0}; // the cell's flight position: safe by construction of the grid
    // A lane's first or last photo: the flight positions of the lane's end cells up to its first (last)
    // cell crossed safely by its line, in flight order: the way onto (off) the lane over the cell path's
    // own safe moves when a straight leg onto or off it is unsafe. Empty for other slots.
    std::vector<Vec2> laneIn, laneOut;
};

// Why a slid photo keeps its cell covered. The `along` photos of a cell split it into bands s = cell /
// along long, one per photo, centred on its planned position: together they tile the cell along the
// track (across it the track spacing tiles the area). Ground inside a no-fly zone is not admissible
// area, but ground inside its margin is, and must still be seen: from outside the margin. A photo
// slides back towards the flight position, never past it, so by at most its planned offset
// |a| <= (cell - s) / 2, and it still sees its whole band while its REAL footprint, R long along the
// track, reaches the band's far end: a + s/2 <= (a - d) + R/2 holds for every slide d <= (R - s)/2,
// hence for every slide as soon as R >= cell. The real short side is at least the cell side whenever
// the side overlap is at least 1 - short side / long side (0.25 for a 4:3 sensor), which usual survey
// settings meet; the tests measure the coverage with the independent raster check (plan::checkCoverage).
// Below that, what a band loses lies in the margin ahead of the last safe point of the track, which no
// safe point of this track sees: so the photo gets a companion off the track, at the safe point nearest
// to where it was planned (just outside the margin, beside the lost ground), when that one sees part of
// what is lost. Its legs may have to go round the margin (the no-fly stage's detours fly them); the
// plan's coverage check reports whatever is still unseen. With several photos across the track (overlaps that make the along spacing the longer effective side, so the cell is at most the
// real short side) the line to the flight position also moves a photo across, by at most its offset
// across; the same argument with the real long side, longer than the cell, keeps its band seen.
class Placer {
public:
    explicit Placer(const grid::Grid& g) : m_g(g) {}

    // The position of slot k (prev: where the waypoint before it went, nextAnchor: the flight position of
    // the waypoint after it).
    Vec2 place(const Slot& slot, const Vec2* prev, const Vec2* nextAnchor) const {
        const Vec2 p = slot.anchor, q = slot.w.pos;
        // Legs joined straight at the flight position must stay straight and safe from the slid photo;
        // legs the grid could not join straight (jumps) are the detours' business. Computed lazily: far
        // from every zone the first test below passes without them.
        int prevLeg = -1, nextLeg = -1;
        auto feasible = [&](const Vec2& x) {
            if (!m_g.pointIsSafe(x) || !m_g.segmentIsSafe(p, x))
                return false;
            if (prev && !m_g.segmentIsSafe(*prev, x)) {
                if (prevLeg < 0)
                    prevLeg = m_g.segmentIsSafe(*prev, p) ? 1 : 0;
                if (prevLeg == 1)
                    return false;
            }
            if (nextAnchor && !m_g.segmentIsSafe(x, *nextAnchor)) {
                if (nextLeg < 0)
                    nextLeg = m_g.segmentIsSafe(p, *nextAnchor) ? 1 : 0;
                if (nextLeg == 1)
                    return false;
            }
            return true;
        };
        if ((q - p).squaredNorm() == 0.0 || feasible(q))
            return q;
        // Bisection on the line from p (feasible: safe, with the same legs as the cell's other
        // waypoints) to q: lo stays feasible, to a tenth of a millimetre. Without the legs' conditions
        // feasibility only shrinks along the line, so this finds the last safe point of the track.
        double lo = 0.0, hi = 1.0;
        const double len = (q - p).norm();
        while ((hi - lo) * len > 1e-4) {
            const double mid = 0.5 * (lo + hi);
            (feasible(p + mid * (q - p)) ? lo : hi) = mid;
        }
        return p + lo * (q - p);
    }

    // The point just outside the buffered zones nearest to q (q inside one), if it is safe: where a photo
    // planned at q sees most of the margin ground around q.
    std::optional<Vec2> nearestSafePoint(const Vec2& q) const {
        Vec2 best = q;
        double bestD = std::numeric_limits<double>::infinity();
        auto scan = [&](const geo::Ring& r) {
            for (std::size_t i = 0; i < r.size(); ++i) {
                const Vec2 a = r[i], ab = r[(i + 1) % r.size()] - a;
                const double len2 = ab.squaredNorm();
                const double t = len2 > 0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
                const Vec2 c = a + t * ab;
                if ((c - q).squaredNorm() < bestD) {
                    bestD = (c - q).squaredNorm();
                    best = c;
                }
            }
        };
        for (const auto& z : m_g.bufferedNoFly()) {
            scan(z.outer);
            for (const auto& h : z.holes)
                scan(h);
        }
        if (!std::isfinite(bestD) || bestD == 0.0)
            return std::nullopt;
        // 1 cm further out, so that rounding keeps it outside.
        const Vec2 n = best + 0.01 * (best - q).normalized();
        return m_g.pointIsSafe(n) ? std::optional<Vec2>(n) : std::nullopt;
    }

private:
    const grid::Grid& m_g;
};

geo::Polygon rectangle(const Vec2& centre, double headingDeg, double acrossM, double alongM) {
    return {sensor::footprintRing(sensor::PhotoFootprint{centre, headingDeg, acrossM, alongM}), {}};
}

// The admissible ground of the band of a photo planned at `q` that no photo of its cell sees (only
// when the real footprint is shorter than the cell, see above): one more photo at the safe point
// nearest to the planned one, off the track, when it sees some of it.
std::optional<Vec2> photoForLostGround(const grid::Grid& g, const Placer& placer,
                                       const sensor::EffectiveFootprint& fp, const Vec2& q,
                                       double heading, const std::vector<Vec2>& cellPhotos) {
    const double cell = g.cellSize();
    const PhotosPerCell ppc = photosPerCell(cell, fp);
    const double sAlong = cell / ppc.along, sAcross = cell / ppc.across;
    geo::MultiPolygon lost =
        geo::intersection(g.admissible(), rectangle(q, heading, sAcross, sAlong));
    for (const auto& c : cellPhotos) {
        if (lost.empty())
            break;
        lost = geo::difference(
            lost, geo::MultiPolygon{rectangle(c, heading, fp.real.longSideM, fp.real.shortSideM)});
    }
    const double lostArea = geo::area(lost);
    if (lostArea <= 1e-3 * sAcross * sAlong)
        return std::nullopt;
    const auto extra = placer.nearestSafePoint(q);
    if (!extra)
        return std::nullopt;
    const double stillLost = geo::area(geo::difference(
        lost,
        geo::MultiPolygon{rectangle(*extra, heading, fp.real.longSideM, fp.real.shortSideM)}));
    if (lostArea - stillLost <= 1e-3 * sAcross * sAlong)
        return std::nullopt;
    return extra;
}

// 1. Where each waypoint of `path` would go: lanes (or, by the paper's rule, every cell alone) and
// the turn and transit points of the cells flown over. Partial when the job is cancelled (the
// caller then drops it).
std::vector<Slot> pathSlots(const grid::Grid& g, const plan::CellPath& path,
                            const sensor::EffectiveFootprint& fp, PhotoRule rule) {
    const std::size_t n = path.cells.size();
    const double a = g.angleDeg() * M_PI / 180.0;
    const Vec2 ex(std::cos(a), std::sin(a)), ey(-std::sin(a), std::cos(a));
    auto stepDir = [&](std::size_t i, std::size_t j) -> Vec2 {
        const int dc = g.col(path.cells[j]) - g.col(path.cells[i]);
        const int dr = g.row(path.cells[j]) - g.row(path.cells[i]);
        const Vec2 v = dc * ex + dr * ey;
        return v.norm() > 0 ? Vec2(v.normalized()) : ex;
    };
    const double cell = g.cellSize();
    const PhotosPerCell ppc = photosPerCell(cell, fp);
    const double sAlong = cell / ppc.along, sAcross = cell / ppc.across;
    std::vector<PathGroup> groups;
    if (rule == PhotoRule::Lanes) {
        groups = cellPathGroups(g, path, fp);
    } else {
        for (std::size_t i = 0; i < n; ++i)
            if (!path.revisit[i])
                groups.push_back({false, static_cast<int>(i), static_cast<int>(i), {}, 0, 0});
    }
    std::vector<Slot> slots;
    bool anyPhoto = false;
    auto push = [&](const Slot& s) { slots.push_back(s); };
    // Photos of one cell by the per-cell rule: the long side across `in`, spaced along it; rows across in
    // a back-and-forth order.
    auto perCellSlots = [&](std::size_t i) {
        const int c = path.cells[i];
        const Vec2 p = g.flightPosition(c);
        const Vec2 in = i > 0 ? stepDir(i - 1, i) : (n > 1 ? stepDir(0, 1) : ex);
        const Vec2 right(in.y(), -in.x());
        const double h = headingDeg(in);
        for (int r = 0; r < ppc.across; ++r) {
            const double across = (r + 0.5) * sAcross - cell / 2;
            for (int k0 = 0; k0 < ppc.along; ++k0) {
                const int k = (r % 2 == 0) ? k0 : ppc.along - 1 - k0;
                const double along = (k + 0.5) * sAlong - cell / 2;
                push(Slot{{p + along * in + across * right, h, WaypointKind::Photo, c}, p, {}, {}});
                anyPhoto = true;
            }
        }
    };
    std::size_t gi = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if ((i & 0xFFF) == 0 && stopRequested())
            break; // a cancelled job drops the partial list
        const int c = path.cells[i];
        if (path.revisit[i]) {
            const Vec2 p = g.flightPosition(c);
            const Vec2 in = i > 0 ? stepDir(i - 1, i) : (n > 1 ? stepDir(0, 1) : ex);
            const Vec2 outDir = i + 1 < n ? stepDir(i, i + 1) : in;
            const bool turns = (in - outDir).norm() > 1e-9;
            if (turns || i == 0 || i + 1 == n) {
                // Cells flown over before their photo (before the first photo of the path) are turn
                // points; later ones are revisits.
                push(Slot{{p, headingDeg(outDir), anyPhoto ? WaypointKind::Transit : WaypointKind::Turn, c}, p, {}, {}});
            }
            continue;
        }
        const PathGroup& grp = groups[gi++];
        if (grp.lane) {
            const auto& photos = grp.strip.photos;
            const int first = path.cells[static_cast<std::size_t>(grp.first)];
            const int last = path.cells[static_cast<std::size_t>(grp.last)];
            for (std::size_t k = 0; k < photos.size(); ++k) {
                // A photo belongs to the cell it is taken over (the lane's end cells at the ends).
                const auto under = g.cellAt(photos[k]);
                const int owner = under && *under >= 0 && g.needsVisit(*under) ? *under : (k == 0 ? first : last);
                Slot s{{photos[k], grp.strip.headingDeg, WaypointKind::Photo, owner}, photos[k], {}, {}};
                if (k == 0)
                    for (int j = grp.first; j <= grp.firstClean; ++j)
                        s.laneIn.push_back(g.flightPosition(path.cells[static_cast<std::size_t>(j)]));
                if (k + 1 == photos.size())
                    for (int j = grp.last; j >= grp.lastClean; --j)
                        s.laneOut.push_back(g.flightPosition(path.cells[static_cast<std::size_t>(j)]));
                push(s);
            }
            anyPhoto = true;
        } else {
            for (int j = grp.first; j <= grp.last; ++j)
                perCellSlots(static_cast<std::size_t>(j));
        }
        i = static_cast<std::size_t>(grp.last);
    }
    return slots;
}

// 2. Safe placement of `slots`, in flight order: each slot knows where the one before it went.
std::vector<LocalWaypoint> placeSlots(const grid::Grid& g, const std::vector<Slot>& slots,
                                      const sensor::EffectiveFootprint& fp, PhotoPlacement& rep) {
    std::vector<LocalWaypoint> out;
    const double cell = g.cellSize();
    const Placer placer(g);
    // Whether a slid photo may lose part of its band (see above): only with a real footprint shorter
    // than the cell (its long side never is: the cell is an effective side); the polygon work is skipped
    // otherwise.
    const bool mayLose = fp.real.longSideM > 0 && fp.real.shortSideM > 0 && fp.real.shortSideM < cell &&
                         !g.admissible().empty();
    std::vector<Vec2> cellPhotos; // photos placed so far for the current cell
    out.reserve(slots.size());
    // The legs onto and off a lane: when the straight leg between the waypoint before and the lane's
    // first photo, or between the lane's last photo and the waypoint after, is unsafe, the aircraft flies
    // through the centre of the lane's end cell instead (on the lane's line, one safe grid move from the
    // cell path's neighbouring cell).
    const std::vector<Vec2>* offLane = nullptr; // the way off the lane whose last photo was output last
    bool photoOut = false;
    auto via = [&](const std::vector<Vec2>& pts, bool reversed, int cellIndex, const Vec2& towards) {
        for (std::size_t j = 0; j < pts.size(); ++j) {
            const Vec2& c = reversed ? pts[pts.size() - 1 - j] : pts[j];
            const Vec2& next = j + 1 < pts.size() ? (reversed ? pts[pts.size() - 2 - j] : pts[j + 1]) : towards;
            out.push_back({c, headingDeg(next - c), photoOut ? WaypointKind::Transit : WaypointKind::Turn, cellIndex});
        }
    };
    for (std::size_t k = 0; k < slots.size(); ++k) {
        if ((k & 0xFFF) == 0 && stopRequested())
            break; // a cancelled job drops the partial list
        LocalWaypoint w = slots[k].w;
        if (offLane && !g.segmentIsSafe(out.back().pos, w.kind == WaypointKind::Photo ? slots[k].anchor : w.pos)) {
            // laneOut runs from the lane's last cell back to its last clean one: flown in reverse.
            via(*offLane, true, out.back().cell, w.pos);
        }
        offLane = nullptr;
        if (!slots[k].laneIn.empty() && !out.empty() && !g.segmentIsSafe(out.back().pos, w.pos))
            via(slots[k].laneIn, false, w.cell, w.pos);
        if (w.kind == WaypointKind::Photo) {
            photoOut = true;
            if (!slots[k].laneOut.empty())
                offLane = &slots[k].laneOut;
        }
        if (w.kind != WaypointKind::Photo) {
            cellPhotos.clear();
            out.push_back(w);
            continue;
        }
        if (!out.empty() && out.back().cell != w.cell)
            cellPhotos.clear();
        const Vec2* prev = out.empty() ? nullptr : &out.back().pos;
        const Vec2* next = k + 1 < slots.size() ? &slots[k + 1].anchor : nullptr;
        const Vec2 q = w.pos;
        const Vec2 x = placer.place(slots[k], prev, next);
        const double slide = (x - q).norm();
        if (slide == 0.0) {
            cellPhotos.push_back(x);
            out.push_back(w);
            continue;
        }
        ++rep.slid;
        rep.maxSlideM = std::max(rep.maxSlideM, slide);
        // A photo slid onto another photo of its cell would take the same picture.
        bool same = false;
        for (const auto& c : cellPhotos)
            same = same || (c - x).norm() < 0.01;
        if (same) {
            ++rep.merged;
        } else {
            w.pos = x;
            out.push_back(w);
            cellPhotos.push_back(x);
        }
        if (!mayLose)
            continue;
        if (auto extra = photoForLostGround(g, placer, fp, q, w.headingDeg, cellPhotos)) {
            w.pos = *extra;
            out.push_back(w);
            cellPhotos.push_back(*extra);
            ++rep.added;
        }
    }
    return out;
}

} // namespace

std::vector<LocalWaypoint> photoWaypoints(const grid::Grid& g, const plan::CellPath& path,
                                          const sensor::EffectiveFootprint& fp,
                                          PhotoPlacement* placement, PhotoRule rule) {
    PhotoPlacement localPlacement;
    PhotoPlacement& rep = placement ? *placement : localPlacement;
    rep = {};
    if (path.cells.empty())
        return {};
    const std::vector<Slot> slots = pathSlots(g, path, fp, rule);
    if (stopRequested())
        return {}; // a cancelled job drops the partial list
    std::vector<LocalWaypoint> out = placeSlots(g, slots, fp, rep);
    dropNearDuplicates(out);
    return out;
}

void dropNearDuplicates(std::vector<LocalWaypoint>& waypoints, const geo::NoFlyField* field) {
    // A turn or transit point a few millimetres from its neighbour (a lane's end cell centre under the
    // lane's last photo, say) adds nothing but a zero-length leg that vehicles reject; so does a photo
    // that repeats the one before it (same heading, less than the gap away: the same picture, shifted
    // by less than the coverage check's resolution).
    const auto near = [](const Vec2& a, const Vec2& b) { return (a - b).norm() < kMinWaypointGapM; };
    const auto safeLeg = [&](const Vec2& a, const Vec2& b) { return !field || field->segmentIsSafe(a, b); };
    const std::size_t n = waypoints.size();
    std::vector<LocalWaypoint> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const LocalWaypoint& w = waypoints[i];
        const bool photo = w.kind == WaypointKind::Photo;
        const bool repeat = photo && !out.empty() && out.back().kind == WaypointKind::Photo && near(out.back().pos, w.pos) &&
                            std::fabs(std::remainder(out.back().headingDeg - w.headingDeg, 360.0)) < 0.5;
        const bool nearPrev = !photo && !out.empty() && near(out.back().pos, w.pos);
        const bool nearNext = !photo && i + 1 < n && near(waypoints[i + 1].pos, w.pos);
        if (!repeat && !nearPrev && !nearNext) {
            out.push_back(w);
            continue;
        }
        // Dropped, w leaves the leg from the waypoint before it straight to the one after it. Every leg
        // of `out` is one of the input's or was tested here, so the margin holds wherever it held.
        if (out.empty() || i + 1 == n || safeLeg(out.back().pos, waypoints[i + 1].pos))
            continue;
        // That leg would cut into a margin. Merged at w's position, the pair keeps w's leg on one side
        // and makes one new leg on the other: with the waypoint before (it moves onto w), or with the
        // one after (it moves onto w, its leg onwards is new).
        const bool wSafe = field->pointIsSafe(w.pos);
        if (wSafe && (repeat || nearPrev) && (out.size() < 2 || safeLeg(out[out.size() - 2].pos, w.pos))) {
            out.back().pos = w.pos;
            continue;
        }
        if (wSafe && nearNext && (i + 2 == n || safeLeg(w.pos, waypoints[i + 2].pos))) {
            waypoints[i + 1].pos = w.pos;
            continue;
        }
        out.push_back(w); // a leg shorter than the gap, but within the margin nowhere
    }
    waypoints.swap(out);
}

void straightenTransits(const grid::Grid& g, std::vector<LocalWaypoint>& waypoints) {
    // True if the straight leg ab keeps out of every no-fly margin and passes only over cells of the
    // grid that are flown (sampled every quarter cell): the aircraft stays over the area.
    const double step = g.cellSize() / 4;
    auto straightIsFine = [&](const Vec2& a, const Vec2& b) {
        if (!g.segmentIsSafe(a, b))
            return false;
        const double len = (b - a).norm();
        const int n = static_cast<int>(std::ceil(len / step));
        for (int k = 1; k < n; ++k) {
            const auto c = g.cellAt(a + (b - a) * (static_cast<double>(k) / n));
            if (!c || !g.needsVisit(*c))
                return false;
        }
        return true;
    };
    std::vector<LocalWaypoint> out;
    out.reserve(waypoints.size());
    std::size_t i = 0;
    while (i < waypoints.size()) {
        out.push_back(waypoints[i]);
        // A run of waypoints without a photo after this one, up to the next photo.
        std::size_t j = i + 1;
        while (j < waypoints.size() && waypoints[j].kind != WaypointKind::Photo)
            ++j;
        if (j > i + 1 && j < waypoints.size() && straightIsFine(waypoints[i].pos, waypoints[j].pos)) {
            i = j; // fly straight to the next photo
            continue;
        }
        ++i;
    }
    waypoints.swap(out);
    dropNearDuplicates(waypoints);
}

} // namespace pf::route
