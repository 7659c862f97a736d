#include "core/io/wpml_kmz.h"

#include "core/io/waypoint_format_util.h"
#include "core/io/wpml/kmz_archive.h"
#include "core/io/wpml/wayline.h"
#include "core/io/wpml/wpml_enums.h"

#include <algorithm>

namespace pf::io {

namespace {

// The archive layout of the "DJI WPML" overview: "wpmz/template.kml" and "wpmz/waylines.wpml" (the
// optional "wpmz/res" folder holds nothing a survey needs).
constexpr const char* kTemplatePath = "wpmz/template.kml";
constexpr const char* kWaylinesPath = "wpmz/waylines.wpml";

// takeOffSecurityHeight: "[1.2, 1500]" with a remote controller, "[8, 1500]" with a dock.
constexpr double kMinTakeOffSecurityM = 8.0, kMaxTakeOffSecurityM = 1500.0;
// The return-to-home altitude range a DJI Dock reports (rth_altitude: min 20, max 500).
constexpr double kMinRthM = 20.0, kMaxRthM = 500.0;

Result<bool> absoluteHeights(const route::Route& r, const ExportOptions& options,
                             const std::string& label) {
    switch (options.altitudeFrame) {
    case AltitudeFrame::Auto:
        return r.hasTerrain();
    case AltitudeFrame::RelativeToHome:
        return false;
    case AltitudeFrame::AboveSeaLevel:
        if (!homeElevation(r, options))
            return makeError(
                ErrorCode::InvalidInput,
                label +
                    ": heights above sea level need the home's elevation (--home-elevation, or a "
                    "route planned over a terrain model)");
        return true;
    case AltitudeFrame::AboveTerrain:
        break;
    }
    return makeError(
        ErrorCode::Unsupported,
        label + ": a DJI WPML waypoint route has no heights above the terrain (its real-time "
                "terrain following is for the Mavic 3 Enterprise's mapping routes only): export "
                "with the altitude frame auto, relative or amsl");
}

wpml::MissionSettings settingsFor(const ExportContext& ctx, std::size_t i,
                                  const ExportOptions& options, const wpml::Wayline& w,
                                  std::optional<double> homeAmsl) {
    const mission::AircraftConfig* a = ctx.aircraftFor(i);
    wpml::MissionSettings s;
    s.drone = *a->dji;
    s.payloadEnum = *a->camera.djiPayloadEnum;
    if (const auto* p = wpml::findPayloadType(s.payloadEnum))
        s.lens = p->lens;
    s.home = ctx.homeFor(i);
    if (s.home && homeAmsl)
        if (auto n = wpml::egm96Undulations({*s.home}); n)
            s.homeEllipsoidHeightM = *homeAmsl + n->front();
    s.end = options.end;
    const double first = ctx.routes[i].waypoints.front().altitudeM;
    s.takeOffSecurityHeightM = std::clamp(first, kMinTakeOffSecurityM, kMaxTakeOffSecurityM);
    s.transitionalSpeedMps = w.speedMps;
    s.rthHeightM = std::clamp(w.highestAboveTakeOffM, kMinRthM, kMaxRthM);
    s.gimbalPitchDeg = ctx.gimbalPitchDeg(i);
    return s;
}

} // namespace

std::string wpmlAircraftProblem(const ExportContext& ctx, std::size_t i) {
    const std::string label = ctx.routeLabel(i);
    const mission::AircraftConfig* a = ctx.aircraftFor(i);
    if (!a)
        return label +
               ": no catalog aircraft flies this route, so the DJI WPML file cannot say which DJI "
               "aircraft flies it (choose a DJI Enterprise aircraft for it)";
    // Checked before the DJI types: a plane is refused for what it is, whatever types a custom
    // entry gives it. WPML waypoint routes are flown by DJI's multirotors (the aircraft of the
    // Cloud API's Product Support list); a wpml:waypointTurnMode stops or curves on the spot.
    if (fleet::fliesAsPlane(a->kind))
        return label + (a->model == label ? "" : " (" + a->model + ")") + " is a " +
               fleet::aircraftKindLabel(a->kind) +
               " aircraft: DJI WPML routes (DJI Pilot 2, FlightHub 2) are flown by DJI's "
               "multirotors only; export a MAVLink mission (.plan or .waypoints) for it";
    if (!a->dji)
        return label + (a->model == label ? "" : " (" + a->model + ")") +
               " is not a DJI Enterprise aircraft that flies DJI WPML routes (DJI "
               "Pilot 2, FlightHub 2): the catalog gives it no DJI drone type";
    if (!wpml::findDroneType(a->dji->droneEnum, a->dji->subEnum))
        return label + ": DJI drone type " + std::to_string(a->dji->droneEnum) + "/" +
               std::to_string(a->dji->subEnum) + " is not one the DJI WPML documentation lists";
    if (!a->camera.djiPayloadEnum)
        return label + ": the camera \"" + a->camera.name +
               "\" is not a DJI payload (no DJI payload type): DJI "
               "Pilot 2 cannot take photos with it on a WPML route";
    if (!wpml::findPayloadType(*a->camera.djiPayloadEnum))
        return label + ": DJI payload type " + std::to_string(*a->camera.djiPayloadEnum) +
               " is not one the DJI WPML documentation lists";
    return {};
}

Result<WpmlDocuments> wpmlDocuments(const ExportContext& ctx, std::size_t i,
                                    const ExportOptions& options) {
    if (i >= ctx.routes.size())
        return makeError(ErrorCode::InvalidInput,
                         "there is no route " + std::to_string(i + 1) + " to export");
    if (const std::string problem = wpmlAircraftProblem(ctx, i); !problem.empty())
        return makeError(ErrorCode::Unsupported, problem);
    const route::Route& r = ctx.routes[i];
    if (r.waypoints.empty())
        return makeError(ErrorCode::InvalidInput,
                         ctx.routeLabel(i) + ": the route has no waypoints to export");
    auto absolute = absoluteHeights(r, options, ctx.routeLabel(i));
    if (!absolute)
        return absolute.error();
    const std::optional<double> homeAmsl = homeElevation(r, options);
    auto wayline = wpml::layOutWayline(r, homeAmsl, *absolute);
    if (!wayline)
        return makeError(wayline.error().code, ctx.routeLabel(i) + ": " + wayline.error().message);
    const wpml::MissionSettings s = settingsFor(ctx, i, options, *wayline, homeAmsl);
    WpmlDocuments docs;
    docs.templateKml = wpml::templateKml(s, *wayline);
    docs.waylinesWpml = wpml::waylinesWpml(s, *wayline);
    docs.waypoints = wayline->points.size();
    docs.photos = wayline->photos;
    return docs;
}

Status writeWpmlKmz(const ExportContext& ctx, std::size_t i, const std::string& path,
                    const ExportOptions& options) {
    auto docs = wpmlDocuments(ctx, i, options);
    if (!docs)
        return docs.error();
    return wpml::writeZipArchive(
        path, {{kTemplatePath, docs->templateKml}, {kWaylinesPath, docs->waylinesWpml}});
}

} // namespace pf::io
