#include "core/mosaic/photo_pose.h"

#include <algorithm>
#include <cmath>

namespace pf::mosaic::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

double normaliseDeg(double a) {
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360.0 : a;
}

struct Fov {
    double longDeg = 0.0;
    double shortDeg = 0.0;
    std::string name;
};

// The catalog camera's fields of view for this photo. A photo whose aspect differs from the
// camera's (a 16:9 mode of a 3:2 sensor) keeps the long side's field of view; the short side
// follows from the photo's square pixels.
Fov fovFromCamera(const sensor::Camera& cam, const PhotoMetadata& m) {
    Fov f{sensor::horizontalFovDeg(cam), sensor::verticalFovDeg(cam), cam.name};
    const double camAspect = static_cast<double>(std::max(cam.imageWidthPx, cam.imageHeightPx)) /
                             std::max(1, std::min(cam.imageWidthPx, cam.imageHeightPx));
    const double photoAspect =
        static_cast<double>(std::max(m.widthPx, m.heightPx)) / std::min(m.widthPx, m.heightPx);
    if (cam.imageWidthPx > 0 && cam.imageHeightPx > 0 &&
        std::abs(camAspect / photoAspect - 1.0) > 0.02)
        f.shortDeg = 2.0 * std::atan(std::tan(f.longDeg * kDeg / 2.0) / photoAspect) / kDeg;
    return f;
}

// From EXIF FocalLengthIn35mmFilm, defined by the diagonal of a 36 x 24 mm frame (43.27 mm).
Fov fovFrom35mm(double f35, const PhotoMetadata& m) {
    const double longPx = std::max(m.widthPx, m.heightPx),
                 shortPx = std::min(m.widthPx, m.heightPx);
    const double halfDiag = 43.2666 / (2.0 * f35); // tan(half the diagonal field of view)
    const double diagPx = std::hypot(longPx, shortPx);
    Fov f;
    f.longDeg = 2.0 * std::atan(halfDiag * longPx / diagPx) / kDeg;
    f.shortDeg = 2.0 * std::atan(halfDiag * shortPx / diagPx) / kDeg;
    f.name = "EXIF 35 mm focal length " + fmt("%.0f mm", f35);
    return f;
}

Fov fovFromPlan(const PlannedPhoto& p) {
    Fov f;
    f.longDeg = 2.0 * std::atan(p.footprintAcrossM / (2.0 * p.altitudeM)) / kDeg;
    f.shortDeg = 2.0 * std::atan(p.footprintAlongM / (2.0 * p.altitudeM)) / kDeg;
    f.name = "the plan's footprint";
    return f;
}

// The altitude above take-off: XMP relative altitude, else GPS altitude less the take-off's, else
// the planned one (a photo placed by capture order takes the plan's). `from` says which.
bool placeAltitude(PhotoWork& w, const PlannedPhoto* plan, const std::optional<double>& takeoff,
                   PlacedPhoto& p, std::string& from, ResolvedPoses& out) {
    const PhotoMetadata& m = *w.meta;
    const auto abs = m.gpsAltitudeM ? m.gpsAltitudeM : m.absoluteAltitudeM;
    if (m.relativeAltitudeM && !w.inOrder) {
        p.altitudeM = *m.relativeAltitudeM;
        from = "XMP relative altitude";
    } else if (abs && takeoff && !w.inOrder) {
        p.altitudeM = *abs - *takeoff;
        from = "GPS altitude";
    } else if (plan) {
        p.altitudeM = plan->altitudeM;
        from = "planned altitude";
    } else {
        addFinding(
            out, w, PhotoFinding::Kind::NoAltitude, true,
            abs ? "only an altitude above sea level (" + fmt("%.1f m", *abs) +
                      ") and no take-off altitude to subtract (give --takeoff-alt M or --plan)"
                : "no altitude in its EXIF or XMP, and no plan to take it from");
        return false;
    }
    if (!(p.altitudeM >= 2.0) || p.altitudeM > 3000.0) {
        addFinding(out, w, PhotoFinding::Kind::NoAltitude, true,
                   fmt("%.1f m", p.altitudeM) + " above take-off (" + from + "): " +
                       (p.altitudeM < 2.0 ? "taken on the ground" : "not a survey altitude"));
        return false;
    }
    return true;
}

// Along the flight track: towards the next photo, or from the previous one, whichever is nearer
// (the photo spacing along a line is shorter than the step to the next line).
std::optional<geo::Vec2> trackDirection(const std::vector<PhotoWork>& work, std::size_t wi) {
    const PhotoWork& w = work[wi];
    std::optional<geo::Vec2> prev, next;
    for (int k = static_cast<int>(wi) - 1; k >= 0 && !prev; --k)
        if (!work[k].excluded && work[k].local && (*work[k].local - *w.local).norm() > 1.0)
            prev = *w.local - *work[k].local;
    for (std::size_t k = wi + 1; k < work.size() && !next; ++k)
        if (!work[k].excluded && work[k].local && (*work[k].local - *w.local).norm() > 1.0)
            next = *work[k].local - *w.local;
    return prev && next ? (prev->norm() < next->norm() ? prev : next) : (prev ? prev : next);
}

// Where the top of the image points: the gimbal's yaw, the flight yaw, the EXIF image direction,
// the planned heading, else along the flight track. `from` says which.
bool placeYaw(std::vector<PhotoWork>& work, std::size_t wi, const PlannedPhoto* plan,
              PlacedPhoto& p, std::string& from, PoseCounts& counts, ResolvedPoses& out) {
    const PhotoMetadata& m = *work[wi].meta;
    if (m.gimbalYawDeg) {
        p.yawDeg = *m.gimbalYawDeg;
        from = "XMP gimbal";
    } else if (m.flightYawDeg) {
        p.yawDeg = *m.flightYawDeg;
        from = "XMP flight yaw";
    } else if (m.imageDirectionDeg) {
        p.yawDeg = *m.imageDirectionDeg;
        from = "EXIF image direction";
        if (m.imageDirectionMagnetic)
            ++counts.magnetic;
    } else if (plan) {
        p.yawDeg = plan->headingDeg;
        from = "planned heading";
    } else {
        const std::optional<geo::Vec2> dir = trackDirection(work, wi);
        if (!dir) {
            addFinding(out, work[wi], PhotoFinding::Kind::NoPosition, true,
                       "no camera direction in its EXIF or XMP, no plan, and no other photo to "
                       "follow the track by");
            return false;
        }
        p.yawDeg = std::atan2(dir->x(), dir->y()) / kDeg;
        from = "yaw from the flight track";
        ++counts.yawFromTrack;
    }
    p.yawDeg = normaliseDeg(p.yawDeg);
    return true;
}

// The field of view: the --camera, the catalog camera of the EXIF make and model, the EXIF 35 mm
// focal length, else the plan's footprint.
std::optional<Fov> fieldOfView(const PhotoMetadata& m, const PlannedPhoto* plan,
                               const PoseSources& src) {
    if (src.forcedCamera)
        return fovFromCamera(*src.forcedCamera, m);
    if (const auto* c = cameraForExif(*src.catalog, m.make, m.model))
        return fovFromCamera(*c, m);
    if (m.focalLength35mmMm)
        return fovFrom35mm(*m.focalLength35mmMm, m);
    if (plan && plan->footprintAcrossM > 0 && plan->footprintAlongM > 0)
        return fovFromPlan(*plan);
    return std::nullopt;
}

} // namespace

std::optional<PlacedPhoto> placePhoto(std::vector<PhotoWork>& work, std::size_t wi,
                                      const PoseSources& src, PoseCounts& counts,
                                      ResolvedPoses& out) {
    PhotoWork& w = work[wi];
    const PhotoMetadata& m = *w.meta;
    const PlannedPhoto* plan = w.planned >= 0 ? &(*src.planned)[w.planned] : nullptr;
    PlacedPhoto p;
    p.meta = m;
    p.position = *w.position;
    p.planned = w.planned;
    p.planOffsetM = w.inOrder ? -1.0 : w.planOffset;

    std::string altFrom, attFrom;
    if (!placeAltitude(w, plan, src.takeoffAltitudeM, p, altFrom, out))
        return std::nullopt;
    if (!placeYaw(work, wi, plan, p, attFrom, counts, out))
        return std::nullopt;
    if (m.gimbalPitchDeg) {
        p.pitchDeg = *m.gimbalPitchDeg;
        p.rollDeg = m.gimbalRollDeg.value_or(0.0);
    } else {
        ++counts.assumedNadir;
    }

    const std::optional<Fov> fov = fieldOfView(m, plan, src);
    if (!fov) {
        const std::string what =
            m.make.empty() && m.model.empty()
                ? std::string("no camera make or model in EXIF")
                : "camera '" + m.make + " " + m.model + "' is not in the catalog";
        addFinding(out, w, PhotoFinding::Kind::NoCamera, true,
                   what + " and no 35 mm focal length: its field of view is unknown (give --camera "
                          "NAME)");
        return std::nullopt;
    }
    p.longSideFovDeg = fov->longDeg;
    p.shortSideFovDeg = fov->shortDeg;
    p.camera = fov->name;
    ++counts.cameras[fov->name];

    const std::string posFrom = w.inOrder ? "plan (capture order)" : (m.position ? "GPS" : "plan");
    p.poseFrom =
        posFrom + ", " + altFrom + ", " + attFrom + (m.gimbalPitchDeg ? "" : ", assumed nadir");
    return p;
}

void addPoseNotes(const PoseCounts& counts, std::vector<std::string>& notes) {
    if (counts.yawFromTrack > 0)
        notes.push_back(
            std::to_string(counts.yawFromTrack) +
            " photo(s) without a camera direction: the top of each image is taken to point along "
            "the flight track");
    if (counts.assumedNadir > 0)
        notes.push_back(std::to_string(counts.assumedNadir) +
                        " photo(s) without gimbal angles in XMP: taken to look straight down");
    if (counts.magnetic > 0)
        notes.push_back(
            std::to_string(counts.magnetic) +
            " photo(s) give their direction from magnetic north: used as true north (the local "
            "declination is not applied)");
    for (const auto& [name, count] : counts.cameras)
        notes.push_back("camera: " + name + " (" + std::to_string(count) + " photo(s))");
}

} // namespace pf::mosaic::detail
