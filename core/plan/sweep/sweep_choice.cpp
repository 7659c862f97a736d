#include "core/plan/sweep/sweep_choice.h"

#include "core/job_scope.h"

#include "core/geo/polygon_ops.h"
#include "core/plan/coverage_check.h"
#include "core/plan/sweep/sweep_finish.h"

#include <algorithm>
#include <utility>

namespace pf::plan::sweep_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// How many more shared-line variants are finished when the fastest one leaves ground unseen.
constexpr int kSharedRetries = 3;

void sortByTime(std::vector<std::unique_ptr<FullPlan>>& plans) {
    std::stable_sort(plans.begin(), plans.end(),
                     [](const auto& a, const auto& b) { return a->timeS < b->timeS; });
}

} // namespace

SweepChoice::SweepChoice(const PreparedGround& g) : m_g(g) {
    const double regionArea = geo::area(g.region);
    m_allowedM2 = 0.001 * regionArea;
    m_toleranceM2 = 0.0005 * regionArea;
}

bool SweepChoice::worse(const FullPlan& a, const FullPlan& b) const {
    const double allowed = m_allowedM2;
    const bool aMiss = a.missedM2 > allowed, bMiss = b.missedM2 > allowed;
    if (aMiss != bMiss)
        return aMiss;
    return aMiss ? a.missedM2 > b.missedM2 + allowed ||
                       (a.missedM2 >= b.missedM2 - allowed && a.timeS > b.timeS)
                 : a.timeS > b.timeS;
}

void SweepChoice::add(std::unique_ptr<FullPlan> fp) {
    // Shared lines leave the ground beside a zone's edge to spot photos (their wedges are counted
    // as missed): among them the search's time decides, the finished flights then weigh the spots.
    // The others are kept: finished too while one could still fly sooner (finishFastest).
    if (!fp->dir->sharedLines.empty()) {
        if (m_bestShared && m_bestShared->timeS > fp->timeS)
            std::swap(m_bestShared, fp);
        if (!m_bestShared)
            m_bestShared = std::move(fp);
        else
            m_otherShared.push_back(std::move(fp));
    } else {
        if (m_best && worse(*m_best, *fp))
            std::swap(m_best, fp);
        if (!m_best)
            m_best = std::move(fp);
        else
            m_otherOwn.push_back(std::move(fp));
    }
}

// The fastest finished flight of one kind of lanes: the search's best, then the others in order of
// their search's time while that is below the fastest finished so far (a finished flight is never
// faster than its search's time: the photographed turns and spot photos only add). What finishing
// adds differs a lot between directions (on a generated area with 19 zones: 1033 s searched, 1308 s
// finished at 60 degrees; 1036 s and 1207 s at 57.9): the search's time alone picked the slower.
// An own-lanes plan that leaves more ground to the wedges than allowed is not taken over one that
// does not.
SweepPlan SweepChoice::finishFastest(const SweepPlan& base, FullPlan& first,
                                     std::vector<std::unique_ptr<FullPlan>>& others, bool ownLanes,
                                     double beatS) {
    SweepPlan fastest = finishPlan(m_g, base, first);
    sortByTime(others);
    for (auto& o : others) {
        if (o->timeS >= std::min(fastest.time.totalS, beatS) || stopRequested())
            break;
        if (ownLanes && o->missedM2 > m_allowedM2 && o->missedM2 > first.missedM2)
            continue;
        SweepPlan p = finishPlan(m_g, base, *o);
        if (p.time.totalS < fastest.time.totalS)
            fastest = std::move(p);
    }
    return fastest;
}

double SweepChoice::unseenM2(const SweepPlan& sp) const {
    CoverageCheckOptions co;
    co.resolutionM = 0.05 * std::min(m_g.realAcrossM, m_g.realAlongM);
    co.maxPatches = 0;
    std::vector<PhotoFootprint> fps;
    for (const auto& l : sp.lanes)
        for (const auto& p : l.photos)
            fps.push_back(PhotoFootprint{p, l.headingDeg, m_g.realAcrossM, m_g.realAlongM});
    auto r = checkCoverage(m_g.toSee, fps, co);
    return r ? r->uncoveredAreaM2 : kInf;
}

// The fastest shared lines left more ground unseen than the cells' own lanes: the next shared
// variants by the search's time (the lines of another phase or placement leave other wedges) while
// they could still fly sooner, the first that sees as much taken; else the own lanes.
SweepPlan SweepChoice::otherSharedSeeing(const SweepPlan& base, SweepPlan& own, double ownUnseen) {
    sortByTime(m_otherShared);
    int tried = 0;
    for (auto& o : m_otherShared) {
        if (o->timeS >= own.time.totalS || tried++ >= kSharedRetries || stopRequested())
            break;
        SweepPlan p = finishPlan(m_g, base, *o);
        if (p.time.totalS < own.time.totalS && unseenM2(p) <= ownUnseen + m_toleranceM2)
            return p;
    }
    return std::move(own);
}

// Shared lines leave some ground to the spot photos: kept only when the flight is faster and the
// real footprints see as much as with the cells' own lanes (within 0.05 % of the area). A finished
// flight is never faster than its search's time (the spot photos only add), so the second kind is
// finished only when it could still win.
Result<SweepPlan> SweepChoice::choose(const SweepPlan& base) {
    if (!m_best || !m_bestShared)
        return m_best ? finishFastest(base, *m_best, m_otherOwn, true)
                      : finishFastest(base, *m_bestShared, m_otherShared, false);
    auto cancelled = [] {
        return makeError(ErrorCode::Cancelled, "planning the sweep: cancelled");
    };
    const double tolerance = m_toleranceM2;
    if (m_best->timeS <= m_bestShared->timeS) {
        SweepPlan own = finishFastest(base, *m_best, m_otherOwn, true);
        if (m_bestShared->timeS >= own.time.totalS)
            return own;
        if (stopRequested())
            return cancelled();
        SweepPlan shared =
            finishFastest(base, *m_bestShared, m_otherShared, false, own.time.totalS);
        return shared.time.totalS < own.time.totalS && unseenM2(shared) <= unseenM2(own) + tolerance
                   ? shared
                   : otherSharedSeeing(base, own, unseenM2(own));
    }
    SweepPlan shared = finishFastest(base, *m_bestShared, m_otherShared, false);
    const double sharedUnseen = unseenM2(shared);
    // What no footprint can reach stays unseen by any plan: seeing all else but 0.1 % of the area
    // (the cells' own lanes leave up to about that too), shared lines need no comparison when the
    // cells' own lanes cannot fly faster.
    const bool sharedSeesAll = sharedUnseen <= shared.stats.unreachableAreaM2 + 2.0 * tolerance;
    if (m_best->timeS >= shared.time.totalS && sharedSeesAll)
        return shared;
    if (stopRequested())
        return cancelled();
    SweepPlan own =
        finishFastest(base, *m_best, m_otherOwn, true, sharedSeesAll ? shared.time.totalS : kInf);
    if (shared.time.totalS >= own.time.totalS)
        return own;
    const double ownUnseen = unseenM2(own);
    return sharedUnseen <= ownUnseen + tolerance ? shared : otherSharedSeeing(base, own, ownUnseen);
}

} // namespace pf::plan::sweep_detail
