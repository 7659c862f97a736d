// Cameras, ground footprint, ground sample distance and overlap.
#pragma once

#include "core/result.h"

#include <optional>
#include <string>

namespace pf::sensor {

// A camera defined either by its optics (sensor size, focal length) or by its field of view.
// When both are present the optics win; `imageWidthPx`/`imageHeightPx` are always needed for GSD.
// "Width" is the image's long side.
struct Camera {
    std::string name;
    double sensorWidthMm = 0.0;  // long side of the sensor
    double sensorHeightMm = 0.0; // short side
    double focalLengthMm = 0.0;
    int imageWidthPx = 0; // long side
    int imageHeightPx = 0;
    double hfovDeg = 0.0; // field of view across the long side (used when the optics are unset)
    double vfovDeg = 0.0; // field of view across the short side
    // The payload type a DJI WPML mission declares for this camera (wpml:payloadEnumValue, the
    // "type" of the camera's enumeration value in DJI's Cloud API, e.g. 52 for the Matrice 30
    // camera).
    std::optional<int> djiPayloadEnum;
    // How far the camera looks forward from straight down, in degrees along the direction of flight
    // (the gimbal's pitch is -90 + tiltDeg): 0 for nadir photos. Not a property of the camera model
    // but of how a mission points it: planning sets it from the mission's camera tilt
    // (mission::PlannerOptions::cameraTiltDeg); catalogs and mission files never hold it.
    double tiltDeg = 0.0;

    bool hasOptics() const { return sensorWidthMm > 0 && sensorHeightMm > 0 && focalLengthMm > 0; }
    friend bool operator==(const Camera& a, const Camera& b);
    friend bool operator!=(const Camera& a, const Camera& b) { return !(a == b); }
};

// Checks that the camera is usable (positive sizes, FOV in (0, 180), image size > 0).
Status validate(const Camera& cam);

// Field of view across the long side and the short side, in degrees.
double horizontalFovDeg(const Camera& cam);
double verticalFovDeg(const Camera& cam);

// Ground footprint of one photo at altitude h over flat ground, nadir view (paper 004):
// W = 2 h tan(FOVh / 2) across the long side, L = 2 h tan(FOVv / 2) across the short side.
// A camera tilted forward by t (Camera::tiltDeg) sees a trapezoid from h tan(t - v/2) to
// h tan(t + v/2) ahead of the aircraft (v = FOVv), narrowest at its near edge, 2 h tan(FOVh / 2)
// cos(v/2) / cos(t - v/2) wide. Its footprint is the rectangle inside that trapezoid: the near
// edge's width across the track (longSideM, then not always the longer side), the trapezoid's depth
// along it (shortSideM), its centre aheadM ahead of the aircraft. Every photo sees at least that
// rectangle, so overlaps and coverage computed with it hold for the whole photo.
struct Footprint {
    double longSideM = 0.0;  // across the track
    double shortSideM = 0.0; // along the track
    double aheadM = 0.0;     // the centre's distance ahead of the aircraft (0 for nadir photos)
};
Result<Footprint> footprintAt(const Camera& cam, double altitudeM);

// The steepest forward tilt a mission may give its cameras, and how close to the horizon the far
// edge of a tilted photo may come (degrees from straight down): beyond, the far part of the photo
// is too slanted to map and the footprint grows without bound.
constexpr double kMaxCameraTiltDeg = 45.0;
constexpr double kMaxFarEdgeFromNadirDeg = 80.0;
// Checks a forward tilt for this camera: a number in [0, kMaxCameraTiltDeg] whose far edge
// (tilt + FOVv / 2) stays within kMaxFarEdgeFromNadirDeg of straight down.
Status checkTilt(const Camera& cam, double tiltDeg);

// Ground sample distance in centimetres per pixel: GSD = h * sensorW / (f * imageW).
Result<double> gsdCmAt(const Camera& cam, double altitudeM);
// Altitude giving the wanted GSD (inverse of gsdCmAt).
Result<double> altitudeForGsd(const Camera& cam, double gsdCm);

// Overlap between consecutive photos along the track (front) and between neighbouring tracks (side),
// each in [0, 1).
struct Overlap {
    double front = 0.7;
    double side = 0.6;
};

// The footprint reduced by the overlaps: what each photo must newly cover. Sensor oriented with its
// long side across the direction of flight (paper 001), so the side overlap applies to the long side
// (spacing between tracks) and the front overlap to the short side (spacing along the track).
struct EffectiveFootprint {
    double acrossM = 0.0; // long side x (1 - side overlap): track spacing
    double alongM = 0.0;  // short side x (1 - front overlap): photo spacing along the track
    Footprint real;       // the full ground footprint
};
Result<EffectiveFootprint> effectiveFootprint(const Camera& cam, double altitudeM, const Overlap& ov);

// The square grid cell side for one aircraft: the longest side of the effective footprint
// (paper 001, section IV). See the implementation for why.
double cellSizeFor(const EffectiveFootprint& fp);

} // namespace pf::sensor
