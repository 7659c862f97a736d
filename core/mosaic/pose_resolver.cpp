#include "core/mosaic/pose_resolver.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/gdal_util.h"
#include "core/mosaic/plan_matching.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <optional>

namespace pf::mosaic {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

using detail::fmt;

double normaliseDeg(double a) {
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360.0 : a;
}

double median(std::vector<double> v) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
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

using Work = detail::PhotoWork;

} // namespace

const sensor::Camera* cameraForExif(const std::vector<sensor::Camera>& catalog,
                                    const std::string& make, const std::string& model) {
    if (model.empty())
        return nullptr;
    auto byName = [&](const std::string& name) -> const sensor::Camera* {
        for (const auto& c : catalog)
            if (lower(c.name) == lower(name))
                return &c;
        return nullptr;
    };
    // EXIF model codes that do not read like the product's name.
    static const std::pair<const char*, const char*> kCodes[] = {
        {"fc6310", "DJI Phantom 4 Pro camera"},  {"fc6310r", "DJI Phantom 4 Pro camera"},
        {"fc6310s", "DJI Phantom 4 Pro camera"}, {"m3e", "DJI Mavic 3 Enterprise wide camera"},
        {"zenmusep1", "DJI Zenmuse P1 35 mm"},   {"ilce-7rm4", "Sony a7R IV 35 mm"},
        {"ilce-7rm4a", "Sony a7R IV 35 mm"},     {"dsc-rx1rm2", "Sony RX1R II"},
        {"rededge-m", "MicaSense RedEdge-MX"},   {"rededge-mx", "MicaSense RedEdge-MX"},
    };
    const std::string m = lower(model);
    for (const auto& [code, name] : kCodes)
        if (m == code)
            if (const auto* c = byName(name))
                return c;
    if (const auto* c = byName(model))
        return c;
    if (const auto* c = byName(make + " " + model))
        return c;
    if (m.size() >= 3)
        for (const auto& c : catalog)
            if (lower(c.name).find(m) != std::string::npos)
                return &c;
    return nullptr;
}

Result<ResolvedPoses> resolvePoses(const std::vector<PhotoMetadata>& metas,
                                   const MosaicOptions& options) {
    ResolvedPoses out;
    const sensor::Camera* forced = nullptr;
    if (!options.cameraName.empty()) {
        for (const auto& c : options.catalog)
            if (lower(c.name) == lower(options.cameraName))
                forced = &c;
        if (!forced) {
            std::string names;
            for (const auto& c : options.catalog)
                names += (names.empty() ? "" : ", ") + c.name;
            return makeError(ErrorCode::NotFound, "--camera: no camera '" + options.cameraName +
                                                      "' in the catalog (known: " + names + ")");
        }
    }

    // The plan's photo points, optionally one aircraft's.
    if (options.plan) {
        for (const auto& p : options.plan->photos)
            if (options.planAircraft.empty() || lower(p.aircraft) == lower(options.planAircraft))
                out.planned.push_back(p);
        if (out.planned.empty()) {
            std::vector<std::string> names;
            for (const auto& p : options.plan->photos)
                if (std::find(names.begin(), names.end(), p.aircraft) == names.end())
                    names.push_back(p.aircraft);
            std::string list;
            for (const auto& n : names)
                list += (list.empty() ? "" : ", ") + n;
            return makeError(ErrorCode::NotFound, "--aircraft: the plan has no photos of '" +
                                                      options.planAircraft +
                                                      "' (its aircraft: " + list + ")");
        }
    }
    const bool havePlan = !out.planned.empty();

    // Capture order: EXIF time, then file name.
    std::vector<Work> work;
    for (const auto& m : metas) {
        Work w;
        w.meta = &m;
        w.file = geo::detail::fileName(m.path);
        w.position = m.position;
        work.push_back(w);
    }
    std::stable_sort(work.begin(), work.end(), [](const Work& a, const Work& b) {
        if (a.meta->dateTime != b.meta->dateTime && !a.meta->dateTime.empty() &&
            !b.meta->dateTime.empty())
            return a.meta->dateTime < b.meta->dateTime;
        return a.file < b.file;
    });
    auto report = [&](PhotoFinding::Kind kind, Work& w, bool exclude, const std::string& message) {
        detail::addFinding(out, w, kind, exclude, message);
    };

    // The matching frame: centred on the plan's area, else its photos, else the photos' median.
    geo::LonLat centre{0, 0};
    std::vector<geo::GeoPolygon> area =
        options.plan ? options.plan->area : std::vector<geo::GeoPolygon>{};
    {
        std::vector<double> lons, lats;
        if (!area.empty()) {
            for (const auto& poly : area)
                for (const auto& p : poly.outer) {
                    lons.push_back(p.lon);
                    lats.push_back(p.lat);
                }
            const auto [lo0, lo1] = std::minmax_element(lons.begin(), lons.end());
            const auto [la0, la1] = std::minmax_element(lats.begin(), lats.end());
            centre = {0.5 * (*lo0 + *lo1), 0.5 * (*la0 + *la1)};
        } else {
            if (havePlan)
                for (const auto& p : out.planned) {
                    lons.push_back(p.position.lon);
                    lats.push_back(p.position.lat);
                }
            else
                for (const auto& w : work)
                    if (w.position) {
                        lons.push_back(w.position->lon);
                        lats.push_back(w.position->lat);
                    }
            if (!lons.empty())
                centre = {median(lons), median(lats)};
        }
    }
    const bool anyPosition =
        std::any_of(work.begin(), work.end(), [](const Work& w) { return w.position.has_value(); });
    if (!havePlan && !anyPosition) {
        for (auto& w : work)
            report(PhotoFinding::Kind::NoPosition, w, true,
                   "no GPS position in its EXIF or XMP, and no plan to place it by (give --plan)");
        return out;
    }
    auto frameR = geo::LocalFrame::create(centre);
    if (!frameR)
        return frameR.error();
    const geo::LocalFrame& frame = *frameR;
    for (auto& w : work)
        if (w.position)
            w.local = frame.toLocal(*w.position);

    // Reach of the site: photos whose nadir point is further from the area (or the planned points)
    // than this belong to another site.
    double diag = 0.0;
    for (const auto& p : out.planned)
        diag = std::max(diag, std::hypot(p.footprintAcrossM, p.footprintAlongM));
    std::vector<geo::Vec2> plannedLocal;
    for (const auto& p : out.planned)
        plannedLocal.push_back(frame.toLocal(p.position));
    geo::MultiPolygon areaLocal;
    for (const auto& poly : area)
        areaLocal.push_back(frame.toLocal(poly));

    if (havePlan) {
        const double reach = std::max(200.0, 3.0 * diag);
        for (auto& w : work) {
            if (!w.local)
                continue;
            double d = 0.0;
            if (!areaLocal.empty()) {
                d = geo::distanceTo(areaLocal, *w.local);
            } else {
                d = 1e300;
                for (const auto& q : plannedLocal)
                    d = std::min(d, (q - *w.local).norm());
            }
            if (d > reach)
                report(PhotoFinding::Kind::OtherSite, w, true,
                       (d >= 2000 ? fmt("%.1f km", d / 1000.0) : fmt("%.0f m", d)) + " from the " +
                           (areaLocal.empty() ? "planned photo points" : "planned area") +
                           ": a photo of another site (not mosaicked)");
        }
    } else {
        // Without a plan the site is the largest group of photos within reach of each other.
        double reach = 200.0;
        std::vector<int> idx;
        for (int i = 0; i < static_cast<int>(work.size()); ++i)
            if (work[i].local)
                idx.push_back(i);
        std::vector<int> group(work.size(), -1);
        int groups = 0;
        for (int seed : idx) {
            if (group[seed] >= 0)
                continue;
            std::vector<int> stack{seed};
            group[seed] = groups;
            while (!stack.empty()) {
                const int a = stack.back();
                stack.pop_back();
                for (int b : idx)
                    if (group[b] < 0 && (*work[a].local - *work[b].local).norm() <= reach) {
                        group[b] = groups;
                        stack.push_back(b);
                    }
            }
            ++groups;
        }
        std::vector<int> size(groups, 0);
        for (int i : idx)
            ++size[group[i]];
        const int main =
            static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
        for (int i : idx) {
            if (group[i] == main)
                continue;
            double d = 1e300;
            for (int j : idx)
                if (group[j] == main)
                    d = std::min(d, (*work[i].local - *work[j].local).norm());
            report(PhotoFinding::Kind::OtherSite, work[i], true,
                   (d >= 2000 ? fmt("%.1f km", d / 1000.0) : fmt("%.0f m", d)) +
                       " from the other photos: a photo of another site (not mosaicked)");
        }
    }

    // Photos taken on the ground (before take-off, after landing) must not take a planned point.
    for (auto& w : work)
        if (!w.excluded && w.meta->relativeAltitudeM && *w.meta->relativeAltitudeM < 2.0)
            report(PhotoFinding::Kind::NoAltitude, w, true,
                   fmt("%.1f m", *w.meta->relativeAltitudeM) +
                       " above take-off (XMP relative altitude): taken on the ground");

    // Matching to the plan's photo points.
    double tolerance = options.matchToleranceM;
    if (havePlan && !(tolerance > 0)) {
        // Less than half the spacing between consecutive planned photos, so that a photo can only
        // be near one of them: 40 % of the median step (the along-track spacing), at least 3 m.
        std::vector<double> steps;
        for (std::size_t j = 1; j < plannedLocal.size(); ++j)
            if (out.planned[j].aircraft == out.planned[j - 1].aircraft)
                steps.push_back((plannedLocal[j] - plannedLocal[j - 1]).norm());
        tolerance = std::max(3.0, steps.empty() ? 10.0 : 0.4 * median(steps));
    }
    std::vector<int> takenBy(out.planned.size(), -1);
    if (havePlan) {
        takenBy = detail::matchToPlan(work, out.planned, plannedLocal, tolerance, anyPosition, out);
    } else {
        for (auto& w : work)
            if (!w.position)
                report(
                    PhotoFinding::Kind::NoPosition, w, true,
                    "no GPS position in its EXIF or XMP, and no plan to place it by (give --plan)");
    }

    // Take-off height above sea level, for photos that only know their absolute altitude.
    std::optional<double> takeoff = options.takeoffAltitudeM;
    if (!takeoff && havePlan) {
        std::vector<double> diffs;
        for (const auto& w : work) {
            if (w.excluded || w.planned < 0 || w.inOrder || w.meta->relativeAltitudeM)
                continue;
            const auto abs =
                w.meta->gpsAltitudeM ? w.meta->gpsAltitudeM : w.meta->absoluteAltitudeM;
            if (abs)
                diffs.push_back(*abs - out.planned[w.planned].altitudeM);
        }
        if (diffs.size() >= 3) {
            takeoff = median(diffs);
            out.notes.push_back("take-off altitude " + fmt("%.1f m", *takeoff) +
                                " above sea level, estimated from " + std::to_string(diffs.size()) +
                                " photos' GPS altitudes against their planned altitudes (give "
                                "--takeoff-alt to set it)");
        }
    }

    // Altitude, attitude and camera of every photo still in.
    int yawFromTrack = 0, assumedNadir = 0, magnetic = 0;
    std::map<std::string, int> cameras;
    for (std::size_t wi = 0; wi < work.size(); ++wi) {
        Work& w = work[wi];
        if (w.excluded)
            continue;
        const PhotoMetadata& m = *w.meta;
        const PlannedPhoto* plan = w.planned >= 0 ? &out.planned[w.planned] : nullptr;
        PlacedPhoto p;
        p.meta = m;
        p.position = *w.position;
        p.planned = w.planned;
        p.planOffsetM = w.inOrder ? -1.0 : w.planOffset;

        std::string altFrom;
        const auto abs = m.gpsAltitudeM ? m.gpsAltitudeM : m.absoluteAltitudeM;
        if (m.relativeAltitudeM && !w.inOrder) {
            p.altitudeM = *m.relativeAltitudeM;
            altFrom = "XMP relative altitude";
        } else if (abs && takeoff && !w.inOrder) {
            p.altitudeM = *abs - *takeoff;
            altFrom = "GPS altitude";
        } else if (plan) {
            p.altitudeM = plan->altitudeM;
            altFrom = "planned altitude";
        } else {
            report(
                PhotoFinding::Kind::NoAltitude, w, true,
                abs ? "only an altitude above sea level (" + fmt("%.1f m", *abs) +
                          ") and no take-off altitude to subtract (give --takeoff-alt M or --plan)"
                    : "no altitude in its EXIF or XMP, and no plan to take it from");
            continue;
        }
        if (!(p.altitudeM >= 2.0) || p.altitudeM > 3000.0) {
            report(PhotoFinding::Kind::NoAltitude, w, true,
                   fmt("%.1f m", p.altitudeM) + " above take-off (" + altFrom + "): " +
                       (p.altitudeM < 2.0 ? "taken on the ground" : "not a survey altitude"));
            continue;
        }

        std::string attFrom;
        if (m.gimbalYawDeg) {
            p.yawDeg = *m.gimbalYawDeg;
            attFrom = "XMP gimbal";
        } else if (m.flightYawDeg) {
            p.yawDeg = *m.flightYawDeg;
            attFrom = "XMP flight yaw";
        } else if (m.imageDirectionDeg) {
            p.yawDeg = *m.imageDirectionDeg;
            attFrom = "EXIF image direction";
            if (m.imageDirectionMagnetic)
                ++magnetic;
        } else if (plan) {
            p.yawDeg = plan->headingDeg;
            attFrom = "planned heading";
        } else {
            // Along the flight track: towards the next photo, or from the previous one, whichever
            // is nearer (the photo spacing along a line is shorter than the step to the next line).
            std::optional<geo::Vec2> prev, next;
            for (int k = static_cast<int>(wi) - 1; k >= 0 && !prev; --k)
                if (!work[k].excluded && work[k].local && (*work[k].local - *w.local).norm() > 1.0)
                    prev = *w.local - *work[k].local;
            for (std::size_t k = wi + 1; k < work.size() && !next; ++k)
                if (!work[k].excluded && work[k].local && (*work[k].local - *w.local).norm() > 1.0)
                    next = *work[k].local - *w.local;
            std::optional<geo::Vec2> dir =
                prev && next ? (prev->norm() < next->norm() ? prev : next) : (prev ? prev : next);
            if (!dir) {
                report(PhotoFinding::Kind::NoPosition, w, true,
                       "no camera direction in its EXIF or XMP, no plan, and no other photo to "
                       "follow the track by");
                continue;
            }
            p.yawDeg = std::atan2(dir->x(), dir->y()) / kDeg;
            attFrom = "yaw from the flight track";
            ++yawFromTrack;
        }
        p.yawDeg = normaliseDeg(p.yawDeg);
        if (m.gimbalPitchDeg) {
            p.pitchDeg = *m.gimbalPitchDeg;
            p.rollDeg = m.gimbalRollDeg.value_or(0.0);
        } else {
            ++assumedNadir;
        }

        std::optional<Fov> fov;
        if (forced)
            fov = fovFromCamera(*forced, m);
        else if (const auto* c = cameraForExif(options.catalog, m.make, m.model))
            fov = fovFromCamera(*c, m);
        else if (m.focalLength35mmMm)
            fov = fovFrom35mm(*m.focalLength35mmMm, m);
        else if (plan && plan->footprintAcrossM > 0 && plan->footprintAlongM > 0)
            fov = fovFromPlan(*plan);
        if (!fov) {
            const std::string what =
                m.make.empty() && m.model.empty()
                    ? std::string("no camera make or model in EXIF")
                    : "camera '" + m.make + " " + m.model + "' is not in the catalog";
            report(PhotoFinding::Kind::NoCamera, w, true,
                   what + " and no 35 mm focal length: its field of view is unknown (give --camera "
                          "NAME)");
            continue;
        }
        p.longSideFovDeg = fov->longDeg;
        p.shortSideFovDeg = fov->shortDeg;
        p.camera = fov->name;
        ++cameras[fov->name];

        const std::string posFrom =
            w.inOrder ? "plan (capture order)" : (m.position ? "GPS" : "plan");
        p.poseFrom =
            posFrom + ", " + altFrom + ", " + attFrom + (m.gimbalPitchDeg ? "" : ", assumed nadir");
        out.photos.push_back(std::move(p));
    }

    if (yawFromTrack > 0)
        out.notes.push_back(
            std::to_string(yawFromTrack) +
            " photo(s) without a camera direction: the top of each image is taken to point along "
            "the flight track");
    if (assumedNadir > 0)
        out.notes.push_back(std::to_string(assumedNadir) +
                            " photo(s) without gimbal angles in XMP: taken to look straight down");
    if (magnetic > 0)
        out.notes.push_back(
            std::to_string(magnetic) +
            " photo(s) give their direction from magnetic north: used as true north (the local "
            "declination is not applied)");
    for (const auto& [name, count] : cameras)
        out.notes.push_back("camera: " + name + " (" + std::to_string(count) + " photo(s))");

    // Planned points without a photo, for the aircraft the photos belong to.
    if (havePlan) {
        std::map<std::string, int> matchedPerAircraft, plannedPerAircraft;
        for (std::size_t j = 0; j < out.planned.size(); ++j) {
            ++plannedPerAircraft[out.planned[j].aircraft];
            if (takenBy[j] >= 0 && !work[takenBy[j]].excluded)
                ++matchedPerAircraft[out.planned[j].aircraft];
        }
        for (std::size_t j = 0; j < out.planned.size(); ++j) {
            const auto& p = out.planned[j];
            if (matchedPerAircraft[p.aircraft] == 0)
                continue;
            if (takenBy[j] < 0 || work[takenBy[j]].excluded)
                out.missing.push_back({p.label(), p.aircraft, p.seq, p.position});
        }
        for (const auto& [name, count] : plannedPerAircraft)
            if (matchedPerAircraft[name] == 0)
                out.notes.push_back("no photo matches any of the " + std::to_string(count) +
                                    " planned points of " + name +
                                    " (give --aircraft NAME to match one aircraft's photos)");
    }
    return out;
}

} // namespace pf::mosaic
