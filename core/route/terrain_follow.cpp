#include "core/route/terrain_follow.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pf::route {

namespace {

// How the altitude runs along a leg: linear between its ends, or level at one of them (the climb
// at take-off, the return to launch).
enum class Profile { Linear, LevelAtEnd, LevelAtStart };

double headingOf(const geo::Vec2& a, const geo::Vec2& b) {
    const geo::Vec2 d = b - a;
    if (d.norm() < 1e-9)
        return 0.0;
    double h = std::atan2(d.x(), d.y()) * 180.0 / M_PI;
    return h < 0 ? h + 360.0 : h;
}

struct Point {
    geo::Vec2 pos;
    double ground = 0.0;
    double z = 0.0;
};

class Follower {
public:
    Follower(const terrain::HeightGrid& g, const TerrainFollowOptions& o, TerrainFollowResult& r)
        : grid(g), opt(o), res(r) {}

    // Points to insert between a and b (in order) so that no sample of the leg is closer to the
    // ground than the clearance. Samples at a home end (take-off, landing) are not checked.
    void fix(const Point& a, const Point& b, Profile prof, bool homeAtA, bool homeAtB, int depth,
             std::vector<Point>& out) {
        const double len = (b.pos - a.pos).norm();
        const int n = std::max(1, static_cast<int>(std::ceil(len / opt.sampleStepM)));
        double worst = 1e-6, worstS = -1, worstG = 0, lowest = std::numeric_limits<double>::infinity();
        double unchecked = 0.0;
        for (int i = 0; i <= n; ++i) {
            const double s = std::min(i * opt.sampleStepM, len);
            if ((homeAtA && s == 0.0) || (homeAtB && s == len))
                continue;
            const geo::Vec2 p = len > 0 ? geo::Vec2(a.pos + (b.pos - a.pos) * (s / len)) : a.pos;
            const double g = grid.heightOr(p, std::nan(""));
            if (std::isnan(g)) {
                unchecked += len / n;
                continue;
            }
            const double z = prof == Profile::LevelAtEnd     ? b.z
                              : prof == Profile::LevelAtStart ? a.z
                                                              : a.z + (b.z - a.z) * (len > 0 ? s / len : 0.0);
            lowest = std::min(lowest, z - g);
            const double deficit = g + opt.minClearanceM - z;
            if (deficit > worst) {
                worst = deficit;
                worstS = s;
                worstG = g;
            }
        }
        if (worstS < 0 || len < 2 * opt.sampleStepM || depth > 40) {
            if (worstS >= 0)
                res.warnings.push_back(tooSteep(a.pos + (b.pos - a.pos) * (worstS / len), worst));
            res.lowestClearanceM = std::min(res.lowestClearanceM, lowest);
            res.uncheckedM += unchecked;
            return;
        }
        const Point p{a.pos + (b.pos - a.pos) * (worstS / len), worstG, worstG + opt.heightAboveGroundM};
        // The two halves: out of home the climb reaches the inserted point's altitude first.
        if (prof == Profile::LevelAtEnd)
            fix(a, p, Profile::LevelAtEnd, homeAtA, false, depth + 1, out);
        else
            fix(a, p, Profile::Linear, homeAtA, false, depth + 1, out);
        out.push_back(p);
        if (prof == Profile::LevelAtStart)
            fix(p, b, Profile::LevelAtStart, false, homeAtB, depth + 1, out);
        else
            fix(p, b, Profile::Linear, false, homeAtB, depth + 1, out);
    }

private:
    std::string tooSteep(const geo::Vec2& at, double deficit) const {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "the ground near (%.1f, %.1f) m rises too steeply to keep the %.1f m clearance "
                      "(%.1f m short): check the route there",
                      at.x(), at.y(), opt.minClearanceM, deficit);
        return buf;
    }

    const terrain::HeightGrid& grid;
    const TerrainFollowOptions& opt;
    TerrainFollowResult& res;
};

} // namespace

LegClearance legClearance(const terrain::HeightGrid& grid, const geo::Vec2& a, double za, const geo::Vec2& b,
                          double zb, double stepM) {
    LegClearance c;
    const auto samples = terrain::profile(grid, a, b, stepM);
    const double len = (b - a).norm();
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const auto& s = samples[i];
        if (std::isnan(s.groundM)) {
            c.uncheckedM += len / std::max<std::size_t>(samples.size() - 1, 1);
            continue;
        }
        const double z = za + (zb - za) * (len > 0 ? s.distanceM / len : 0.0);
        if (z - s.groundM < c.clearanceM) {
            c.clearanceM = z - s.groundM;
            c.distanceM = s.distanceM;
        }
    }
    return c;
}

Result<TerrainFollowResult> followTerrain(const std::vector<LocalWaypoint>& flown,
                                          const std::vector<std::pair<int, int>>& sorties,
                                          const std::optional<geo::Vec2>& home, const terrain::HeightGrid& grid,
                                          const TerrainFollowOptions& opt, const std::optional<geo::Vec2>& landing) {
    if (!(opt.heightAboveGroundM > 0) || !std::isfinite(opt.heightAboveGroundM))
        return makeError(ErrorCode::InvalidInput, "the height above ground must be a number greater than 0");
    if (!(opt.minClearanceM >= 0) || opt.minClearanceM > opt.heightAboveGroundM)
        return makeError(ErrorCode::InvalidInput,
                         "the minimum clearance must be between 0 and the height above ground");
    if (!(opt.sampleStepM > 0))
        return makeError(ErrorCode::InvalidInput, "the terrain sampling step must be greater than 0");
    TerrainFollowResult res;
    if (flown.empty())
        return res;
    // The ground under every waypoint; where the grid knows nothing, the nearest known one before it.
    std::vector<double> ground(flown.size(), std::nan(""));
    int unknown = 0;
    for (std::size_t i = 0; i < flown.size(); ++i)
        ground[i] = grid.heightOr(flown[i].pos, std::nan(""));
    double last = std::nan("");
    for (double g : ground)
        if (!std::isnan(g)) {
            last = g;
            break;
        }
    if (std::isnan(last))
        return makeError(ErrorCode::InvalidInput, "the terrain model has no heights under any waypoint");
    for (double& g : ground) {
        if (std::isnan(g)) {
            g = last;
            ++unknown;
        }
        last = g;
    }
    if (unknown > 0)
        res.warnings.push_back(std::to_string(unknown) +
                               " waypoint(s) lie where the terrain model has no heights: their altitude follows "
                               "the ground of the waypoint before them");

    Follower f(grid, opt, res);
    const std::vector<std::pair<int, int>> ranges =
        sorties.empty() ? std::vector<std::pair<int, int>>{{0, static_cast<int>(flown.size()) - 1}} : sorties;
    auto point = [&](std::size_t i) { return Point{flown[i].pos, ground[i], ground[i] + opt.heightAboveGroundM}; };
    auto emit = [&](const LocalWaypoint& w, const Point& p, bool added) {
        res.waypoints.push_back(w);
        res.groundM.push_back(p.ground);
        res.altitudeM.push_back(p.z);
        res.inserted.push_back(added);
        res.insertedCount += added;
    };
    auto emitInserted = [&](const std::vector<Point>& pts, const geo::Vec2& to, WaypointKind kind) {
        for (std::size_t k = 0; k < pts.size(); ++k) {
            LocalWaypoint w;
            w.pos = pts[k].pos;
            w.kind = kind;
            w.headingDeg = headingOf(pts[k].pos, k + 1 < pts.size() ? pts[k + 1].pos : to);
            emit(w, pts[k], true);
        }
    };
    const Point homePt = home ? Point{*home, opt.homeGroundM, opt.homeGroundM} : Point{};
    for (const auto& [first, lastIdx] : ranges) {
        const int start = static_cast<int>(res.waypoints.size());
        std::vector<Point> add;
        if (home) {
            f.fix(homePt, point(static_cast<std::size_t>(first)), Profile::LevelAtEnd, true, false, 0, add);
            emitInserted(add, flown[static_cast<std::size_t>(first)].pos, WaypointKind::Transit);
        }
        for (int i = first; i <= lastIdx; ++i) {
            const auto k = static_cast<std::size_t>(i);
            emit(flown[k], point(k), false);
            if (i == lastIdx)
                break;
            add.clear();
            f.fix(point(k), point(k + 1), Profile::Linear, false, false, 0, add);
            const bool transit = flown[k].kind == WaypointKind::Transit || flown[k + 1].kind == WaypointKind::Transit;
            emitInserted(add, flown[k + 1].pos, transit ? WaypointKind::Transit : WaypointKind::Turn);
        }
        if (home) {
            add.clear();
            Point back = homePt;
            if (landing && &first == &ranges.back().first)
                back.pos = *landing;
            f.fix(point(static_cast<std::size_t>(lastIdx)), back, Profile::LevelAtStart, false, true, 0, add);
            emitInserted(add, back.pos, WaypointKind::Transit);
        }
        res.sorties.push_back({start, static_cast<int>(res.waypoints.size()) - 1});
    }
    if (res.uncheckedM > 0.5) {
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "%.0f m of the flight pass over ground the terrain model does not cover: the clearance "
                      "there is not checked",
                      res.uncheckedM);
        res.warnings.push_back(buf);
    }
    return res;
}

} // namespace pf::route
