// The sweep's choice among its searched plans: the fastest of each kind of lanes (the cells' own,
// lines shared by all cells) finished, then the others while one could still fly sooner, and the
// shared lines kept only when they fly sooner and see as much. Internal to the sweep planner.
#pragma once

#include "core/plan/sweep/sweep_planner.h"
#include "core/plan/sweep/sweep_prepare.h"
#include "core/plan/sweep/sweep_state.h"
#include "core/result.h"

#include <limits>
#include <memory>
#include <vector>

namespace pf::plan::sweep_detail {

class SweepChoice {
public:
    explicit SweepChoice(const PreparedGround& g);

    // Keeps a searched plan (its dir, the router's graphs and g must outlive the choice).
    void add(std::unique_ptr<FullPlan> fp);
    // The plan flown, finished from `base` (the directions' statistics); Cancelled when asked to
    // stop between two finished plans. At least one plan must have been added.
    Result<SweepPlan> choose(const SweepPlan& base);

private:
    // An own-lanes plan that leaves more ground to the wedges than allowed is worse than one that
    // does not; else the slower is worse.
    bool worse(const FullPlan& a, const FullPlan& b) const;
    SweepPlan finishFastest(const SweepPlan& base, FullPlan& first,
                            std::vector<std::unique_ptr<FullPlan>>& others, bool ownLanes,
                            double beatS = std::numeric_limits<double>::infinity());
    // The ground the plan's real footprints leave unseen, by the coverage check.
    double unseenM2(const SweepPlan& sp) const;
    SweepPlan otherSharedSeeing(const SweepPlan& base, SweepPlan& own, double ownUnseen);

    const PreparedGround& m_g;
    double m_allowedM2 = 0.0;   // ground a direction may leave to the wedges (see worse)
    double m_toleranceM2 = 0.0; // unseen ground two plans may differ by and see as much
    // The fastest plan of each kind of lanes, and the others.
    std::unique_ptr<FullPlan> m_best, m_bestShared;
    std::vector<std::unique_ptr<FullPlan>> m_otherOwn, m_otherShared;
};

} // namespace pf::plan::sweep_detail
