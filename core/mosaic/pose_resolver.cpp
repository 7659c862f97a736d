#include "core/mosaic/pose_resolver.h"

#include "core/geo/gdal_util.h"
#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/mosaic/photo_pose.h"
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

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

using detail::fmt;

double median(std::vector<double> v) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

using Work = detail::PhotoWork;

// The catalog camera --camera names (null when none is named); NotFound, listing the catalog's
// cameras, when the catalog has none of that name.
Result<const sensor::Camera*> forcedCamera(const MosaicOptions& options) {
    if (options.cameraName.empty())
        return static_cast<const sensor::Camera*>(nullptr);
    const sensor::Camera* forced = nullptr;
    for (const auto& c : options.catalog)
        if (lower(c.name) == lower(options.cameraName))
            forced = &c;
    if (forced)
        return forced;
    std::string names;
    for (const auto& c : options.catalog)
        names += (names.empty() ? "" : ", ") + c.name;
    return makeError(ErrorCode::NotFound, "--camera: no camera '" + options.cameraName +
                                              "' in the catalog (known: " + names + ")");
}

// The plan's photo points, optionally one aircraft's (none without a plan); NotFound, listing the
// plan's aircraft, when that aircraft has none.
Result<std::vector<PlannedPhoto>> plannedPhotos(const MosaicOptions& options) {
    std::vector<PlannedPhoto> planned;
    if (!options.plan)
        return planned;
    for (const auto& p : options.plan->photos)
        if (options.planAircraft.empty() || lower(p.aircraft) == lower(options.planAircraft))
            planned.push_back(p);
    if (!planned.empty())
        return planned;
    std::vector<std::string> names;
    for (const auto& p : options.plan->photos)
        if (std::find(names.begin(), names.end(), p.aircraft) == names.end())
            names.push_back(p.aircraft);
    std::string list;
    for (const auto& n : names)
        list += (list.empty() ? "" : ", ") + n;
    return makeError(ErrorCode::NotFound, "--aircraft: the plan has no photos of '" +
                                              options.planAircraft + "' (its aircraft: " + list +
                                              ")");
}

// The photos in capture order: EXIF time, then file name.
std::vector<Work> captureOrder(const std::vector<PhotoMetadata>& metas) {
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
    return work;
}

// The matching frame's centre: the middle of the plan's area, else the median of its photo points,
// else of the photos' positions.
geo::LonLat matchingCentre(const std::vector<geo::GeoPolygon>& area,
                           const std::vector<PlannedPhoto>& planned,
                           const std::vector<Work>& work) {
    geo::LonLat centre{0, 0};
    std::vector<double> lons, lats;
    if (!area.empty()) {
        for (const auto& poly : area)
            for (const auto& p : poly.outer) {
                lons.push_back(p.lon);
                lats.push_back(p.lat);
            }
        const auto [lo0, lo1] = std::minmax_element(lons.begin(), lons.end());
        const auto [la0, la1] = std::minmax_element(lats.begin(), lats.end());
        return {0.5 * (*lo0 + *lo1), 0.5 * (*la0 + *la1)};
    }
    if (!planned.empty())
        for (const auto& p : planned) {
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
    return centre;
}

std::string distanceText(double d) {
    return d >= 2000 ? fmt("%.1f km", d / 1000.0) : fmt("%.0f m", d);
}

// With a plan: photos whose nadir point is further from the planned area (or the planned points)
// than 200 m or three footprint diagonals belong to another site.
void excludeFarFromPlan(std::vector<Work>& work, const std::vector<PlannedPhoto>& planned,
                        const std::vector<geo::Vec2>& plannedLocal,
                        const geo::MultiPolygon& areaLocal, ResolvedPoses& out) {
    double diag = 0.0;
    for (const auto& p : planned)
        diag = std::max(diag, std::hypot(p.footprintAcrossM, p.footprintAlongM));
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
            detail::addFinding(out, w, PhotoFinding::Kind::OtherSite, true,
                               distanceText(d) + " from the " +
                                   (areaLocal.empty() ? "planned photo points" : "planned area") +
                                   ": a photo of another site (not mosaicked)");
    }
}

// Without a plan the site is the largest group of photos within 200 m of each other; the others
// belong to another site.
void excludeOtherGroups(std::vector<Work>& work, ResolvedPoses& out) {
    const double reach = 200.0;
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
    const int main = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
    for (int i : idx) {
        if (group[i] == main)
            continue;
        double d = 1e300;
        for (int j : idx)
            if (group[j] == main)
                d = std::min(d, (*work[i].local - *work[j].local).norm());
        detail::addFinding(out, work[i], PhotoFinding::Kind::OtherSite, true,
                           distanceText(d) +
                               " from the other photos: a photo of another site (not mosaicked)");
    }
}

// Photos taken on the ground (before take-off, after landing) must not take a planned point.
void excludeOnGround(std::vector<Work>& work, ResolvedPoses& out) {
    for (auto& w : work)
        if (!w.excluded && w.meta->relativeAltitudeM && *w.meta->relativeAltitudeM < 2.0)
            detail::addFinding(out, w, PhotoFinding::Kind::NoAltitude, true,
                               fmt("%.1f m", *w.meta->relativeAltitudeM) +
                                   " above take-off (XMP relative altitude): taken on the ground");
}

// How far a photo may lie from its planned point: --match-tolerance, else less than half the
// spacing between consecutive planned photos, so that a photo can only be near one of them: 40 %
// of the median step (the along-track spacing), at least 3 m.
double matchTolerance(const MosaicOptions& options, const std::vector<PlannedPhoto>& planned,
                      const std::vector<geo::Vec2>& plannedLocal) {
    if (options.matchToleranceM > 0)
        return options.matchToleranceM;
    std::vector<double> steps;
    for (std::size_t j = 1; j < plannedLocal.size(); ++j)
        if (planned[j].aircraft == planned[j - 1].aircraft)
            steps.push_back((plannedLocal[j] - plannedLocal[j - 1]).norm());
    return std::max(3.0, steps.empty() ? 10.0 : 0.4 * median(steps));
}

// Take-off height above sea level, for photos that only know their absolute altitude: given, else
// estimated from at least 3 matched photos' GPS altitudes against their planned ones (with a note).
std::optional<double> takeoffAltitude(const MosaicOptions& options, const std::vector<Work>& work,
                                      const std::vector<PlannedPhoto>& planned,
                                      std::vector<std::string>& notes) {
    std::optional<double> takeoff = options.takeoffAltitudeM;
    if (takeoff || planned.empty())
        return takeoff;
    std::vector<double> diffs;
    for (const auto& w : work) {
        if (w.excluded || w.planned < 0 || w.inOrder || w.meta->relativeAltitudeM)
            continue;
        const auto abs = w.meta->gpsAltitudeM ? w.meta->gpsAltitudeM : w.meta->absoluteAltitudeM;
        if (abs)
            diffs.push_back(*abs - planned[w.planned].altitudeM);
    }
    if (diffs.size() >= 3) {
        takeoff = median(diffs);
        notes.push_back("take-off altitude " + fmt("%.1f m", *takeoff) +
                        " above sea level, estimated from " + std::to_string(diffs.size()) +
                        " photos' GPS altitudes against their planned altitudes (give "
                        "--takeoff-alt to set it)");
    }
    return takeoff;
}

// Planned points without a photo, for the aircraft the photos belong to; a note for each aircraft
// none of whose points has a photo.
void addMissing(const std::vector<Work>& work, const std::vector<int>& takenBy,
                ResolvedPoses& out) {
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

// The stages: the named camera and the plan's points; the photos in capture order, in a local frame
// round the site; photos of another site or taken on the ground left out; the rest matched to the
// plan; the take-off altitude; every photo's pose; the planned points without a photo.
Result<ResolvedPoses> resolvePoses(const std::vector<PhotoMetadata>& metas,
                                   const MosaicOptions& options) {
    ResolvedPoses out;
    auto forced = forcedCamera(options);
    if (!forced)
        return forced.error();
    auto planned = plannedPhotos(options);
    if (!planned)
        return planned.error();
    out.planned = std::move(*planned);
    const bool havePlan = !out.planned.empty();

    std::vector<Work> work = captureOrder(metas);
    const std::vector<geo::GeoPolygon> area =
        options.plan ? options.plan->area : std::vector<geo::GeoPolygon>{};
    const geo::LonLat centre = matchingCentre(area, out.planned, work);
    const bool anyPosition =
        std::any_of(work.begin(), work.end(), [](const Work& w) { return w.position.has_value(); });
    const char* noPosition =
        "no GPS position in its EXIF or XMP, and no plan to place it by (give --plan)";
    if (!havePlan && !anyPosition) {
        for (auto& w : work)
            detail::addFinding(out, w, PhotoFinding::Kind::NoPosition, true, noPosition);
        return out;
    }
    auto frameR = geo::LocalFrame::create(centre);
    if (!frameR)
        return frameR.error();
    const geo::LocalFrame& frame = *frameR;
    for (auto& w : work)
        if (w.position)
            w.local = frame.toLocal(*w.position);
    std::vector<geo::Vec2> plannedLocal;
    for (const auto& p : out.planned)
        plannedLocal.push_back(frame.toLocal(p.position));
    geo::MultiPolygon areaLocal;
    for (const auto& poly : area)
        areaLocal.push_back(frame.toLocal(poly));

    if (havePlan)
        excludeFarFromPlan(work, out.planned, plannedLocal, areaLocal, out);
    else
        excludeOtherGroups(work, out);
    excludeOnGround(work, out);
    std::vector<int> takenBy(out.planned.size(), -1);
    if (havePlan) {
        takenBy = detail::matchToPlan(work, out.planned, plannedLocal,
                                      matchTolerance(options, out.planned, plannedLocal),
                                      anyPosition, out);
    } else {
        for (auto& w : work)
            if (!w.position)
                detail::addFinding(out, w, PhotoFinding::Kind::NoPosition, true, noPosition);
    }

    detail::PoseSources sources;
    sources.forcedCamera = *forced;
    sources.catalog = &options.catalog;
    sources.takeoffAltitudeM = takeoffAltitude(options, work, out.planned, out.notes);
    sources.planned = &out.planned;
    detail::PoseCounts counts;
    for (std::size_t wi = 0; wi < work.size(); ++wi)
        if (!work[wi].excluded)
            if (auto p = detail::placePhoto(work, wi, sources, counts, out))
                out.photos.push_back(std::move(*p));
    detail::addPoseNotes(counts, out.notes);
    if (havePlan)
        addMissing(work, takenBy, out);
    return out;
}

} // namespace pf::mosaic
