// Matching photos to the plan's photo points: each photo to the nearest free point within a tolerance,
// and photos without a position to the points between their matched neighbours, in capture order.
#pragma once

#include "core/mosaic/pose_resolver.h"

#include <optional>
#include <string>
#include <vector>

namespace pf::mosaic::detail {

// A photo while its pose is resolved.
struct PhotoWork {
    const PhotoMetadata* meta = nullptr;
    std::string file;
    bool excluded = false;
    std::optional<geo::Vec2> local; // position in the matching frame
    std::optional<geo::LonLat> position;
    int planned = -1;
    double planOffset = -1.0;
    bool inOrder = false; // placed by capture order
};

// Records a finding for `w`; an excluding finding takes the photo out of the mosaic.
void addFinding(ResolvedPoses& out, PhotoWork& w, PhotoFinding::Kind kind, bool exclude,
                const std::string& message);

// Matches `work` (in capture order, `local` in the same frame as `plannedLocal`) to the planned
// points, reporting the photos it cannot match into `out`. Returns, for each planned point, the
// photo that took it (-1: none).
std::vector<int> matchToPlan(std::vector<PhotoWork>& work, const std::vector<PlannedPhoto>& points,
                             const std::vector<geo::Vec2>& plannedLocal, double tolerance,
                             bool anyPosition, ResolvedPoses& out);

// printf-style formatting of one number, for messages.
std::string fmt(const char* format, double v);

} // namespace pf::mosaic::detail
