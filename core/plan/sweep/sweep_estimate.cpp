#include "core/plan/sweep/sweep_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pf::plan::sweep_detail {

using geo::Vec2;

bool sameDirection(double aDeg, double bDeg) {
    const double dd = std::fabs(std::fmod(aDeg - bDeg, 180.0));
    return std::min(dd, 180.0 - dd) < 0.5;
}

std::vector<double> candidateDirections(const geo::MultiPolygon& region, const std::vector<geo::Polygon>& noFly,
                                        const SweepOptions& opt) {
    std::vector<double> angles;
    auto addAngle = [&](double deg) {
        deg = std::fmod(deg, 180.0);
        if (deg < 0)
            deg += 180.0;
        for (double a : angles)
            if (sameDirection(a, deg))
                return;
        angles.push_back(deg);
    };
    if (!opt.anglesDeg.empty()) {
        for (double a : opt.anglesDeg)
            addAngle(a);
    } else {
        auto longest = [&](const std::vector<geo::Polygon>& polys) {
            std::vector<std::pair<double, double>> edges; // length, angle
            for (const auto& poly : polys) {
                const auto& r = poly.outer;
                for (std::size_t i = 0; i < r.size(); ++i) {
                    const Vec2 d = r[(i + 1) % r.size()] - r[i];
                    edges.emplace_back(d.norm(), std::atan2(d.y(), d.x()) * 180.0 / M_PI);
                }
            }
            std::stable_sort(edges.begin(), edges.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
            for (std::size_t i = 0; i < edges.size() && static_cast<int>(i) < opt.edgeDirections; ++i)
                addAngle(edges[i].second);
        };
        longest(region);
        longest(noFly);
        for (double a = 0; a < 180.0 - 1e-9; a += opt.coarseStepDeg)
            addAngle(a);
    }
    return angles;
}

double quickEstimateS(const Decomposition& d, const std::vector<MergedCell>& merged,
                      const std::vector<std::vector<double>>& heights, double photoSpacingM,
                      const FlightTimeModel& time, double trackSpacingM) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double ph = photoSpacingM;
    const double uTurnS = 2.0 * turnCostS(90.0, time) + trackSpacingM / time.speedMps;
    double est = 0.0;
    std::vector<std::pair<Vec2, Vec2>> ends;
    for (std::size_t mi = 0; mi < merged.size(); ++mi) {
        const auto& m = merged[mi];
        const auto& hs = heights[mi];
        if (hs.empty())
            continue;
        std::size_t part = 0;
        Vec2 first(0, 0), last(0, 0);
        for (std::size_t j = 0; j < hs.size(); ++j) {
            while (part + 1 < m.parts.size() && hs[j] > d.cells[static_cast<std::size_t>(m.parts[part])].yhi)
                ++part;
            const auto& c = d.cells[static_cast<std::size_t>(m.parts[part])];
            const double w = c.xRight(hs[j]) - c.xLeft(hs[j]);
            est += std::max(0.0, w - ph) / time.speedMps;
            const Vec2 mid(0.5 * (c.xRight(hs[j]) + c.xLeft(hs[j])), hs[j]);
            if (j == 0)
                first = mid;
            last = mid;
        }
        est += static_cast<double>(hs.size() > 0 ? hs.size() - 1 : 0) * uTurnS;
        ends.emplace_back(first, last);
    }
    // cell changes: nearest neighbour over the cells' first and last lanes
    if (!ends.empty()) {
        std::vector<char> used(ends.size(), 0);
        used[0] = 1;
        Vec2 at = ends[0].second;
        for (std::size_t k = 1; k < ends.size(); ++k) {
            double best = kInf;
            std::size_t bi = 0;
            bool flip = false;
            for (std::size_t i = 0; i < ends.size(); ++i) {
                if (used[i])
                    continue;
                const double d1 = (ends[i].first - at).norm(), d2 = (ends[i].second - at).norm();
                if (std::min(d1, d2) < best) {
                    best = std::min(d1, d2);
                    bi = i;
                    flip = d2 < d1;
                }
            }
            used[bi] = 1;
            at = flip ? ends[bi].first : ends[bi].second;
            est += best / time.speedMps + 2.0 * turnCostS(90.0, time);
        }
    }
    return est;
}

} // namespace pf::plan::sweep_detail
