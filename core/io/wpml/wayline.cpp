#include "core/io/wpml/wayline.h"

#include "core/geo/geodesic.h"
#include "core/io/trigger_lanes.h"
#include "core/io/waypoint_format_util.h"

#include <cpl_error.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace pf::io::wpml {

namespace {

// wpml:waypointHeadingAngle is documented in [-180, 180] (0 north, 90 east).
double wpmlHeading(double deg) {
    const double h = detail::normaliseHeading(deg);
    return h > 180.0 ? h - 360.0 : h;
}

// Positions as written: 9 decimals of a degree (0.1 mm).
geo::LonLat asWritten(geo::LonLat p) {
    return {std::round(p.lon * 1e9) / 1e9, std::round(p.lat * 1e9) / 1e9};
}

// A lane's interval from its ends as written, rounded down to a micrometre, so that the last photo,
// (n - 1) intervals after the first, never falls beyond the end waypoint where the group ends.
double intervalDown(const route::Waypoint& first, const route::Waypoint& last, std::size_t photos) {
    const double len = geo::geodesicDistance(asWritten(first.position), asWritten(last.position));
    return std::floor(len / static_cast<double>(photos - 1) * 1e6) / 1e6;
}

} // namespace

Result<std::vector<double>> egm96Undulations(const std::vector<geo::LonLat>& points) {
    OGRSpatialReference egm96, ellipsoidal;
    egm96.SetFromUserInput("EPSG:4326+5773"); // WGS 84 + EGM96 height
    egm96.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    ellipsoidal.importFromEPSG(4979); // WGS 84, ellipsoidal height
    ellipsoidal.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    std::unique_ptr<OGRCoordinateTransformation> t(
        OGRCreateCoordinateTransformation(&egm96, &ellipsoidal));
    std::vector<double> x, y, z(points.size(), 0.0);
    for (const auto& p : points) {
        x.push_back(p.lon);
        y.push_back(p.lat);
    }
    const bool ok =
        t && (points.empty() || t->Transform(points.size(), x.data(), y.data(), z.data()));
    CPLPopErrorHandler();
    if (!ok || std::any_of(z.begin(), z.end(),
                           [](double v) { return !std::isfinite(v) || std::abs(v) > 200.0; }))
        return makeError(
            ErrorCode::Unsupported,
            "heights above sea level need PROJ's EGM96 geoid grid (egm96_15.gtx, Debian package "
            "proj-data) to become the ellipsoidal heights a DJI WPML route flies");
    return z; // the ellipsoidal height of the EGM96 height 0: N
}

Result<Wayline> layOutWayline(const route::Route& route, std::optional<double> homeAmslM,
                              bool absolute) {
    const auto& w = route.waypoints;
    Wayline out;
    out.absolute = absolute && homeAmslM.has_value();
    out.speedMps = std::clamp(route.cruiseSpeedMps, 0.1, kMaxSpeedMps);
    const std::vector<TriggerLane> lanes = findTriggerLanes(w);
    std::size_t lane = 0;
    std::vector<const route::Waypoint*> kept;
    for (std::size_t i = 0; i < w.size();) {
        if (w[i].kind == route::WaypointKind::Photo)
            ++out.photos;
        if (lane < lanes.size() && lanes[lane].first == i) {
            // A lane of equally spaced photos: its two ends, the photos between taken by distance
            // (wpml:actionTrigger "multipleDistance" with takePhoto: "equal-distance interval
            // capture").
            const TriggerLane& l = lanes[lane++];
            out.photos += l.photos() - 1;
            out.groups.push_back({GroupKind::PhotosByDistance, kept.size(), kept.size() + 1,
                                  intervalDown(w[l.first], w[l.last], l.photos())});
            kept.push_back(&w[l.first]);
            kept.push_back(&w[l.last]);
            i = l.last + 1;
            continue;
        }
        if (w[i].kind == route::WaypointKind::Photo)
            out.groups.push_back({GroupKind::Photo, kept.size(), kept.size(), 0.0});
        kept.push_back(&w[i]);
        ++i;
    }
    if (!kept.empty())
        out.groups.insert(out.groups.begin(), ActionGroup{GroupKind::Gimbal, 0, 0, 0.0});

    std::vector<geo::LonLat> positions;
    for (const auto* p : kept)
        positions.push_back(p->position);
    std::vector<double> n(kept.size(), 0.0);
    if (homeAmslM) {
        auto u = egm96Undulations(positions);
        if (!u)
            return u.error();
        n = *u;
    }
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const route::Waypoint& p = *kept[k];
        WaylinePoint q;
        q.position = asWritten(p.position);
        q.headingDeg = wpmlHeading(p.headingDeg);
        const double amsl = homeAmslM.value_or(0.0) + p.altitudeM;
        q.heightM = out.absolute ? amsl : p.altitudeM;
        q.ellipsoidHeightM = homeAmslM ? amsl + n[k] : p.altitudeM;
        out.highestAboveTakeOffM = std::max(out.highestAboveTakeOffM, p.altitudeM);
        out.points.push_back(q);
    }
    return out;
}

} // namespace pf::io::wpml
