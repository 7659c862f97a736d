// Photos a lane need not take: inside a lane, photos whose ground the other photos already see are
// left out, while the lane is still flown end to end (the flight, and so its time, do not change).
#pragma once

#include "core/geo/types.h"
#include "core/plan/lanes/lane.h"

#include <functional>
#include <vector>

namespace pf::plan {

struct PhotoThinningOptions {
    double trackSpacingM = 0.0; // effective footprint across the lane (the side overlap kept)
    double photoSpacingM = 0.0; // effective footprint along it (the front overlap kept)
    double realAcrossM = 0.0;   // the real footprint, across and along (>= the effective one)
    double realAlongM = 0.0;
    double stepM = 1.0; // probe spacing (at least 0.25 m)
};

// Leaves out interior photos (never a lane's first or last: the lane keeps its ends, its line and
// its trigger distance between the photos kept) whose ground every other photo kept already sees:
// - inside the photo's effective footprint (track spacing across, trigger distance along, centred
// on
//   it, oriented along its lane), every point of `ground` lies in another kept photo's effective
//   footprint: the overlap the operator set holds there without it;
// - beyond that, within its real footprint, every point of `ground` lies in another kept photo's
// real
//   footprint (ground in a no-fly margin or a pocket, which only real footprints reach, stays
//   seen).
// The footprints are probed every stepM along and across (and 5 cm inside their edges). Lanes are
// taken most redundant first (the share of their interior photos the others cover), each photo
// judged against the photos kept by then, so that two photos never both give up the same ground.
// `fixedLanes` (per lane, may be empty): lanes whose photos all stay (they count for the others).
// Returns the number of photos left out.
int thinLanePhotos(std::vector<Lane>& lanes, const std::vector<char>& fixedLanes,
                   const PhotoThinningOptions& opt,
                   const std::function<bool(const geo::Vec2&)>& ground);

} // namespace pf::plan
