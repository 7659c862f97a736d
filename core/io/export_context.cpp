#include "core/io/export_context.h"

#include "core/geo/local_frame.h"

namespace pf::io {

const mission::AircraftConfig* ExportContext::aircraftFor(std::size_t i) const {
    if (i >= routes.size())
        return nullptr;
    for (const auto& a : mission.aircraft)
        if (a.name == routes[i].aircraft)
            return &a;
    return nullptr;
}

std::optional<geo::LonLat> ExportContext::homeFor(std::size_t i) const {
    if (i < routes.size() && routes[i].home)
        return routes[i].home;
    if (const auto* a = aircraftFor(i); a && a->home)
        return a->home;
    return mission.home;
}

std::optional<geo::LonLat> ExportContext::landingFor(std::size_t i) const {
    if (mission.landing)
        return mission.landing;
    return homeFor(i);
}

std::string ExportContext::routeLabel(std::size_t i) const {
    if (i < labels.size() && !labels[i].empty())
        return labels[i];
    if (i < routes.size() && !routes[i].aircraft.empty())
        return routes[i].aircraft;
    return "Route " + std::to_string(i + 1);
}

fleet::AircraftKind ExportContext::kindFor(std::size_t i) const {
    const auto* a = aircraftFor(i);
    return a ? a->kind : fleet::AircraftKind::Multirotor;
}

double ExportContext::gimbalPitchDeg(std::size_t i) const {
    return fleet::fliesAsPlane(kindFor(i)) ? -90.0 : -90.0 + mission.options.cameraTiltDeg;
}

std::string planeFormatError(const ExportContext& ctx, std::size_t i, const std::string& format) {
    const fleet::AircraftKind k = ctx.kindFor(i);
    if (!fleet::fliesAsPlane(k))
        return {};
    return ctx.routeLabel(i) + " is a " + fleet::aircraftKindLabel(k) + " aircraft: " + format +
           " missions are flown by DJI multirotors only, which stop and turn on the spot; export a "
           "QGroundControl .plan or a .waypoints file for its ArduPilot or PX4 autopilot instead";
}

std::optional<sensor::Footprint> ExportContext::footprintFor(std::size_t i) const {
    return i < footprints.size() ? footprints[i] : std::nullopt;
}

ExportContext makeExportContext(const mission::Mission& mission, std::vector<route::Route> routes) {
    ExportContext ctx;
    ctx.mission = mission;
    ctx.routes = std::move(routes);
    for (std::size_t i = 0; i < ctx.routes.size(); ++i) {
        std::optional<sensor::Footprint> fp;
        if (const auto* a = ctx.aircraftFor(i)) {
            std::optional<double> alt = a->altitudeM;
            if (!alt && a->gsdCm)
                if (auto h = sensor::altitudeForGsd(a->camera, *a->gsdCm); h.ok())
                    alt = *h;
            if (!alt)
                for (const auto& w : ctx.routes[i].waypoints)
                    if (w.kind == route::WaypointKind::Photo) {
                        alt = w.altitudeM;
                        break;
                    }
            if (alt)
                // As the mission points the camera: an oblique photo's footprint lies ahead.
                if (auto f = sensor::footprintAt(mission::pointedCamera(*a, ctx.mission.options), *alt);
                    f.ok())
                    fp = *f;
        }
        ctx.footprints.push_back(fp);
    }
    return ctx;
}

Status addTrajectories(ExportContext& ctx, const route::TrajectoryOptions& options) {
    ctx.trajectories.assign(ctx.routes.size(), {});
    std::optional<geo::LonLat> origin;
    for (const auto& r : ctx.routes)
        if (!origin && !r.waypoints.empty())
            origin = r.waypoints.front().position;
    if (!origin)
        return {};
    auto frame = ctx.mission.area.outer.empty() ? geo::LocalFrame::create(*origin)
                                                : geo::LocalFrame::forArea(ctx.mission.area);
    if (!frame)
        return frame.error();
    std::vector<geo::GeoPolygon> zones;
    for (const auto& z : ctx.mission.noFlyZones)
        zones.push_back(z.polygon);
    const geo::MultiPolygon keepOut =
        route::keepOutZones(zones, *frame, ctx.mission.options.safetyMarginM);
    for (std::size_t i = 0; i < ctx.routes.size(); ++i) {
        route::Route r = ctx.routes[i];
        r.home = ctx.homeFor(i);
        auto t = route::buildTrajectory(r, *frame, keepOut, options);
        if (!t)
            return makeError(t.error().code, ctx.routeLabel(i) + ": " + t.error().message);
        ctx.trajectories[i] = route::toGeo(*t, *frame);
    }
    return {};
}

std::optional<double> cameraTiltFromPitch(double pitchDeg) {
    const double tilt = 90.0 + pitchDeg;
    if (!std::isfinite(tilt) || tilt < 0.0 || tilt > sensor::kMaxCameraTiltDeg)
        return std::nullopt;
    return tilt;
}

ExportContext contextFromImport(const ImportedWaypoints& imported) {
    ExportContext ctx;
    ctx.mission.noFlyZones = imported.noFlyZones;
    ctx.mission.home = imported.home;
    ctx.mission.options.cameraTiltDeg = imported.cameraTiltDeg.value_or(0.0);
    ctx.routes = imported.routes;
    for (auto& r : ctx.routes)
        if (!r.home)
            r.home = imported.home;
    for (std::size_t i = 0; i < ctx.routes.size() && i < imported.kinds.size(); ++i) {
        if (!imported.kinds[i] || !fleet::fliesAsPlane(*imported.kinds[i]) || ctx.aircraftFor(i))
            continue;
        mission::AircraftConfig a;
        a.name = ctx.routes[i].aircraft;
        a.kind = *imported.kinds[i];
        a.cruiseSpeedMps = ctx.routes[i].cruiseSpeedMps;
        ctx.mission.aircraft.push_back(a);
    }
    return ctx;
}

std::optional<double> homeElevation(const route::Route& route, const ExportOptions& options) {
    if (route.homeElevationM)
        return route.homeElevationM;
    return options.homeElevationM;
}

std::optional<double> altitudeAmsl(const route::Route& route, const route::Waypoint& w, const ExportOptions& options) {
    if (auto h = homeElevation(route, options))
        return *h + w.altitudeM;
    return std::nullopt;
}

} // namespace pf::io
