// Camera geometry: fields of view, ground footprint, GSD <-> altitude and the effective footprint.
#include "core/sensor/camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pf::sensor {

namespace {

constexpr double kPi = 3.14159265358979323846;
double toRad(double deg) { return deg * kPi / 180.0; }
double toDeg(double rad) { return rad * 180.0 / kPi; }

// Shortest decimal form that still says what the user typed ("0.7", "1e-09", "inf").
std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string label(const Camera& cam) { return cam.name.empty() ? std::string("camera") : "camera '" + cam.name + "'"; }

Error invalid(const Camera& cam, const std::string& what) {
    return makeError(ErrorCode::InvalidInput, label(cam) + ": " + what);
}

Status checkAltitude(double altitudeM) {
    if (!std::isfinite(altitudeM) || altitudeM <= 0.0)
        return makeError(ErrorCode::InvalidInput,
                         "altitude must be a number greater than 0 m (got " + num(altitudeM) + " m)");
    return {};
}

Status checkOverlap(double v, const char* which) {
    if (!std::isfinite(v) || v < 0.0 || v >= 1.0)
        return makeError(ErrorCode::InvalidInput, std::string(which) +
                                                      " overlap must be at least 0 and less than 1 (got " +
                                                      num(v) + ")");
    return {};
}

// Ground width covered per metre of altitude across the long side: sensorW / f = 2 tan(FOVh / 2).
// Computed from the optics directly when they are known so that no trigonometric round trip blurs
// the hand-checkable ratio.
double longSidePerMetre(const Camera& cam) {
    if (cam.hasOptics())
        return cam.sensorWidthMm / cam.focalLengthMm;
    return 2.0 * std::tan(toRad(cam.hfovDeg) / 2.0);
}

double shortSidePerMetre(const Camera& cam) {
    if (cam.hasOptics())
        return cam.sensorHeightMm / cam.focalLengthMm;
    return 2.0 * std::tan(toRad(cam.vfovDeg) / 2.0);
}

} // namespace

bool operator==(const Camera& a, const Camera& b) {
    return a.name == b.name && a.sensorWidthMm == b.sensorWidthMm &&
           a.sensorHeightMm == b.sensorHeightMm && a.focalLengthMm == b.focalLengthMm &&
           a.imageWidthPx == b.imageWidthPx && a.imageHeightPx == b.imageHeightPx &&
           a.hfovDeg == b.hfovDeg && a.vfovDeg == b.vfovDeg && a.djiPayloadEnum == b.djiPayloadEnum &&
           a.tiltDeg == b.tiltDeg;
}

Status validate(const Camera& cam) {
    const double fields[] = {cam.sensorWidthMm, cam.sensorHeightMm, cam.focalLengthMm, cam.hfovDeg, cam.vfovDeg};
    for (double v : fields)
        if (!std::isfinite(v))
            return invalid(cam, "every size and angle must be a finite number");

    if (cam.imageWidthPx <= 0 || cam.imageHeightPx <= 0)
        return invalid(cam, "image size must be positive (got " + std::to_string(cam.imageWidthPx) + " x " +
                                std::to_string(cam.imageHeightPx) + " px)");
    if (cam.imageWidthPx < cam.imageHeightPx)
        return invalid(cam, "image width is the long side and must not be smaller than the height (got " +
                                std::to_string(cam.imageWidthPx) + " x " + std::to_string(cam.imageHeightPx) +
                                " px)");

    // A camera is defined by its optics as soon as any optical value is given: then all of them must
    // be right, otherwise a typo (a zero sensor height) would silently fall back to the FOV.
    const bool anyOptics = cam.sensorWidthMm != 0.0 || cam.sensorHeightMm != 0.0 || cam.focalLengthMm != 0.0;
    if (anyOptics) {
        if (cam.sensorWidthMm <= 0.0)
            return invalid(cam, "sensor width must be greater than 0 mm (got " + num(cam.sensorWidthMm) + " mm)");
        if (cam.sensorHeightMm <= 0.0)
            return invalid(cam, "sensor height must be greater than 0 mm (got " + num(cam.sensorHeightMm) + " mm)");
        if (cam.focalLengthMm <= 0.0)
            return invalid(cam, "focal length must be greater than 0 mm (got " + num(cam.focalLengthMm) + " mm)");
        if (cam.sensorWidthMm < cam.sensorHeightMm)
            return invalid(cam, "sensor width is the long side and must not be smaller than the height (got " +
                                    num(cam.sensorWidthMm) + " x " + num(cam.sensorHeightMm) + " mm)");
        return {};
    }

    if (cam.hfovDeg == 0.0 && cam.vfovDeg == 0.0)
        return invalid(cam, "needs either a sensor size and focal length or horizontal and vertical fields of view "
                            "(both fields of view are 0 or missing; each must be between 0 and 180 degrees, "
                            "exclusive)");
    if (cam.hfovDeg <= 0.0 || cam.hfovDeg >= 180.0)
        return invalid(cam, "horizontal field of view must be between 0 and 180 degrees, exclusive (got " +
                                num(cam.hfovDeg) + " degrees)");
    if (cam.vfovDeg <= 0.0 || cam.vfovDeg >= 180.0)
        return invalid(cam, "vertical field of view must be between 0 and 180 degrees, exclusive (got " +
                                num(cam.vfovDeg) + " degrees)");
    if (cam.hfovDeg < cam.vfovDeg)
        return invalid(cam, "horizontal field of view is across the long side and must not be smaller than the "
                            "vertical one (got " + num(cam.hfovDeg) + " and " + num(cam.vfovDeg) + " degrees)");
    return {};
}

double horizontalFovDeg(const Camera& cam) {
    return cam.hasOptics() ? toDeg(2.0 * std::atan(cam.sensorWidthMm / (2.0 * cam.focalLengthMm))) : cam.hfovDeg;
}

double verticalFovDeg(const Camera& cam) {
    return cam.hasOptics() ? toDeg(2.0 * std::atan(cam.sensorHeightMm / (2.0 * cam.focalLengthMm))) : cam.vfovDeg;
}

Status checkTilt(const Camera& cam, double tiltDeg) {
    if (!std::isfinite(tiltDeg) || tiltDeg < 0.0 || tiltDeg > kMaxCameraTiltDeg)
        return makeError(ErrorCode::InvalidInput,
                         "camera tilt must be between 0 (straight down) and " + num(kMaxCameraTiltDeg) +
                             " degrees forward (got " + num(tiltDeg) + ")");
    const double far = tiltDeg + verticalFovDeg(cam) / 2.0;
    if (tiltDeg > 0.0 && far > kMaxFarEdgeFromNadirDeg)
        return invalid(cam, "tilted " + num(tiltDeg) + " degrees, its photos reach " + num(std::round(far)) +
                                " degrees from straight down, too close to the horizon to map (at most " +
                                num(kMaxFarEdgeFromNadirDeg) + "): tilt it less");
    return {};
}

Result<Footprint> footprintAt(const Camera& cam, double altitudeM) {
    if (auto s = validate(cam); !s)
        return s.error();
    if (auto s = checkAltitude(altitudeM); !s)
        return s.error();
    if (cam.tiltDeg == 0.0)
        return Footprint{altitudeM * longSidePerMetre(cam), altitudeM * shortSidePerMetre(cam)};
    if (auto s = checkTilt(cam, cam.tiltDeg); !s)
        return s.error();
    // The tilted view (see Footprint): near edge at t - v/2, far edge at t + v/2 from straight down.
    const double halfV = std::atan(shortSidePerMetre(cam) / 2.0);
    const double t = toRad(cam.tiltDeg);
    const double nearM = altitudeM * std::tan(t - halfV), farM = altitudeM * std::tan(t + halfV);
    const double across = altitudeM * longSidePerMetre(cam) * std::cos(halfV) / std::cos(t - halfV);
    return Footprint{across, farM - nearM, (nearM + farM) / 2.0};
}

Result<double> gsdCmAt(const Camera& cam, double altitudeM) {
    if (auto s = validate(cam); !s)
        return s.error();
    if (auto s = checkAltitude(altitudeM); !s)
        return s.error();
    // Optics: GSD = h * sensorW / (f * imageW). Without optics the same quantity is the ground width
    // of the image divided by its pixels across, which is what the formula means geometrically.
    return 100.0 * altitudeM * longSidePerMetre(cam) / cam.imageWidthPx;
}

Result<double> altitudeForGsd(const Camera& cam, double gsdCm) {
    if (auto s = validate(cam); !s)
        return s.error();
    if (!std::isfinite(gsdCm) || gsdCm <= 0.0)
        return makeError(ErrorCode::InvalidInput,
                         "ground sample distance must be a number greater than 0 cm/px (got " + num(gsdCm) + ")");
    return gsdCm / 100.0 * cam.imageWidthPx / longSidePerMetre(cam);
}

Result<EffectiveFootprint> effectiveFootprint(const Camera& cam, double altitudeM, const Overlap& ov) {
    if (auto s = checkOverlap(ov.front, "front"); !s)
        return s.error();
    if (auto s = checkOverlap(ov.side, "side"); !s)
        return s.error();
    auto fp = footprintAt(cam, altitudeM);
    if (!fp)
        return fp.error();
    EffectiveFootprint out;
    out.real = *fp;
    out.acrossM = fp->longSideM * (1.0 - ov.side);
    out.alongM = fp->shortSideM * (1.0 - ov.front);
    return out;
}

// Why the longest side (paper 001, section IV): the planners work on a square grid and visit each
// cell once, so the cell must be as large as one pass can cover to keep the number of cells - and
// with it the path length, the turns and the planning time - as small as possible. With the sensor's
// long side across the track the longest effective side is normally the track spacing (`acrossM`):
// a track through a column of cells then covers the cells' full width, and the waypoint step puts
// ceil(cell / alongM) photos per cell along the track using the short side, as the paper does.
// Using the shortest side instead would multiply the cells (and the planning cost) by about
// acrossM / alongM for no gain in coverage.
// Caveat: if the overlaps are chosen so that alongM > acrossM (front overlap much lower than the
// side overlap), the longest side is along the track and one track per cell no longer spans the
// cell's width; such settings should be flagged by mission validation.
double cellSizeFor(const EffectiveFootprint& fp) { return std::max(fp.acrossM, fp.alongM); }

} // namespace pf::sensor
