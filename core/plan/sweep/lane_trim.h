// A sweep's lanes not needed: short lanes whose ground the others' photos already see are dropped,
// and every lane is shortened to the ground only it photographs (the part of its strip the other
// lanes' photos already see, at the overlap the operator set, is not flown).
#pragma once

#include "core/plan/sweep/decomposition.h"
#include "core/plan/sweep/sweep_lanes.h"

#include <vector>

namespace pf::plan {

// Drops short lanes (flown no longer than maxLengthM, not `pinned`) whose ground the photos of the
// other lanes already see with the real footprint (across x along): slivers between a zone's margin and
// the area's edge, or between two margins, often are. Shortest first; a dropped lane no longer counts
// for the others. Returns how many were dropped.
int dropCoveredLanes(const Decomposition& d, std::vector<std::vector<CellLane>>& lanes,
                     const std::vector<std::vector<char>>& pinned, const SweepLaneParams& p, const SweepGround& ground,
                     double realAcrossM, double realAlongM, double maxLengthM);

struct LaneTrimStats {
    int dropped = 0;       // lanes no longer needed at all
    int shortened = 0;     // lanes flown shorter
    double savedM = 0.0;   // length of strip no longer flown
};

// Every lane photographs, with the effective footprint (track spacing across, trigger distance along:
// the overlap the operator set), the rectangle of its band (trackSpacingM wide, centred on its line)
// from half a trigger distance before its first photo to half one after its last. A lane whose band
// another lane's rectangle already covers over a stretch at its end (a lane a cut between cells put
// under a zone runs the cell's whole width, though the lanes beside it see all but the part under the
// zone) is shortened to the stretch of its strip where its band still holds ground to photograph
// (inside the area, outside the zones; a margin's ground counts) that no other rectangle covers, and
// dropped when there is none. The lanes are taken most redundant first, each judged against the others
// as they are by then, so that two lanes never both give up the same ground. The band is probed on five
// lines across it and every `stepM` along (at least 0.25 m); a stretch kept is widened by a step on
// either side. Interior stretches that others cover stay flown: a lane is shortened, never split.
// Lane ends kept keep their wedges; a shortened end has none (its ground is covered).
// `flownCells` (when given, per cell of `lanes`): cells the flight enters; the lanes of the others
// (a pocket no safe path reaches) photograph nothing, count for no one and are left as they are.
LaneTrimStats trimCoveredLanes(const Decomposition& d, std::vector<std::vector<CellLane>>& lanes,
                               const SweepLaneParams& p, const SweepGround& ground, double stepM = 1.0,
                               const std::vector<char>* flownCells = nullptr);

} // namespace pf::plan
