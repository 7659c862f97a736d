#include "core/route/sorties.h"

#include "core/job_scope.h"

#include "core/route/transit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pf::route {

namespace {

using geo::Vec2;

// The time the vertex b of the legs a->b, b->c costs (its turn and, for a real turn, the stop).
double vertexCostS(const Vec2& a, const Vec2& b, const Vec2& c, const FlightModel& m) {
    return plan::turnCostS(plan::turnAngleDeg(a, b, c), m);
}

std::string fmt(double v, int decimals = 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

} // namespace

double flightTimeS(const std::vector<Vec2>& pts, const FlightModel& m) { return plan::flightTime(pts, m).totalS; }

Result<SortiePlan> splitIntoSorties(const std::vector<LocalWaypoint>& survey, const Vec2& home,
                                    const SafePathFinder& finder, const FlightModel& model,
                                    const SortieOptions& opt, const std::string& aircraft) {
    const std::string who = aircraft.empty() ? std::string("The aircraft") : aircraft;
    if (!(opt.enduranceMin > 0) || !std::isfinite(opt.enduranceMin))
        return makeError(ErrorCode::InvalidInput, who + " has an endurance that is not positive.");
    if (!(opt.reserveFraction >= 0 && opt.reserveFraction < 1))
        return makeError(ErrorCode::InvalidInput, "The battery reserve must be a fraction from 0 up to (not including) 1.");
    if (!(model.speedMps > 0) || !(model.turnRateDegS > 0) || !(model.accelerationMps2 > 0) || model.photoDwellS < 0)
        return makeError(ErrorCode::InvalidInput,
                         who + " needs a positive speed, turn rate and acceleration to estimate flight times.");
    SortiePlan plan;
    plan.budgetS = opt.enduranceMin * 60.0 * (1.0 - opt.reserveFraction);
    const int n = static_cast<int>(survey.size());
    if (n == 0)
        return plan;

    // Prefix sums over the survey: legs, the cost of the turns at interior waypoints, photo dwell.
    std::vector<double> legPrefix(static_cast<std::size_t>(n), 0.0), turnPrefix(static_cast<std::size_t>(n), 0.0),
        dwellPrefix(static_cast<std::size_t>(n) + 1, 0.0);
    for (int k = 0; k < n; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        if (k > 0)
            legPrefix[uk] = legPrefix[uk - 1] + (survey[uk].pos - survey[uk - 1].pos).norm();
        if (k > 0)
            turnPrefix[uk] = turnPrefix[uk - 1] +
                             (k + 1 < n ? vertexCostS(survey[uk - 1].pos, survey[uk].pos, survey[uk + 1].pos, model) : 0.0);
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
    // Home -> out[i] ... -> w_i .. w_j -> in[j] ... -> home. The transits out and back are each timed
    // from rest to rest; the sortie starts and ends at rest only once, so one stop cost comes off.
    auto sortieTime = [&](int i, int j, const std::vector<Vec2>& out, const std::vector<Vec2>& in) {
        const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
        const plan::FlightTime to = plan::flightTime(out, model), ti = plan::flightTime(in, model);
        double t = to.totalS + ti.totalS - (to.lengthM > 0 && ti.lengthM > 0 ? model.stopCostS() : 0.0);
        t += (legPrefix[uj] - legPrefix[ui]) / model.speedMps;
        if (j - 1 > i)
            t += turnPrefix[uj - 1] - turnPrefix[ui];
        const Vec2 beforeI = out[out.size() - 2];
        const Vec2 afterJ = in[1];
        if (i == j) {
            t += vertexCostS(beforeI, pos(i), afterJ, model);
        } else {
            t += vertexCostS(beforeI, pos(i), pos(i + 1), model);
            t += vertexCostS(pos(j - 1), pos(j), afterJ, model);
        }
        return t + dwellPrefix[uj + 1] - dwellPrefix[ui];
    };

    for (int i = 0; i < n;) {
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "cutting the flight into sorties: cancelled");
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
        // The furthest waypoint j such that the sortie [i, j] fits. The way back from each j is a safe
        // path (a search around the zones), so it is computed only for the candidates that could fit:
        // the time with the straight line home instead is a lower bound (every part of the sortie's time
        // is counted, the way back at its shortest), the survey part alone only grows with j, and the
        // candidates are tried from the furthest down, the first that fits being the answer.
        int best = i;
        double bestTime = alone;
        const double outTime = flightTimeS(**out, model);
        std::vector<int> candidates;
        for (int j = i + 1; j < n; ++j) {
            const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
            const double surveyPart = (legPrefix[uj] - legPrefix[ui]) / model.speedMps;
            if (outTime + surveyPart > plan.budgetS)
                break;
            const double lower = outTime + surveyPart + (pos(j) - home).norm() / model.speedMps +
                                 (j - 1 > i ? turnPrefix[uj - 1] - turnPrefix[ui] : 0.0) + dwellPrefix[uj + 1] -
                                 dwellPrefix[ui];
            if (lower <= plan.budgetS)
                candidates.push_back(j);
        }
        // The candidates from the furthest down: the first that fits ends the sortie. Each try
        // searches a safe way home, and where the straight line home is a loose bound (zones between
        // the survey and home, turns on the way back) dozens of candidates in a row miss the budget by
        // a little (56 searches per sortie on a 1.25 km site with 30 zones). So after the furthest
        // kLinear candidates the search gallops down (1, 2, 4, ... candidates at a step) to one that
        // fits and bisects back up between it and the last that did not: the sortie found fits the
        // budget as before, and is the furthest one where the time grows with the sortie's end.
        constexpr int kLinear = 8;
        auto fits = [&](int c, double* time) -> Result<bool> {
            const int j = candidates[static_cast<std::size_t>(c)];
            auto back = inPath(j);
            if (!back)
                return back.error();
            *time = sortieTime(i, j, **out, **back);
            return *time <= plan.budgetS;
        };
        const int nc = static_cast<int>(candidates.size());
        int found = -1, failed = nc; // candidate indices: found fits, failed does not (nc: none tried)
        double foundTime = 0.0;
        for (int c = nc - 1; c >= 0 && c >= nc - kLinear && found < 0; --c) {
            double t = 0.0;
            auto f = fits(c, &t);
            if (!f)
                return f.error();
            if (*f) {
                found = c;
                foundTime = t;
            } else {
                failed = c;
            }
        }
        if (found < 0 && failed > 0 && nc > kLinear) {
            for (int step = 1; found < 0 && failed > 0; step *= 2) {
                const int c = std::max(0, failed - step);
                double t = 0.0;
                auto f = fits(c, &t);
                if (!f)
                    return f.error();
                if (*f) {
                    found = c;
                    foundTime = t;
                } else {
                    failed = c;
                }
            }
            while (found >= 0 && failed - found > 1) {
                const int c = found + (failed - found) / 2;
                double t = 0.0;
                auto f = fits(c, &t);
                if (!f)
                    return f.error();
                if (*f) {
                    found = c;
                    foundTime = t;
                } else {
                    failed = c;
                }
            }
        }
        if (found >= 0) {
            best = candidates[static_cast<std::size_t>(found)];
            bestTime = foundTime;
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
