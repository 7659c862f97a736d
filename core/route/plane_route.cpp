#include "core/route/plane_route.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace pf::route {

namespace {

using geo::Vec2;

// What a turn that keeps no margin costs in the order search: more than any flight, so that every
// order avoiding such turns wins over one that needs them, and orders needing fewer win among
// those.
constexpr double kUnsafeTurnCostM = 1e7;

// One lane flown in one direction: its run-in point, first and last photo, direction.
struct FlownLane {
    Vec2 runIn{0, 0};
    Vec2 first{0, 0};
    Vec2 last{0, 0};
    double headingRad = 0.0;
    bool runInShortened = false;
};

// A turn: one Dubins path, or a chain of them along a detour.
struct Turn {
    std::vector<DubinsPath> pieces;
    bool safe = true;
    double lengthM() const {
        double l = 0.0;
        for (const auto& p : pieces)
            l += p.lengthM();
        return l;
    }
};

Vec2 unitOfCompass(double compassDeg) {
    const double h = headingFromCompassDeg(compassDeg);
    return {std::cos(h), std::sin(h)};
}

class RouteSearch {
public:
    RouteSearch(const std::vector<plan::Lane>& lanes, const PlaneRouteOptions& o)
        : m_o(o) {
        for (std::size_t i = 0; i < lanes.size(); ++i)
            if (!lanes[i].photos.empty())
                m_used.push_back(static_cast<int>(i));

        for (int i : m_used)
            for (int r = 0; r < 2; ++r)
                m_flown[key(i, r)] = makeFlown(lanes[static_cast<std::size_t>(i)], r == 1);
    }

    const std::vector<int>& used() const { return m_used; }
    const FlownLane& flown(int lane, bool rev) const { return m_flown.at(key(lane, rev)); }

    // The turn from lane a (direction ra) to lane b (direction rb): the shortest Dubins path
    // keeping the margin, or the shortest of all when none does.
    Turn turn(int a, bool ra, int b, bool rb) const {
        const FlownLane& fa = flown(a, ra);
        const FlownLane& fb = flown(b, rb);
        const Pose from{fa.last, fa.headingRad};
        const Pose to{fb.runIn, fb.headingRad};
        const auto direct = safestPiece(from, to);
        if (direct.safe || !m_o.detours)
            return direct;
        if (auto chain = detourTurn(from, to))
            return *chain;
        return direct;
    }

    // The cost of a turn in the order search (cached).
    double turnCost(int a, bool ra, int b, bool rb) {
        const long long k =
            (static_cast<long long>(key(a, ra)) << 32) | static_cast<unsigned>(key(b, rb));
        const auto it = m_costs.find(k);
        if (it != m_costs.end())
            return it->second;
        const Turn t = turn(a, ra, b, rb);
        const double c = t.lengthM() + (t.safe ? 0.0 : kUnsafeTurnCostM);
        m_costs.emplace(k, c);
        return c;
    }

    // The straight from home to a lane's run-in and from a lane's end to the landing.
    double startCost(int lane, bool rev) const {
        return m_o.home ? (flown(lane, rev).runIn - *m_o.home).norm() : 0.0;
    }
    double endCost(int lane, bool rev) const {
        const auto& at = m_o.landing ? m_o.landing : m_o.home;
        return at ? (flown(lane, rev).last - *at).norm() : 0.0;
    }
    double laneLength(int lane, bool rev) const {
        const FlownLane& f = flown(lane, rev);
        return (f.first - f.runIn).norm() + (f.last - f.first).norm();
    }

private:
    static int key(int lane, bool rev) { return 2 * lane + (rev ? 1 : 0); }

    FlownLane makeFlown(const plan::Lane& lane, bool rev) const {
        FlownLane f;
        f.first = rev ? lane.photos.back() : lane.photos.front();
        f.last = rev ? lane.photos.front() : lane.photos.back();
        const Vec2 d = f.last - f.first;
        Vec2 u = d.norm() > 1e-6 ? Vec2(d.normalized()) : unitOfCompass(lane.headingDeg);
        if (d.norm() <= 1e-6 && rev)
            u = -u;
        f.headingRad = std::atan2(u.y(), u.x());
        // The run-in and, behind it, one turn radius of room for the turn that ends there.
        double len = m_o.runInM;
        const double room = len + m_o.radiusM;
        if (m_o.field && room > 0 && !m_o.field->segmentIsSafe(f.first - room * u, f.first)) {
            // The longest safe straight behind the first photo, by bisection (safe up to some
            // length: the margin begins where it ends); the run-in is that less the turn's room.
            double lo = 0.0, hi = room;
            for (int it = 0; it < 30; ++it) {
                const double mid = 0.5 * (lo + hi);
                (m_o.field->segmentIsSafe(f.first - mid * u, f.first) ? lo : hi) = mid;
            }
            len = std::min(len, std::max(0.0, lo - m_o.radiusM));
            f.runInShortened = len < m_o.runInM;
        }
        f.runIn = f.first - len * u;
        return f;
    }

    // The shortest word from `from` to `to` that keeps the margin, else the shortest.
    Turn safestPiece(const Pose& from, const Pose& to) const {
        std::vector<DubinsPath> paths;
        if (m_o.radiusM <= 0) {
            paths.push_back(shortestDubinsPath(from, to, 0.0));
        } else {
            for (DubinsWord w : kDubinsWords)
                if (auto p = dubinsPath(from, to, m_o.radiusM, w))
                    paths.push_back(*p);
            std::sort(paths.begin(), paths.end(), [](const DubinsPath& x, const DubinsPath& y) {
                return x.lengthM() < y.lengthM();
            });
        }
        for (const auto& p : paths)
            if (pathIsSafe(p))
                return {{p}, true};
        return {{paths.front()}, false};
    }

    // The turn along the detour path round the zones: Dubins pieces through its corners, each
    // corner passed along the bisector of its two legs. Nothing when a piece cannot keep the
    // margin.
    std::optional<Turn> detourTurn(const Pose& from, const Pose& to) const {
        const Vec2 a = m_o.detours->nearestSafePoint(from.pos);
        const Vec2 b = m_o.detours->nearestSafePoint(to.pos);
        auto mid = m_o.detours->detour(a, b);
        if (!mid)
            return std::nullopt;
        std::vector<Vec2> pts{from.pos};
        auto add = [&](const Vec2& p) {
            if ((p - pts.back()).norm() > 1.0)
                pts.push_back(p);
        };
        add(a);
        for (const auto& p : *mid)
            add(p);
        add(b);
        if ((to.pos - pts.back()).norm() <= 1.0 && pts.size() > 1)
            pts.pop_back();
        pts.push_back(to.pos);
        Turn t;
        Pose at = from;
        for (std::size_t i = 1; i < pts.size(); ++i) {
            Pose next = to;
            if (i + 1 < pts.size()) {
                const Vec2 d =
                    (pts[i] - pts[i - 1]).normalized() + (pts[i + 1] - pts[i]).normalized();
                const Vec2 dir = d.norm() > 1e-9 ? Vec2(d) : Vec2(pts[i + 1] - pts[i]);
                next = {pts[i], std::atan2(dir.y(), dir.x())};
            }
            Turn piece = safestPiece(at, next);
            if (!piece.safe)
                return std::nullopt;
            t.pieces.push_back(piece.pieces.front());
            at = next;
        }
        return t;
    }

    bool pathIsSafe(const DubinsPath& p) const {
        if (!m_o.field || m_o.field->empty())
            return true;
        const auto pts = turnPoints(p);
        for (std::size_t i = 1; i < pts.size(); ++i)
            if (!m_o.field->segmentIsSafe(pts[i - 1].pos, pts[i].pos))
                return false;
        return true;
    }

    PlaneRouteOptions m_o;
    std::vector<int> m_used;
    std::unordered_map<int, FlownLane> m_flown;
    std::unordered_map<long long, double> m_costs;
};

struct Candidate {
    std::vector<int> order;
    std::vector<bool> reversed;
    double costM = std::numeric_limits<double>::infinity();
    int skipEvery = 0;
};

// The lanes sorted across the flight direction (then along it): the rows a Survey flies in turn.
std::vector<int> rowOrder(const std::vector<plan::Lane>& lanes, const std::vector<int>& used) {
    Vec2 u(1, 0);
    double longest = -1;
    for (int i : used) {
        const auto& p = lanes[static_cast<std::size_t>(i)].photos;
        const double l = (p.back() - p.front()).norm();
        if (l > longest && l > 1e-6) {
            longest = l;
            u = (p.back() - p.front()).normalized();
        }
    }
    const Vec2 n(-u.y(), u.x());
    std::vector<int> out = used;
    auto mid = [&](int i) {
        const auto& p = lanes[static_cast<std::size_t>(i)].photos;
        return Vec2(0.5 * (p.front() + p.back()));
    };
    std::stable_sort(out.begin(), out.end(), [&](int a, int b) {
        const double ka = mid(a).dot(n), kb = mid(b).dot(n);
        if (std::fabs(ka - kb) > 1e-3)
            return ka < kb;
        return mid(a).dot(u) < mid(b).dot(u);
    });
    return out;
}

// Every k-th lane of `rows` forward, then the next residue backward, and so on.
std::vector<int> skipOrder(const std::vector<int>& rows, int k) {
    std::vector<int> out;
    const int n = static_cast<int>(rows.size());
    for (int r = 0; r < k; ++r) {
        std::vector<int> pass;
        for (int i = r; i < n; i += k)
            pass.push_back(rows[static_cast<std::size_t>(i)]);
        if (r % 2 == 1)
            std::reverse(pass.begin(), pass.end());
        out.insert(out.end(), pass.begin(), pass.end());
    }
    return out;
}

// The directions of a fixed order that fly it soonest: two states per lane, exact.
Candidate bestDirections(RouteSearch& s, const std::vector<int>& order) {
    Candidate c;
    c.order = order;
    const std::size_t n = order.size();
    if (n == 0) {
        c.costM = 0.0;
        return c;
    }
    std::vector<std::array<double, 2>> cost(n);
    std::vector<std::array<int, 2>> from(n, {0, 0});
    for (int r = 0; r < 2; ++r)
        cost[0][static_cast<std::size_t>(r)] =
            s.startCost(order[0], r == 1) + s.laneLength(order[0], r == 1);
    for (std::size_t i = 1; i < n; ++i)
        for (int r = 0; r < 2; ++r) {
            double best = std::numeric_limits<double>::infinity();
            for (int q = 0; q < 2; ++q) {
                const double v = cost[i - 1][static_cast<std::size_t>(q)] +
                                 s.turnCost(order[i - 1], q == 1, order[i], r == 1);
                if (v < best) {
                    best = v;
                    from[i][static_cast<std::size_t>(r)] = q;
                }
            }
            cost[i][static_cast<std::size_t>(r)] = best + s.laneLength(order[i], r == 1);
        }
    int r = 0;
    double end0 = cost[n - 1][0] + s.endCost(order[n - 1], false);
    double end1 = cost[n - 1][1] + s.endCost(order[n - 1], true);
    if (end1 < end0)
        r = 1;
    c.costM = std::min(end0, end1);
    c.reversed.assign(n, false);
    for (std::size_t i = n; i-- > 0;) {
        c.reversed[i] = r == 1;
        r = from[i][static_cast<std::size_t>(r)];
    }
    return c;
}

// Greedy: from a start lane, always the lane whose turn is shortest next. The straight distance is
// a lower bound of a turn, so candidates are taken nearest first and the scan stops when no nearer
// turn can follow.
Candidate greedyOrder(RouteSearch& s, int start, bool startRev) {
    Candidate c;
    const auto& used = s.used();
    std::unordered_map<int, bool> left;
    for (int i : used)
        left[i] = true;
    left.erase(start);
    int cur = start;
    bool curRev = startRev;
    c.order.push_back(cur);
    c.reversed.push_back(curRev);
    double total = s.startCost(cur, curRev) + s.laneLength(cur, curRev);
    std::vector<std::pair<double, std::pair<int, bool>>> near;
    while (!left.empty()) {
        near.clear();
        const Vec2 at = s.flown(cur, curRev).last;
        for (const auto& [j, _] : left)
            for (int r = 0; r < 2; ++r)
                near.push_back({(s.flown(j, r == 1).runIn - at).norm(), {j, r == 1}});
        std::sort(near.begin(), near.end());
        double best = std::numeric_limits<double>::infinity();
        std::pair<int, bool> pick = near.front().second;
        for (const auto& [d, jr] : near) {
            if (d >= best)
                break;
            const double v = s.turnCost(cur, curRev, jr.first, jr.second);
            if (v < best) {
                best = v;
                pick = jr;
            }
        }
        total += best + s.laneLength(pick.first, pick.second);
        cur = pick.first;
        curRev = pick.second;
        left.erase(cur);
        c.order.push_back(cur);
        c.reversed.push_back(curRev);
    }
    c.costM = total + s.endCost(cur, curRev);
    return c;
}

void appendLane(PlaneRoute& out, const plan::Lane& lane, const FlownLane& f, bool rev) {
    const double compass = compassFromHeadingRad(f.headingRad);
    if ((f.first - f.runIn).norm() > 1e-6)
        out.waypoints.push_back({f.runIn, compass, WaypointKind::Turn, -1});
    const std::size_t n = lane.photos.size();
    for (std::size_t k = 0; k < n; ++k)
        out.waypoints.push_back(
            {lane.photos[rev ? n - 1 - k : k], compass, WaypointKind::Photo, -1});
}

} // namespace

std::vector<Pose> turnPoints(const DubinsPath& path) {
    std::vector<Pose> out{path.start};
    double at = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double len = path.segmentLengthM(i);
        if (len <= 0.0)
            continue;
        if (path.kind(i) != SegmentKind::Straight && path.radiusM > 0) {
            const double step = std::max(kMinTurnStepM, path.radiusM * kTurnStepDeg * M_PI / 180.0);
            const int n = static_cast<int>(std::ceil(len / step - 1e-9));
            for (int k = 1; k < n; ++k)
                out.push_back(path.poseAt(at + len * k / n));
        }
        at += len;
        out.push_back(path.poseAt(at));
    }
    return out;
}

PlaneRoute planPlaneRoute(const std::vector<plan::Lane>& lanes, const PlaneRouteOptions& o) {
    PlaneRoute out;
    RouteSearch s(lanes, o);
    const auto& used = s.used();
    if (used.empty())
        return out;
    // The orders tried: the skip patterns, then greedy from the ends of the first and last rows.
    const std::vector<int> rows = rowOrder(lanes, used);
    Candidate best;
    const int n = static_cast<int>(rows.size());
    const int kMax =
        o.trackSpacingM > 0
            ? std::min(n, static_cast<int>(std::ceil(2.0 * o.radiusM / o.trackSpacingM)) + 1)
            : 1;
    for (int k = 1; k <= std::max(1, kMax); ++k) {
        Candidate c = bestDirections(s, skipOrder(rows, k));
        c.skipEvery = k;
        if (c.costM < best.costM)
            best = std::move(c);
    }
    for (int start : {rows.front(), rows.back()})
        for (bool rev : {false, true}) {
            Candidate c = bestDirections(s, greedyOrder(s, start, rev).order);
            if (c.costM < best.costM - 1e-6)
                best = std::move(c);
        }

    // The route of the order kept.
    out.order = best.order;
    out.reversed = best.reversed;
    out.skipEvery = best.skipEvery;
    for (std::size_t i = 0; i < best.order.size(); ++i) {
        const int lane = best.order[i];
        const bool rev = best.reversed[i];
        const FlownLane& f = s.flown(lane, rev);
        if (i > 0) {
            const Turn t = s.turn(best.order[i - 1], best.reversed[i - 1], lane, rev);
            out.unsafeTurns += t.safe ? 0 : 1;
            out.lengthM += t.lengthM();
            for (std::size_t pi = 0; pi < t.pieces.size(); ++pi) {
                const auto pts = turnPoints(t.pieces[pi]);
                // Each piece's end is the next one's start; the last one's is the run-in point.
                const std::size_t last = pi + 1 < t.pieces.size() ? pts.size() : pts.size() - 1;
                for (std::size_t k = 1; k < last; ++k)
                    out.waypoints.push_back({pts[k].pos, compassFromHeadingRad(pts[k].headingRad),
                                             WaypointKind::Turn, -1});
            }
        }
        out.runInsShortened += f.runInShortened ? 1 : 0;
        out.lengthM += s.laneLength(lane, rev);
        appendLane(out, lanes[static_cast<std::size_t>(lane)], f, rev);
    }
    if (out.unsafeTurns > 0)
        out.warnings.push_back(
            std::to_string(out.unsafeTurns) +
            " turn(s) between lanes cannot be flown at the minimum turn radius without entering a "
            "no-fly margin: the route check lists them; a larger margin around the zones or a "
            "smaller turn radius avoids them");
    if (out.runInsShortened > 0)
        out.warnings.push_back(
            std::to_string(out.runInsShortened) +
            " lane(s) begin with a run-in shorter than the plane's, which would enter a no-fly "
            "margin: their first photos come sooner after the turn");
    return out;
}

} // namespace pf::route
