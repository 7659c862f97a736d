#include "core/io/export_context.h"

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
    if (i < routes.size() && !routes[i].aircraft.empty())
        return routes[i].aircraft;
    return "Route " + std::to_string(i + 1);
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
                if (auto f = sensor::footprintAt(a->camera, *alt); f.ok())
                    fp = *f;
        }
        ctx.footprints.push_back(fp);
    }
    return ctx;
}

ExportContext contextFromImport(const ImportedWaypoints& imported) {
    ExportContext ctx;
    ctx.mission.noFlyZones = imported.noFlyZones;
    ctx.mission.home = imported.home;
    ctx.routes = imported.routes;
    for (auto& r : ctx.routes)
        if (!r.home)
            r.home = imported.home;
    return ctx;
}

} // namespace pf::io
