#include "core/route/sorties.h"

#include "core/route/transit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pf::route {

namespace {

using geo::Vec2;

// Direction change in degrees at b between the legs a->b and b->c (0 when a leg has no length).
double turnDeg(const Vec2& a, const Vec2& b, const Vec2& c) {
    const Vec2 u = b - a, v = c - b;
    if (u.squaredNorm() == 0.0 || v.squaredNorm() == 0.0)
        return 0.0;
    const double cosA = std::clamp(u.dot(v) / (u.norm() * v.norm()), -1.0, 1.0);
    return std::acos(cosA) * 180.0 / M_PI;
}

std::string fmt(double v, int decimals = 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

} // namespace

double flightTimeS(const std::vector<Vec2>& pts, const FlightModel& m) {
    double len = 0, turn = 0;
    for (std::size_t i = 1; i < pts.size(); ++i) {
        len += (pts[i] - pts[i - 1]).norm();
        if (i + 1 < pts.size())
            turn += turnDeg(pts[i - 1], pts[i], pts[i + 1]);
    }
    return len / m.speedMps + turn / m.turnRateDegS;
}

Result<SortiePlan> splitIntoSorties(const std::vector<LocalWaypoint>& survey, const Vec2& home,
                                    const SafePathFinder& finder, const FlightModel& model,
                                    const SortieOptions& opt, const std::string& aircraft) {
    const std::string who = "Aircraft \"" + aircraft + "\"";
    if (!(opt.enduranceMin > 0) || !std::isfinite(opt.enduranceMin))
        return makeError(ErrorCode::InvalidInput, who + " has an endurance that is not positive.");
    if (!(opt.reserveFraction >= 0 && opt.reserveFraction < 1))
        return makeError(ErrorCode::InvalidInput, "The battery reserve must be a fraction from 0 up to (not including) 1.");
    if (!(model.speedMps > 0) || !(model.turnRateDegS > 0) || model.photoDwellS < 0)
        return makeError(ErrorCode::InvalidInput, who + " needs a positive speed and turn rate to estimate flight times.");
    SortiePlan plan;
    plan.budgetS = opt.enduranceMin * 60.0 * (1.0 - opt.reserveFraction);
    const int n = static_cast<int>(survey.size());
    if (n == 0)
        return plan;

    // Prefix sums over the survey: legs, turns at interior waypoints, photo dwell.
    std::vector<double> legPrefix(static_cast<std::size_t>(n), 0.0), turnPrefix(static_cast<std::size_t>(n), 0.0),
        dwellPrefix(static_cast<std::size_t>(n) + 1, 0.0);
    for (int k = 0; k < n; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        if (k > 0)
            legPrefix[uk] = legPrefix[uk - 1] + (survey[uk].pos - survey[uk - 1].pos).norm();
        if (k > 0)
            turnPrefix[uk] = turnPrefix[uk - 1] +
                             (k + 1 < n ? turnDeg(survey[uk - 1].pos, survey[uk].pos, survey[uk + 1].pos) : 0.0);
        dwellPrefix[uk + 1] = dwellPrefix[uk] + (survey[uk].kind == WaypointKind::Photo ? model.photoDwellS : 0.0);
    }
    const auto pos = [&](int k) { return survey[static_cast<std::size_t>(k)].pos; };
    std::vector<std::vector<Vec2>> outbound(static_cast<std::size_t>(n)), inbound(static_cast<std::size_t>(n));
    auto outPath = [&](int i) -> Result<const std::vector<Vec2>*> {
        auto& p = outbound[static_cast<std::size_t>(i)];
        if (p.empty()) {
            auto r = safePolyline(home, pos(i), finder);
            if (!r)
                return makeError(r.error().code, who + ", transit out to waypoint " + std::to_string(i + 1) + ": " +
                                                     r.error().message);
            p = std::move(r).value();
        }
        return &p;
    };
    auto inPath = [&](int j) -> Result<const std::vector<Vec2>*> {
        auto& p = inbound[static_cast<std::size_t>(j)];
        if (p.empty()) {
            auto r = safePolyline(pos(j), home, finder);
            if (!r)
                return makeError(r.error().code, who + ", transit back from waypoint " + std::to_string(j + 1) + ": " +
                                                     r.error().message);
            p = std::move(r).value();
        }
        return &p;
    };
    // Home -> out[i] ... -> w_i .. w_j -> in[j] ... -> home.
    auto sortieTime = [&](int i, int j, const std::vector<Vec2>& out, const std::vector<Vec2>& in) {
        const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
        double t = flightTimeS(out, model) + flightTimeS(in, model);
        t += (legPrefix[uj] - legPrefix[ui]) / model.speedMps;
        if (j - 1 > i)
            t += (turnPrefix[uj - 1] - turnPrefix[ui]) / model.turnRateDegS;
        const Vec2 beforeI = out[out.size() - 2];
        const Vec2 afterJ = in[1];
        if (i == j) {
            t += turnDeg(beforeI, pos(i), afterJ) / model.turnRateDegS;
        } else {
            t += turnDeg(beforeI, pos(i), pos(i + 1)) / model.turnRateDegS;
            t += turnDeg(pos(j - 1), pos(j), afterJ) / model.turnRateDegS;
        }
        return t + dwellPrefix[uj + 1] - dwellPrefix[ui];
    };

    for (int i = 0; i < n;) {
        auto out = outPath(i);
        if (!out)
            return out.error();
        auto in = inPath(i);
        if (!in)
            return in.error();
        const double alone = sortieTime(i, i, **out, **in);
        if (alone > plan.budgetS)
            return makeError(ErrorCode::InvalidInput,
                             who + " cannot fly to waypoint " + std::to_string(i + 1) + " (" +
                                 fmt((pos(i) - home).norm()) + " m from home) and back within its endurance of " +
                                 fmt(opt.enduranceMin, 1) + " min less the " + fmt(100 * opt.reserveFraction) +
                                 " % reserve (" + fmt(plan.budgetS) + " s available, " + fmt(alone) +
                                 " s needed): take off closer or use an aircraft with more endurance.");
        // The furthest waypoint j such that the sortie [i, j] fits; the survey part alone only grows
        // with j, so the scan stops once it exceeds the budget.
        int best = i;
        double bestTime = alone;
        const double outTime = flightTimeS(**out, model);
        for (int j = i + 1; j < n; ++j) {
            const double surveyPart =
                (legPrefix[static_cast<std::size_t>(j)] - legPrefix[static_cast<std::size_t>(i)]) / model.speedMps;
            if (outTime + surveyPart > plan.budgetS)
                break;
            auto back = inPath(j);
            if (!back)
                return back.error();
            const double t = sortieTime(i, j, **out, **back);
            if (t <= plan.budgetS) {
                best = j;
                bestTime = t;
            }
        }
        Sortie s;
        s.firstSurvey = i;
        s.lastSurvey = best;
        s.timeS = bestTime;
        auto addTransit = [&](const std::vector<Vec2>& pts) {
            for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
                LocalWaypoint w;
                w.pos = pts[k];
                w.headingDeg = headingDeg(pts[k], pts[k + 1]);
                w.kind = WaypointKind::Transit;
                s.waypoints.push_back(w);
            }
        };
        addTransit(**out);
        s.waypoints.insert(s.waypoints.end(), survey.begin() + i, survey.begin() + best + 1);
        addTransit(inbound[static_cast<std::size_t>(best)]);
        double len = 0;
        for (std::size_t k = 1; k < (*out)->size(); ++k)
            len += ((**out)[k] - (**out)[k - 1]).norm();
        len += legPrefix[static_cast<std::size_t>(best)] - legPrefix[static_cast<std::size_t>(i)];
        const auto& inb = inbound[static_cast<std::size_t>(best)];
        for (std::size_t k = 1; k < inb.size(); ++k)
            len += (inb[k] - inb[k - 1]).norm();
        s.lengthM = len;
        plan.totalTimeS += s.timeS;
        plan.sorties.push_back(std::move(s));
        i = best + 1;
    }
    return plan;
}

} // namespace pf::route
