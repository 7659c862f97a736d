// The mosaic's vector companion: photo footprints, seams, gaps, camera positions and missing
// planned photos as GeoPackage layers in the mosaic's coordinate system, for any GIS.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"

#include <string>
#include <vector>

namespace pf::mosaic {

struct VectorPhoto {
    std::string file;
    bool used = false;   // gives colour to the mosaic
    std::string status;  // "used", "not used: ...", the reason it was left out
    geo::Ring footprint; // grid metres (may be empty)
    geo::MultiPolygon seam;
    geo::Vec2 camera{0, 0};
    double altitudeM = 0.0, yawDeg = 0.0, pitchDeg = -90.0, rollDeg = 0.0, gsdM = 0.0;
    std::string planned;
    double planOffsetM = -1.0;
    std::string poseFrom;
    std::string cameraName;
};

struct VectorPoint {
    std::string label;
    geo::Vec2 at{0, 0};
};

// Writes `path` (a .gpkg, atomically) with the layers footprints, seams, gaps (area_m2),
// camera_positions and missing_photos, all in the coordinate system `wkt`.
Status writeMosaicVectors(const std::string& path, const std::string& wkt,
                          const std::vector<VectorPhoto>& photos,
                          const std::vector<geo::Polygon>& gaps,
                          const std::vector<VectorPoint>& missing);

} // namespace pf::mosaic
