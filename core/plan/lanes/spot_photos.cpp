#include "core/plan/lanes/spot_photos.h"

#include "core/geo/polygon_ops.h"
#include "core/plan/coverage_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace pf::plan {

using geo::Vec2;

namespace {

// Unit vectors along the flight and to its right for a heading clockwise from north.
struct Axes {
    Vec2 along, right;
    explicit Axes(double headingDeg) {
        const double h = headingDeg * M_PI / 180.0;
        along = Vec2(std::sin(h), std::cos(h));
        right = Vec2(std::cos(h), -std::sin(h));
    }
};

struct Probe {
    Vec2 p;
    bool seen = false;
};

// Whether a photo at c along the axes sees q: the footprint rectangle, the one test of this file.
inline bool seesAt(const Vec2& c, const Axes& ax, double halfAlong, double halfAcross, const Vec2& q) {
    const Vec2 d = q - c;
    return std::abs(d.dot(ax.along)) <= halfAlong && std::abs(d.dot(ax.right)) <= halfAcross;
}

// A patch of unseen ground large enough to pay for a detour: its probes [first, last), its box.
struct UnseenPatch {
    std::size_t first = 0, last = 0;
    geo::Box box;
    double areaM2 = 0.0;
};

// The probes of every patch of at least minPatchM2: the centres of its unseen pixels (each half a
// pixel from the pixels' edges, so the pixel it falls in is never in doubt).
std::vector<UnseenPatch> unseenPatches(const CoverageReport& cov, double minPatchM2,
                                       std::vector<Probe>& probes) {
    const double res = cov.resolutionM;
    std::vector<UnseenPatch> out;
    for (const auto& patch : cov.patches) {
        if (patch.areaM2 < minPatchM2)
            continue;
        const geo::Box b = patch.box;
        const std::size_t first = probes.size();
        auto own = [&](const Vec2& q) {
            const auto i = static_cast<std::size_t>(std::floor((q.x() - b.min.x()) / res));
            const auto j = static_cast<std::size_t>(std::floor((q.y() - b.min.y()) / res));
            const auto cols = static_cast<std::size_t>(patch.columns);
            return i < cols && j * cols + i < patch.mask.size() && patch.mask[j * cols + i] != 0;
        };
        for (double y = b.min.y() + 0.5 * res; y < b.max.y(); y += res)
            for (double x = b.min.x() + 0.5 * res; x < b.max.x(); x += res)
                if (own(Vec2(x, y)))
                    probes.push_back(Probe{Vec2(x, y)});
        if (probes.size() > first)
            out.push_back(UnseenPatch{first, probes.size(), b, patch.areaM2});
    }
    return out;
}

// The places round one patch a spot photo may be taken from (within a footprint's reach of it, on
// a grid coarser round large patches), and how far each lies from the flight's legs near it.
struct PatchPlaces {
    double step = 0.0;
    std::vector<Vec2> places;
    std::vector<double> flightDist;
    std::vector<std::pair<Vec2, Vec2>> legs;

    PatchPlaces(const geo::Box& b, double reach, double candidateStepM,
                const std::function<bool(const geo::Vec2&)>& mayFlyAt,
                const std::vector<std::pair<geo::Vec2, geo::Vec2>>& flightLegs) {
        const double w = b.max.x() - b.min.x() + 2 * reach, h = b.max.y() - b.min.y() + 2 * reach;
        step = std::max(candidateStepM, std::sqrt(w * h / 1200.0));
        for (double y = b.min.y() - reach; y <= b.max.y() + reach; y += step)
            for (double x = b.min.x() - reach; x <= b.max.x() + reach; x += step)
                if (mayFlyAt(Vec2(x, y)))
                    places.emplace_back(x, y);
        if (places.empty())
            return;
        for (const auto& [a, c] : flightLegs) {
            if (std::max(a.x(), c.x()) >= b.min.x() - reach - step &&
                std::min(a.x(), c.x()) <= b.max.x() + reach + step &&
                std::max(a.y(), c.y()) >= b.min.y() - reach - step &&
                std::min(a.y(), c.y()) <= b.max.y() + reach + step)
                legs.emplace_back(a, c);
        }
        flightDist.resize(places.size());
        for (std::size_t ci = 0; ci < places.size(); ++ci)
            flightDist[ci] = distToFlight(places[ci]);
    }

    double distToFlight(const Vec2& p) const {
        double d = std::numeric_limits<double>::infinity();
        for (const auto& [a, c] : legs) {
            const Vec2 ab = c - a;
            const double l2 = ab.squaredNorm();
            const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
            d = std::min(d, (p - (a + t * ab)).norm());
        }
        return d;
    }
};

// The next spot photo for a patch: of the places that see nearly the most of the probes left
// (scored on at most about 600 of them, every stride-th; the count scales back), the one nearest
// the flight (on its way, a spot photo costs hardly a detour), then a finer look round it (the grid
// may stop a step short of what the photo sees). `seen`: the ground it sees by the scored probes, 0
// if none.
struct SpotCandidate {
    Vec2 pos{0, 0};
    std::size_t heading = 0; // index into the headings
    double seen = 0.0;
};

SpotCandidate bestSpot(const std::vector<std::size_t>& left, const std::vector<Probe>& probes,
                       const PatchPlaces& pp, const std::array<double, 2>& headings,
                       double halfAlong, double halfAcross, double px, const SpotPhotoOptions& o,
                       const std::function<bool(const geo::Vec2&)>& mayFlyAt) {
    const std::size_t stride = std::max<std::size_t>(1, left.size() / 600);
    std::vector<Vec2> scored;
    for (std::size_t i = 0; i < left.size(); i += stride)
        scored.push_back(probes[left[i]].p);
    const spot_detail::ScoredProbes scoredProbes(std::move(scored), headings[0], headings[1],
                                                 halfAlong, halfAcross);
    const auto& places = pp.places;
    std::array<std::vector<double>, 2> seenAt;
    double most = 0.0;
    for (std::size_t hi = 0; hi < headings.size(); ++hi) {
        seenAt[hi].resize(places.size());
        for (std::size_t ci = 0; ci < places.size(); ++ci) {
            const std::size_t n = scoredProbes.count(places[ci], static_cast<int>(hi));
            seenAt[hi][ci] = static_cast<double>(n * stride) * px;
            most = std::max(most, seenAt[hi][ci]);
        }
    }
    SpotCandidate best;
    double bestDist = std::numeric_limits<double>::infinity();
    for (std::size_t hi = 0; hi < headings.size(); ++hi)
        for (std::size_t ci = 0; ci < places.size(); ++ci) {
            const double seen = seenAt[hi][ci];
            if (seen < o.nearFlightShare * most || seen < o.minSeenM2)
                continue;
            const double d = pp.flightDist[ci];
            if (d < bestDist - 1e-9 || (d <= bestDist + 1e-9 && seen > best.seen)) {
                best = SpotCandidate{places[ci], hi, seen};
                bestDist = d;
            }
        }
    if (best.seen <= 0.0)
        return best;
    const Vec2 c0 = best.pos;
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j) {
            const Vec2 c = c0 + 0.25 * pp.step * Vec2(i, j);
            if ((i == 0 && j == 0) || !mayFlyAt(c) || pp.distToFlight(c) > bestDist + 0.5 * pp.step)
                continue;
            const std::size_t n = scoredProbes.count(c, static_cast<int>(best.heading));
            const double seen = static_cast<double>(n * stride) * px;
            if (seen > best.seen) {
                best.seen = seen;
                best.pos = c;
            }
        }
    return best;
}

// One stop of the flight while spot photos are placed in it: a lane, or a spot photo.
struct Stop {
    int lane = -1;             // index into lanes, or -1 - the spot's index
    int entry = -1, exit = -1; // router ids, added when first timed (kNotAdded before)
    Vec2 entryPos{0, 0}, exitPos{0, 0};
    Vec2 dir{0, 0}; // a lane's heading
};
constexpr int kNotAdded = -2;

// The flight's stops on the router: only the ends of the slots timed join it (a large plan's lanes
// stay out of it).
class FlightStops {
public:
    FlightStops(const SpotRouting& routing, const std::optional<Vec2>& home,
                const std::optional<Vec2>& landing)
        : m_routing(routing), m_home(home), m_landing(landing) {}

    // The lanes in flight order; false when a lane has no photos (no flight to place spots in).
    bool addLanes(const std::vector<Lane>& lanes) {
        for (std::size_t i = 0; i < lanes.size(); ++i) {
            const Lane& l = lanes[i];
            if (l.photos.empty())
                continue;
            Stop it;
            it.lane = static_cast<int>(i);
            it.entryPos = l.photos.front();
            it.exitPos = l.photos.back();
            it.dir = Axes(l.headingDeg).along;
            it.entry = it.exit = kNotAdded;
            m_seq.push_back(it);
        }
        if (m_seq.size() != lanes.size())
            return false;
        m_homeId = m_home ? m_routing.add(*m_home, Vec2(0, 0)) : -1;
        m_landingId = m_landing ? m_routing.add(*m_landing, Vec2(0, 0)) : -1;
        return true;
    }

    // Spot photo si at s, flown where it adds the least time; links, homeLink and landingLink
    // follow.
    void insertSpot(std::size_t si, const Vec2& s, std::vector<std::vector<Vec2>>& links,
                    std::vector<Vec2>& homeLink, std::vector<Vec2>& landingLink) {
        const int sid = m_routing.add(s, Vec2(0, 0));
        const std::size_t n = m_seq.size();
        const std::size_t at = cheapestSlot(s, sid);
        const int prev = at == 0 ? m_homeId : exitOf(m_seq[at - 1]);
        const int next = at == n ? m_landingId : entryOf(m_seq[at]);
        // links[k] joins seq[k] and seq[k + 1]: the spot takes the place of one link and adds one.
        if (n == 0) {
            homeLink = way(prev, sid);
            landingLink = way(sid, next);
        } else if (at == 0) {
            homeLink = way(prev, sid);
            links.insert(links.begin(), way(sid, next));
        } else if (at == n) {
            links.push_back(way(prev, sid));
            landingLink = way(sid, next);
        } else {
            links[at - 1] = way(prev, sid);
            links.insert(links.begin() + static_cast<std::ptrdiff_t>(at), way(sid, next));
        }
        Stop it;
        it.lane = -1 - static_cast<int>(si);
        it.entry = it.exit = sid;
        it.entryPos = it.exitPos = s;
        m_seq.insert(m_seq.begin() + static_cast<std::ptrdiff_t>(at), it);
    }

    const std::vector<Stop>& stops() const { return m_seq; }

private:
    int entryOf(Stop& it) {
        if (it.entry == kNotAdded)
            it.entry = m_routing.add(it.entryPos, it.dir);
        return it.entry;
    }
    int exitOf(Stop& it) {
        if (it.exit == kNotAdded)
            it.exit = m_routing.add(it.exitPos, -it.dir);
        return it.exit;
    }
    double time(int a, int b) const { return a < 0 || b < 0 ? 0.0 : m_routing.timeS(a, b); }
    std::vector<Vec2> way(int a, int b) const {
        return a < 0 || b < 0 ? std::vector<Vec2>{} : m_routing.way(a, b);
    }

    // Where in the flight (before stop k, k = n: after the last) the spot at s (router id sid) adds
    // the least time: the places by the straight detour, the nearest 8 timed on the safe ways.
    std::size_t cheapestSlot(const Vec2& s, int sid) {
        const std::size_t n = m_seq.size();
        std::vector<std::pair<double, std::size_t>> est;
        for (std::size_t k = 0; k <= n; ++k) {
            const std::optional<Vec2> prev =
                k == 0 ? m_home : std::optional<Vec2>(m_seq[k - 1].exitPos);
            const std::optional<Vec2> next =
                k == n ? m_landing : std::optional<Vec2>(m_seq[k].entryPos);
            double e = 0.0;
            if (prev)
                e += (s - *prev).norm();
            if (next)
                e += (*next - s).norm();
            if (prev && next)
                e -= (*next - *prev).norm();
            est.emplace_back(e, k);
        }
        const std::size_t timed = std::min<std::size_t>(est.size(), 8);
        std::partial_sort(est.begin(), est.begin() + static_cast<std::ptrdiff_t>(timed), est.end());
        est.resize(timed);
        double best = std::numeric_limits<double>::infinity();
        std::size_t at = 0;
        for (const auto& [e, k] : est) {
            const int prev = k == 0 ? m_homeId : exitOf(m_seq[k - 1]);
            const int next = k == n ? m_landingId : entryOf(m_seq[k]);
            const double d = time(prev, sid) + time(sid, next) - time(prev, next);
            if (d < best) {
                best = d;
                at = k;
            }
        }
        return at;
    }

    const SpotRouting& m_routing;
    const std::optional<Vec2> m_home, m_landing;
    std::vector<Stop> m_seq;
    int m_homeId = -1, m_landingId = -1;
};

} // namespace

namespace spot_detail {

ScoredProbes::ScoredProbes(std::vector<Vec2> pts, double headingDeg0, double headingDeg1, double halfAlong,
                           double halfAcross)
    : m_pts(std::move(pts)), m_halfAlong(halfAlong), m_halfAcross(halfAcross) {
    const Axes a0(headingDeg0), a1(headingDeg1);
    m_axes = {{{a0.along, a0.right}, {a1.along, a1.right}}};
    double big = 0.0;
    for (const auto& q : m_pts)
        big = std::max({big, std::abs(q.x()), std::abs(q.y())});
    m_slack = 1e-9 * (1.0 + 4.0 * (big + halfAlong + halfAcross));
    for (std::size_t first = 0; first < m_pts.size(); first += kRun) {
        Run r;
        r.first = first;
        r.last = std::min(m_pts.size(), first + kRun);
        for (std::size_t h = 0; h < 2; ++h) {
            auto& e = r.extent[h];
            e = {kInf, -kInf, kInf, -kInf};
            for (std::size_t k = r.first; k < r.last; ++k) {
                const double u = m_pts[k].dot(m_axes[h][0]), v = m_pts[k].dot(m_axes[h][1]);
                e[0] = std::min(e[0], u);
                e[1] = std::max(e[1], u);
                e[2] = std::min(e[2], v);
                e[3] = std::max(e[3], v);
            }
        }
        m_runs.push_back(r);
    }
}

bool ScoredProbes::sees(const Vec2& c, int h, const Vec2& q) const {
    const auto& ax = m_axes[static_cast<std::size_t>(h)];
    const Vec2 d = q - c;
    return std::abs(d.dot(ax[0])) <= m_halfAlong && std::abs(d.dot(ax[1])) <= m_halfAcross;
}

std::size_t ScoredProbes::count(const Vec2& c, int h) const {
    const auto& ax = m_axes[static_cast<std::size_t>(h)];
    const double uc = c.dot(ax[0]), vc = c.dot(ax[1]);
    const double inA = m_halfAlong - m_slack, inC = m_halfAcross - m_slack;
    const double outA = m_halfAlong + m_slack, outC = m_halfAcross + m_slack;
    std::size_t n = 0;
    for (const Run& r : m_runs) {
        const auto& e = r.extent[static_cast<std::size_t>(h)];
        const double u0 = e[0] - uc, u1 = e[1] - uc, v0 = e[2] - vc, v1 = e[3] - vc;
        if (u0 > outA || u1 < -outA || v0 > outC || v1 < -outC)
            continue;
        if (u0 >= -inA && u1 <= inA && v0 >= -inC && v1 <= inC) {
            n += r.last - r.first;
            continue;
        }
        for (std::size_t k = r.first; k < r.last; ++k)
            n += sees(c, h, m_pts[k]) ? 1 : 0;
    }
    return n;
}

} // namespace spot_detail

Result<SpotPhotoChoice> chooseSpotPhotos(const geo::MultiPolygon& ground,
                                         const std::vector<sensor::PhotoFootprint>& photos,
                                         const std::function<bool(const geo::Vec2&)>& mayFlyAt,
                                         const SpotPhotoOptions& o,
                                         const std::vector<std::pair<geo::Vec2, geo::Vec2>>& flightLegs) {
    if (!(o.realAcrossM > 0) || !(o.realAlongM > 0) || !(o.candidateStepM > 0) ||
        !(o.resolutionM > 0))
        return makeError(ErrorCode::InvalidInput,
                         "spot photos: the footprint's sides and the steps must be positive");
    SpotPhotoChoice out;
    if (ground.empty())
        return out;
    CoverageCheckOptions co;
    co.resolutionM = o.resolutionM;
    co.maxPatches = 2000;
    co.maxPixels = 16'000'000;
    co.patchShapes = false; // the probes are looked up in the patches' pixels
    auto cov = checkCoverage(ground, photos, co);
    if (!cov.ok())
        return cov.error();
    out.unseenBeforeM2 = out.unseenAfterM2 = cov->uncoveredAreaM2;
    const double px = cov->resolutionM * cov->resolutionM;
    std::vector<Probe> probes;
    const std::vector<UnseenPatch> patches = unseenPatches(*cov, o.minPatchM2, probes);
    const double halfAlong = 0.5 * o.realAlongM, halfAcross = 0.5 * o.realAcrossM;
    const double reach = std::hypot(halfAlong, halfAcross);
    const std::array<double, 2> headings{o.headingDeg, std::fmod(o.headingDeg + 90.0, 360.0)};

    const double allowedUnseen = (1.0 - o.coverageGoal) * cov->admissibleAreaM2;
    for (const UnseenPatch& patch : patches) {
        if (patch.areaM2 < o.wholePatchM2 && out.unseenAfterM2 <= allowedUnseen)
            break; // patches come largest first
        const PatchPlaces pp(patch.box, reach, o.candidateStepM, mayFlyAt, flightLegs);
        if (pp.places.empty())
            continue;
        while (static_cast<int>(out.photos.size()) < o.maxPhotos) {
            std::vector<std::size_t> left;
            for (std::size_t k = patch.first; k < patch.last; ++k)
                if (!probes[k].seen)
                    left.push_back(k);
            if (static_cast<double>(left.size()) * px < o.minSeenM2)
                break;
            const SpotCandidate best =
                bestSpot(left, probes, pp, headings, halfAlong, halfAcross, px, o, mayFlyAt);
            if (best.seen <= 0.0 || best.seen < o.minSeenM2)
                break;
            // The photo sees its probes in every patch.
            const double bestHeading = headings[best.heading];
            const Axes ax(bestHeading);
            double seen = 0.0;
            for (auto& pr : probes)
                if (!pr.seen && (pr.p - best.pos).norm() <= reach &&
                    seesAt(best.pos, ax, halfAlong, halfAcross, pr.p)) {
                    pr.seen = true;
                    seen += px;
                }
            out.photos.push_back(SpotPhoto{best.pos, bestHeading, seen});
            out.unseenAfterM2 -= seen;
        }
    }
    out.unseenAfterM2 = std::max(0.0, out.unseenAfterM2);
    return out;
}

int placeSpotPhotos(std::vector<Lane>& lanes, std::vector<std::vector<geo::Vec2>>& links,
                    std::vector<geo::Vec2>& homeLink, std::vector<geo::Vec2>& landingLink,
                    std::vector<int>& laneCells, const std::vector<SpotPhoto>& spots,
                    const std::optional<geo::Vec2>& home, const std::optional<geo::Vec2>& landing,
                    const SpotRouting& routing) {
    if (spots.empty())
        return 0;
    FlightStops flight(routing, home, landing);
    if (!flight.addLanes(lanes))
        return 0;
    for (std::size_t si = 0; si < spots.size(); ++si)
        flight.insertSpot(si, spots[si].pos, links, homeLink, landingLink);

    std::vector<Lane> outLanes;
    std::vector<int> outCells;
    outLanes.reserve(flight.stops().size());
    for (const Stop& it : flight.stops()) {
        if (it.lane >= 0) {
            outLanes.push_back(std::move(lanes[static_cast<std::size_t>(it.lane)]));
            outCells.push_back(static_cast<std::size_t>(it.lane) < laneCells.size()
                                   ? laneCells[static_cast<std::size_t>(it.lane)]
                                   : -1);
        } else {
            const SpotPhoto& sp = spots[static_cast<std::size_t>(-1 - it.lane)];
            outLanes.push_back(Lane{sp.pos, sp.pos, {sp.pos}, sp.headingDeg});
            outCells.push_back(-1);
        }
    }
    lanes = std::move(outLanes);
    laneCells = std::move(outCells);
    return static_cast<int>(spots.size());
}

} // namespace pf::plan
