// What a photo file says about itself: image size, EXIF GPS position and altitude, camera make and
// model, XMP gimbal angles and relative altitude (DJI), read through GDAL's JPEG driver.
#pragma once

#include "core/geo/types.h"
#include "core/result.h"

#include <optional>
#include <string>

namespace pf::mosaic {

struct PhotoMetadata {
    std::string path;
    int widthPx = 0; // as stored (EXIF orientation not applied)
    int heightPx = 0;
    int orientation = 1; // EXIF Orientation, 1..8 (1: stored upright)

    std::optional<geo::LonLat> position; // EXIF GPS, else XMP GpsLatitude/GpsLongitude
    std::optional<double>
        gpsAltitudeM; // EXIF GPSAltitude (above sea level, sign from GPSAltitudeRef)
    std::optional<double> relativeAltitudeM; // XMP RelativeAltitude: above the take-off point
    std::optional<double> absoluteAltitudeM; // XMP AbsoluteAltitude
    std::optional<double> gimbalPitchDeg;    // XMP GimbalPitchDegree: -90 looks straight down
    std::optional<double> gimbalYawDeg;      // XMP GimbalYawDegree: clockwise from north
    std::optional<double> gimbalRollDeg;     // XMP GimbalRollDegree
    std::optional<double> flightYawDeg;      // XMP FlightYawDegree (the aircraft's heading)
    std::optional<double> imageDirectionDeg; // EXIF GPSImgDirection (true or magnetic, see ref)
    bool imageDirectionMagnetic = false;     // GPSImgDirectionRef M

    std::string make;  // EXIF Make, trimmed
    std::string model; // EXIF Model, trimmed
    std::optional<double> focalLengthMm;
    std::optional<double> focalLength35mmMm; // EXIF FocalLengthIn35mmFilm
    std::string dateTime;                    // EXIF DateTimeOriginal (+ sub-seconds), sortable text

    bool hasXmp = false;
};

// Reads the metadata of one photo. Errors name the file: not readable, not an image, not RGB or
// grey.
Result<PhotoMetadata> readPhotoMetadata(const std::string& path);

// Decodes the whole photo at its smallest resolution (cheap with JPEG's scaled decoding) and fails
// if the data is damaged (truncated, corrupt entropy data), so a damaged photo is refused before
// the seams are drawn rather than leaving a hole in the mosaic.
Status checkPhotoDecodes(const std::string& path);

namespace detail {
// "(49) (0) (43.2)" -> the values; EXIF rationals and numbers as GDAL prints them.
std::optional<double> exifNumber(const std::string& text, int index = 0);
// Degrees from an EXIF GPS triple "(d) (m) (s)" and its reference letter (S and W negative).
std::optional<double> exifDegrees(const std::string& triple, const std::string& ref);
// The value of an XMP property by its local name, in attribute (prefix:Name="v") or element form
// (<prefix:Name>v</prefix:Name>), whatever the namespace prefix.
std::optional<std::string> xmpProperty(const std::string& xmp, const std::string& localName);
std::optional<double> xmpNumber(const std::string& xmp, const std::string& localName);
} // namespace detail

} // namespace pf::mosaic
