// Each photo's pose (position, altitude above take-off, camera angles) and camera, from its own
// metadata, the plan and the catalog; and how the photo set matches the plan.
#pragma once

#include "core/mosaic/mosaic_types.h"
#include "core/mosaic/photo_metadata.h"
#include "core/result.h"

#include <string>
#include <vector>

namespace pf::mosaic {

struct PlacedPhoto {
    PhotoMetadata meta;
    geo::LonLat position;
    double altitudeM = 0.0;  // above the take-off point
    double yawDeg = 0.0;     // where the top of the image points, clockwise from true north
    double pitchDeg = -90.0; // -90: straight down
    double rollDeg = 0.0;
    double longSideFovDeg = 0.0;
    double shortSideFovDeg = 0.0;
    std::string camera; // the catalog camera, or where the field of view came from
    int planned = -1;   // index into the plan's photos (after the aircraft filter), -1: none
    double planOffsetM = -1.0;
    std::string poseFrom; // "EXIF GPS, XMP altitude and gimbal", "plan (in order)", ...
};

struct ResolvedPoses {
    std::vector<PlacedPhoto> photos; // in capture order
    std::vector<PhotoFinding> findings;
    std::vector<MissingPhoto> missing;
    std::vector<std::string> notes;
    std::vector<PlannedPhoto> planned; // the plan's photo points used for matching
};

// Places every photo it can; the others get a finding saying why. Fails only on options that name
// something that does not exist (an unknown camera or aircraft).
Result<ResolvedPoses> resolvePoses(const std::vector<PhotoMetadata>& photos,
                                   const MosaicOptions& options);

// The catalog camera for an EXIF make and model (DJI's model codes, then catalog names containing
// the model), or null.
const sensor::Camera* cameraForExif(const std::vector<sensor::Camera>& catalog,
                                    const std::string& make, const std::string& model);

} // namespace pf::mosaic
