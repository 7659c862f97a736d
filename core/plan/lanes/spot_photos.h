// Single photos for the ground the lanes leave unseen: patches of admissible ground that no real
// footprint covers (a corner of the area past a lane end's photo, ground between zones whose
// margins merge, the inside of a ring of zones seen from outside it), each photographed from the
// safe places around it by as few photos as see it, each photo flown where it lengthens the flight
// least.
#pragma once

#include "core/geo/types.h"
#include "core/plan/lanes/lane.h"
#include "core/result.h"
#include "core/sensor/footprint.h"

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace pf::plan {

struct SpotPhotoOptions {
    double realAcrossM = 0.0, realAlongM = 0.0; // the real footprint, across and along the heading
    double headingDeg = 0.0;                    // the lanes' heading, clockwise from north; a spot
                                                // photo is taken along it or across it
    // Each spot photo costs a detour with its stops. Patches of at least wholePatchM2 (a hole the
    // size of a car) are always photographed; smaller ones, of at least minPatchM2, largest first,
    // only while the unseen ground is more than (1 - coverageGoal) of the ground.
    double wholePatchM2 = 25.0;
    double minPatchM2 = 2.0;
    double coverageGoal = 0.999;
    // A spot photo is taken only when it sees at least this much of the unseen ground.
    double minSeenM2 = 1.0;
    // Of the places whose photo sees at least this share of the most any place sees, the one
    // nearest the flight is taken: on the way, a spot photo costs hardly a detour.
    double nearFlightShare = 0.9;
    int maxPhotos = 100;         // in all, largest patches first
    double candidateStepM = 1.0; // the places tried round a patch, this far apart
    double resolutionM = 0.5;    // of the coverage check that finds the patches and of the probes
};

struct SpotPhoto {
    geo::Vec2 pos{0, 0};
    double headingDeg = 0.0;
    double seenM2 = 0.0; // unseen ground it sees (by the probes)
};

struct SpotPhotoChoice {
    std::vector<SpotPhoto> photos;
    double unseenBeforeM2 = 0.0; // by the coverage check, all patches
    double unseenAfterM2 = 0.0;  // estimate: less what the spot photos see
};

// Finds the patches of `ground` (local metres) the real footprints of `photos` leave unseen and,
// for each patch worth it (SpotPhotoOptions; largest first), chooses photos greedily: of the places
// round it (candidateStepM apart, within a footprint's reach) that `mayFlyAt` accepts, the one
// whose footprint (along or across the heading) sees most of the patch still unseen, until a photo
// would see less than minSeenM2 or maxPhotos are taken; of the places seeing nearly the most
// (nearFlightShare), the one nearest the flight (`flightLegs`: the straight legs flown near the
// ground, may be empty). A photo counts for every patch it sees. Errors: a footprint side or a step
// not positive.
Result<SpotPhotoChoice> chooseSpotPhotos(const geo::MultiPolygon& ground,
                                         const std::vector<sensor::PhotoFootprint>& photos,
                                         const std::function<bool(const geo::Vec2&)>& mayFlyAt,
                                         const SpotPhotoOptions& options,
                                         const std::vector<std::pair<geo::Vec2, geo::Vec2>>& flightLegs = {});

// The ways between the places a flight stops at, for placing spot photos in it.
struct SpotRouting {
    // A place: p, with the direction a lane starting there flies along (a lane ending there arrives
    // along -in); zero for a spot photo, home and landing. Returns its id.
    std::function<int(const geo::Vec2& p, const geo::Vec2& in)> add;
    std::function<double(int from, int to)> timeS;               // the safe way's time
    std::function<std::vector<geo::Vec2>(int from, int to)> way; // its points strictly between
};

// A flight as the sweep gives it: lanes in flight order, links[i] between lane i and lane i + 1,
// the links from home and to landing. Each spot photo becomes a lane of one photo flown where it
// adds the least time (between two lanes, before the first or after the last); laneCells gets -1
// for it. Returns how many were placed.
int placeSpotPhotos(std::vector<Lane>& lanes, std::vector<std::vector<geo::Vec2>>& links,
                    std::vector<geo::Vec2>& homeLink, std::vector<geo::Vec2>& landingLink,
                    std::vector<int>& laneCells, const std::vector<SpotPhoto>& spots,
                    const std::optional<geo::Vec2>& home, const std::optional<geo::Vec2>& landing,
                    const SpotRouting& routing);

namespace spot_detail {

// The probes chooseSpotPhotos scores a candidate place on, in runs of consecutive probes (a patch's
// probes come row by row, so a run is a short stretch of ground) with each run's extent along and
// across both headings: a run wholly inside a footprint counts whole, one wholly outside not at all,
// and only the runs its edge cuts are tested probe by probe. The extents carry a slack far above the
// rounding of the projections, so a run is decided whole only where every probe's own test agrees:
// count() is the number of probes sees() accepts, found faster.
class ScoredProbes {
public:
    ScoredProbes(std::vector<geo::Vec2> pts, double headingDeg0, double headingDeg1, double halfAlong, double halfAcross);
    // Whether a photo at c along heading h (0 or 1; clockwise from north) sees q: the footprint rectangle.
    bool sees(const geo::Vec2& c, int h, const geo::Vec2& q) const;
    // How many of the probes a photo at c along heading h sees.
    std::size_t count(const geo::Vec2& c, int h) const;

private:
    static constexpr std::size_t kRun = 16;
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    struct Run {
        std::size_t first = 0, last = 0;
        std::array<std::array<double, 4>, 2> extent{}; // per heading: along min, max, across min, max
    };
    std::vector<geo::Vec2> m_pts;
    std::array<std::array<geo::Vec2, 2>, 2> m_axes; // per heading: along, right
    double m_halfAlong, m_halfAcross, m_slack = 0.0;
    std::vector<Run> m_runs;
};

} // namespace spot_detail

} // namespace pf::plan
