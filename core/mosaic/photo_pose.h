// One photo's pose from its own metadata, the plan and the catalog: its altitude above take-off,
// where the top of the image points, its pitch and roll, and its field of view. Internal to
// resolvePoses.
#pragma once

#include "core/mosaic/plan_matching.h"
#include "core/mosaic/pose_resolver.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pf::mosaic::detail {

// What a pose may come from besides the photo's own metadata.
struct PoseSources {
    const sensor::Camera* forcedCamera = nullptr; // --camera
    const std::vector<sensor::Camera>* catalog = nullptr;
    std::optional<double> takeoffAltitudeM; // above sea level
    const std::vector<PlannedPhoto>* planned = nullptr;
};

// What the poses took from elsewhere than the photo, for the notes.
struct PoseCounts {
    int yawFromTrack = 0;
    int assumedNadir = 0;
    int magnetic = 0;
    std::map<std::string, int> cameras; // photos per camera (field-of-view source)
};

// The pose of work[wi] (not excluded; others of `work` give the flight track); none, with an
// excluding finding in `out`, when its altitude, direction or field of view is unknown or its
// altitude is not a survey altitude.
std::optional<PlacedPhoto> placePhoto(std::vector<PhotoWork>& work, std::size_t wi,
                                      const PoseSources& src, PoseCounts& counts,
                                      ResolvedPoses& out);

// The notes on what the poses assumed (direction along the track, straight down, magnetic north)
// and the photos per camera.
void addPoseNotes(const PoseCounts& counts, std::vector<std::string>& notes);

} // namespace pf::mosaic::detail
