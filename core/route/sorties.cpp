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

// Where the search for a sortie's end stands: candidate indices, `found` fits (its time
// `foundTime`), `failed` does not (the number of candidates: none tried yet).
struct FitSearch {
    int found = -1;
    int failed = 0;
    double foundTime = 0.0;
};

// Cuts the survey into sorties one at a time: the prefix sums that time any run of survey
// waypoints, and the safe transits out to and back from each waypoint, each searched once.
class SortieCutter {
public:
    SortieCutter(const std::vector<LocalWaypoint>& survey, const Vec2& home,
                 const SafePathFinder& finder, const FlightModel& model, const std::string& who);

    // The sortie that starts at survey waypoint i and takes as many waypoints as fit `budgetS`.
    Result<Sortie> sortieFrom(int i, double budgetS, const SortieOptions& opt);

private:
    Vec2 pos(int k) const { return m_survey[static_cast<std::size_t>(k)].pos; }
    Result<const std::vector<Vec2>*> outPath(int i);
    Result<const std::vector<Vec2>*> inPath(int j);
    double sortieTime(int i, int j, const std::vector<Vec2>& out,
                      const std::vector<Vec2>& in) const;
    Error tooFar(int i, double alone, double budgetS, const SortieOptions& opt) const;
    std::vector<int> candidateEnds(int i, double outTime, double budgetS) const;
    Status tryEnd(int i, const std::vector<Vec2>& out, const std::vector<int>& candidates, int c,
                  double budgetS, FitSearch& search);
    Result<FitSearch> furthestFit(int i, const std::vector<Vec2>& out,
                                  const std::vector<int>& candidates, double budgetS);
    Sortie makeSortie(int i, int last, double timeS, const std::vector<Vec2>& out) const;

    const std::vector<LocalWaypoint>& m_survey;
    const Vec2& m_home;
    const SafePathFinder& m_finder;
    const FlightModel& m_model;
    const std::string& m_who;
    int m_n;
    // Prefix sums over the survey: legs, the cost of the turns at interior waypoints, photo dwell.
    std::vector<double> m_legPrefix, m_turnPrefix, m_dwellPrefix;
    std::vector<std::vector<Vec2>> m_outbound, m_inbound; // empty until searched
};

SortieCutter::SortieCutter(const std::vector<LocalWaypoint>& survey, const Vec2& home,
                           const SafePathFinder& finder, const FlightModel& model,
                           const std::string& who)
    : m_survey(survey), m_home(home), m_finder(finder), m_model(model), m_who(who),
      m_n(static_cast<int>(survey.size())), m_legPrefix(static_cast<std::size_t>(m_n), 0.0),
      m_turnPrefix(static_cast<std::size_t>(m_n), 0.0),
      m_dwellPrefix(static_cast<std::size_t>(m_n) + 1, 0.0),
      m_outbound(static_cast<std::size_t>(m_n)), m_inbound(static_cast<std::size_t>(m_n)) {
    for (int k = 0; k < m_n; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        if (k > 0)
            m_legPrefix[uk] = m_legPrefix[uk - 1] + (survey[uk].pos - survey[uk - 1].pos).norm();
        if (k > 0)
            m_turnPrefix[uk] = m_turnPrefix[uk - 1] +
                               (k + 1 < m_n ? vertexCostS(survey[uk - 1].pos, survey[uk].pos,
                                                          survey[uk + 1].pos, model)
                                            : 0.0);
        m_dwellPrefix[uk + 1] =
            m_dwellPrefix[uk] + (survey[uk].kind == WaypointKind::Photo ? model.photoDwellS : 0.0);
    }
}

// The safe transit from home out to waypoint i, searched the first time it is asked for.
Result<const std::vector<Vec2>*> SortieCutter::outPath(int i) {
    auto& p = m_outbound[static_cast<std::size_t>(i)];
    if (p.empty()) {
        auto r = safePolyline(m_home, pos(i), m_finder);
        if (!r)
            return makeError(r.error().code, m_who + ", transit out to waypoint " +
                                                 std::to_string(i + 1) + ": " + r.error().message);
        p = std::move(r).value();
    }
    return &p;
}

// The safe transit from waypoint j back home, searched the first time it is asked for.
Result<const std::vector<Vec2>*> SortieCutter::inPath(int j) {
    auto& p = m_inbound[static_cast<std::size_t>(j)];
    if (p.empty()) {
        auto r = safePolyline(pos(j), m_home, m_finder);
        if (!r)
            return makeError(r.error().code, m_who + ", transit back from waypoint " +
                                                 std::to_string(j + 1) + ": " + r.error().message);
        p = std::move(r).value();
    }
    return &p;
}

// Home -> out[i] ... -> w_i .. w_j -> in[j] ... -> home. The transits out and back are each timed
// from rest to rest; the sortie starts and ends at rest only once, so one stop cost comes off.
double SortieCutter::sortieTime(int i, int j, const std::vector<Vec2>& out,
                                const std::vector<Vec2>& in) const {
    const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
    const plan::FlightTime to = plan::flightTime(out, m_model), ti = plan::flightTime(in, m_model);
    double t =
        to.totalS + ti.totalS - (to.lengthM > 0 && ti.lengthM > 0 ? m_model.stopCostS() : 0.0);
    t += (m_legPrefix[uj] - m_legPrefix[ui]) / m_model.speedMps;
    if (j - 1 > i)
        t += m_turnPrefix[uj - 1] - m_turnPrefix[ui];
    const Vec2 beforeI = out[out.size() - 2];
    const Vec2 afterJ = in[1];
    if (i == j) {
        t += vertexCostS(beforeI, pos(i), afterJ, m_model);
    } else {
        t += vertexCostS(beforeI, pos(i), pos(i + 1), m_model);
        t += vertexCostS(pos(j - 1), pos(j), afterJ, m_model);
    }
    return t + m_dwellPrefix[uj + 1] - m_dwellPrefix[ui];
}

// The error for waypoint i, which no sortie reaches and comes back from within the budget.
Error SortieCutter::tooFar(int i, double alone, double budgetS, const SortieOptions& opt) const {
    return makeError(
        ErrorCode::InvalidInput,
        m_who + " cannot fly to waypoint " + std::to_string(i + 1) + " (" +
            fmt((pos(i) - m_home).norm()) + " m from home) and back within its endurance of " +
            fmt(opt.enduranceMin, 1) + " min less the " + fmt(100 * opt.reserveFraction) +
            " % reserve (" + fmt(budgetS) + " s available, " + fmt(alone) +
            " s needed): take off closer or use an aircraft with more endurance.");
}

// The ends j > i that could close the sortie [i, j]. The way back from each j is a safe path (a
// search around the zones), so it is computed only for the candidates that could fit: the time
// with the straight line home instead is a lower bound (every part of the sortie's time is
// counted, the way back at its shortest), and the survey part alone only grows with j.
std::vector<int> SortieCutter::candidateEnds(int i, double outTime, double budgetS) const {
    std::vector<int> candidates;
    for (int j = i + 1; j < m_n; ++j) {
        const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
        const double surveyPart = (m_legPrefix[uj] - m_legPrefix[ui]) / m_model.speedMps;
        if (outTime + surveyPart > budgetS)
            break;
        const double lower = outTime + surveyPart + (pos(j) - m_home).norm() / m_model.speedMps +
                             (j - 1 > i ? m_turnPrefix[uj - 1] - m_turnPrefix[ui] : 0.0) +
                             m_dwellPrefix[uj + 1] - m_dwellPrefix[ui];
        if (lower <= budgetS)
            candidates.push_back(j);
    }
    return candidates;
}

// Times the sortie ending at candidate c with its safe way home, and records whether it fits.
Status SortieCutter::tryEnd(int i, const std::vector<Vec2>& out, const std::vector<int>& candidates,
                            int c, double budgetS, FitSearch& search) {
    const int j = candidates[static_cast<std::size_t>(c)];
    auto back = inPath(j);
    if (!back)
        return back.error();
    const double time = sortieTime(i, j, out, **back);
    if (time <= budgetS) {
        search.found = c;
        search.foundTime = time;
    } else {
        search.failed = c;
    }
    return {};
}

// The candidates from the furthest down: the first that fits ends the sortie. Each try
// searches a safe way home, and where the straight line home is a loose bound (zones between
// the survey and home, turns on the way back) dozens of candidates in a row miss the budget by
// a little (56 searches per sortie on a 1.25 km site with 30 zones). So after the furthest
// kLinear candidates the search gallops down (1, 2, 4, ... candidates at a step) to one that
// fits and bisects back up between it and the last that did not: the sortie found fits the
// budget as before, and is the furthest one where the time grows with the sortie's end.
Result<FitSearch> SortieCutter::furthestFit(int i, const std::vector<Vec2>& out,
                                            const std::vector<int>& candidates, double budgetS) {
    constexpr int kLinear = 8;
    const int nc = static_cast<int>(candidates.size());
    FitSearch s;
    s.failed = nc;
    for (int c = nc - 1; c >= 0 && c >= nc - kLinear && s.found < 0; --c)
        if (auto st = tryEnd(i, out, candidates, c, budgetS, s); !st)
            return st.error();
    if (s.found < 0 && s.failed > 0 && nc > kLinear) {
        for (int step = 1; s.found < 0 && s.failed > 0; step *= 2) { // gallop down
            const int c = std::max(0, s.failed - step);
            if (auto st = tryEnd(i, out, candidates, c, budgetS, s); !st)
                return st.error();
        }
        while (s.found >= 0 && s.failed - s.found > 1) { // bisect back up
            const int c = s.found + (s.failed - s.found) / 2;
            if (auto st = tryEnd(i, out, candidates, c, budgetS, s); !st)
                return st.error();
        }
    }
    return s;
}

// The sortie over survey waypoints i..last: transit out, the survey run, transit back, its length.
Sortie SortieCutter::makeSortie(int i, int last, double timeS, const std::vector<Vec2>& out) const {
    Sortie s;
    s.firstSurvey = i;
    s.lastSurvey = last;
    s.timeS = timeS;
    auto addTransit = [&](const std::vector<Vec2>& pts) {
        for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
            LocalWaypoint w;
            w.pos = pts[k];
            w.headingDeg = headingDeg(pts[k], pts[k + 1]);
            w.kind = WaypointKind::Transit;
            s.waypoints.push_back(w);
        }
    };
    const auto& inb = m_inbound[static_cast<std::size_t>(last)];
    addTransit(out);
    s.waypoints.insert(s.waypoints.end(), m_survey.begin() + i, m_survey.begin() + last + 1);
    addTransit(inb);
    double len = 0;
    for (std::size_t k = 1; k < out.size(); ++k)
        len += (out[k] - out[k - 1]).norm();
    len += m_legPrefix[static_cast<std::size_t>(last)] - m_legPrefix[static_cast<std::size_t>(i)];
    for (std::size_t k = 1; k < inb.size(); ++k)
        len += (inb[k] - inb[k - 1]).norm();
    s.lengthM = len;
    return s;
}

// The sortie from waypoint i: the furthest end that fits, else waypoint i alone (if that fits).
Result<Sortie> SortieCutter::sortieFrom(int i, double budgetS, const SortieOptions& opt) {
    auto out = outPath(i);
    if (!out)
        return out.error();
    auto in = inPath(i);
    if (!in)
        return in.error();
    const double alone = sortieTime(i, i, **out, **in);
    if (alone > budgetS)
        return tooFar(i, alone, budgetS, opt);
    // The furthest waypoint j such that the sortie [i, j] fits, tried only among the candidates.
    const std::vector<int> candidates = candidateEnds(i, flightTimeS(**out, m_model), budgetS);
    auto fit = furthestFit(i, **out, candidates, budgetS);
    if (!fit)
        return fit.error();
    if (fit->found < 0)
        return makeSortie(i, i, alone, **out);
    return makeSortie(i, candidates[static_cast<std::size_t>(fit->found)], fit->foundTime, **out);
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
        return makeError(ErrorCode::InvalidInput,
                         "The battery reserve must be a fraction from 0 up to (not including) 1.");
    if (!(model.speedMps > 0) || !(model.turnRateDegS > 0) || !(model.accelerationMps2 > 0) ||
        model.photoDwellS < 0)
        return makeError(
            ErrorCode::InvalidInput,
            who + " needs a positive speed, turn rate and acceleration to estimate flight times.");
    SortiePlan plan;
    plan.budgetS = opt.enduranceMin * 60.0 * (1.0 - opt.reserveFraction);
    SortieCutter cutter(survey, home, finder, model, who);
    for (int i = 0; i < static_cast<int>(survey.size());) {
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "cutting the flight into sorties: cancelled");
        auto s = cutter.sortieFrom(i, plan.budgetS, opt);
        if (!s)
            return s.error();
        plan.totalTimeS += s->timeS;
        i = s->lastSurvey + 1;
        plan.sorties.push_back(std::move(*s));
    }
    return plan;
}

} // namespace pf::route
