// The mosaic's inputs, options and report: what the CLI and the GUI hand in and show afterwards.
#pragma once

#include "core/geo/types.h"
#include "core/mosaic/ground_model.h"
#include "core/mosaic/planned_flight.h"
#include "core/sensor/camera.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pf::mosaic {

struct MosaicOptions {
    std::vector<std::string> photos; // photo files (JPEG; any 8-bit RGB or grey raster GDAL reads)
    std::optional<PlannedFlight> plan;   // where the photos were meant to be taken, and the area
    std::string planAircraft;            // match the photos to this aircraft's photo points only
    std::vector<sensor::Camera> catalog; // cameras to recognise from EXIF make/model
    std::string cameraName;              // force this catalog camera for every photo
    double gsdM = 0.0;                   // output ground sample distance; 0: the photos' median
    double featherM = 0.0;               // blend width across seams, ground metres; 0: hard seams
    double matchToleranceM =
        0.0; // photo to planned point; 0: 40 % of the planned photo spacing (>= 3 m)
    std::optional<double>
        takeoffAltitudeM; // above sea level, for photos with only an absolute altitude
    // The ground under the photos in grid coordinates of the output; null: flat at the take-off
    // height. Heights are in the vertical datum of the photos' altitudes above take-off.
    std::shared_ptr<const GroundModel> ground;
    double maxViewAngleDeg = 60.0; // ground seen further than this from the vertical is not used
    std::string outputPath;        // the GeoTIFF (.tif)
    std::string vectorPath;        // footprints, seams, gaps; empty: beside the GeoTIFF (.gpkg)
    bool jpegCompression = true;   // JPEG (quality 90, with a mask); false: lossless DEFLATE
    int threads = 0;               // 0: the machine's cores (at most 8)
    // GDAL's block cache is lowered to this for the run (and restored) so memory stays bounded.
    std::size_t gdalCacheBytes = std::size_t(256) << 20;
    double maxOutputPixels = 4e9; // refuse larger mosaics (suggest a coarser GSD)
};

// Something the user must know about one photo (or the set). Excluded photos are not in the mosaic.
struct PhotoFinding {
    enum class Kind {
        Unreadable,  // not an image, no such file, damaged data
        NoPosition,  // no GPS and nothing to place it by
        NoAltitude,  // no altitude above take-off and nothing to derive it
        NoCamera,    // the camera's field of view is unknown
        OtherSite,   // far from the area (or from the other photos)
        FarFromPlan, // no planned photo point near it (mosaicked where its EXIF says)
        Duplicate,   // a second photo at a planned point (mosaicked)
        Assumption,  // a value assumed or taken from elsewhere (yaw from the track, nadir, plan
                     // altitude)
        Unused,      // every part of it is seen more from above by other photos
    };
    std::string file; // file name; empty for the whole set
    Kind kind = Kind::Assumption;
    bool excluded = false;
    std::string message;
};

// A planned photo point no photo was matched to.
struct MissingPhoto {
    std::string label; // "Falcon 8 #12"
    std::string aircraft;
    int seq = 0;
    geo::LonLat position;
};

// One photo as it went into the mosaic.
struct PlacedPhotoSummary {
    std::string file;
    geo::LonLat position;
    double altitudeM = 0.0; // above take-off
    double yawDeg = 0.0;    // true north
    double pitchDeg = -90.0;
    double rollDeg = 0.0;
    std::string camera;                // catalog name or how the field of view was found
    std::string planned;               // matched planned point ("Falcon 8 #12"), empty if none
    double planOffsetM = -1;           // distance to it, -1 if none
    std::string poseFrom;              // "EXIF GPS + XMP", "plan (in order)", ...
    double gsdM = 0.0;                 // nadir ground resolution
    geo::GeoPolygon footprint;         // WGS84
    std::vector<geo::GeoPolygon> seam; // the part of the mosaic taken from it, WGS84
};

struct GapArea {
    std::vector<geo::GeoPolygon> shape; // WGS84
    double areaM2 = 0.0;
    geo::LonLat centre;
};

struct MosaicReport {
    std::string outputPath;
    std::string vectorPath;
    std::string crsName; // "UTM zone 32N (EPSG:32632)"
    int epsg = 0;
    double gsdM = 0.0;
    int widthPx = 0;
    int heightPx = 0;
    geo::LonLat southWest, northEast; // bounds
    int photosGiven = 0;
    int photosUsed = 0;
    std::vector<PhotoFinding> findings;
    std::vector<MissingPhoto> missing;
    std::vector<PlacedPhotoSummary> photos;
    std::vector<std::string>
        notes; // the set as a whole: take-off altitude estimated, camera found, ...
    // Against the plan's area (zero without a plan): the area, the share of it the mosaic covers
    // and the parts it does not, largest first.
    double areaM2 = 0.0;
    double coveredRatio = 0.0;
    double gapAreaM2 = 0.0;
    std::vector<GapArea> gaps;
    double seconds = 0.0;
    struct StageTime {
        std::string name; // "reading", "seams", "warping", "writing", "vectors"
        double seconds = 0.0;
        double cpuSeconds = 0.0; // all threads of the process
    };
    std::vector<StageTime> stages;
};

} // namespace pf::mosaic
