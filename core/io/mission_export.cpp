#include "core/io/mission_export.h"

#include "core/io/mission_items.h"
#include "core/io/waypoint_format_util.h"
#include "core/route/route_sorties.h"

#include <algorithm>

namespace pf::io {

namespace {

// The routes `indices` of ctx as a context of their own (what one aircraft's display file holds).
ExportContext subContext(const ExportContext& ctx, const std::vector<std::size_t>& indices) {
    ExportContext out;
    out.mission = ctx.mission;
    for (std::size_t i : indices) {
        out.routes.push_back(ctx.routes[i]);
        out.footprints.push_back(ctx.footprintFor(i));
        out.trajectories.push_back(i < ctx.trajectories.size() ? ctx.trajectories[i]
                                                               : std::vector<geo::LonLat>{});
        out.labels.push_back(ctx.routeLabel(i));
    }
    return out;
}

// What a display file draws: every route, an aircraft needing several batteries as one route per
// sortie ("Falcon 8, sortie 2 of 5") when `perSortie`; `owner[k]` is the route of ctx that route k
// comes from.
ExportContext displayContext(const ExportContext& ctx, bool perSortie,
                             std::vector<std::size_t>& owner) {
    ExportContext out;
    out.mission = ctx.mission;
    owner.clear();
    bool split = false;
    for (std::size_t i = 0; i < ctx.routes.size(); ++i) {
        auto sorties = perSortie ? route::splitSorties(ctx.routes[i], ctx.homeFor(i))
                                 : std::vector<route::Route>{};
        if (sorties.size() < 2) {
            out.routes.push_back(ctx.routes[i]);
            out.footprints.push_back(ctx.footprintFor(i));
            out.labels.push_back(ctx.routeLabel(i));
            owner.push_back(i);
            continue;
        }
        split = true;
        for (std::size_t s = 0; s < sorties.size(); ++s) {
            out.routes.push_back(std::move(sorties[s]));
            out.footprints.push_back(ctx.footprintFor(i));
            out.labels.push_back(ctx.routeLabel(i) + ", sortie " + std::to_string(s + 1) + " of " +
                                 std::to_string(sorties.size()));
            owner.push_back(i);
        }
    }
    // Trajectories drawn for the routes as given still fit them when no route was cut.
    if (!split)
        out.trajectories = ctx.trajectories;
    return out;
}

Status appendReport(MissionExportReport& to, const Result<ExportReport>& r) {
    if (!r)
        return r.error();
    to.files.insert(to.files.end(), r->files.begin(), r->files.end());
    to.notes.insert(to.notes.end(), r->notes.begin(), r->notes.end());
    return {};
}

std::string folderPrefix(const MissionExportRequest& request) {
    return request.folder.empty() ? std::string() : request.folder + "/";
}

// A flight's mission items with the request's options, and with the camera triggered by distance
// (what the warning offers instead); nothing when the route cannot be made into items.
struct FlightItems {
    std::size_t items = 0;
    std::optional<std::size_t> byDistance;
};
std::optional<FlightItems> countItems(const ExportContext& ctx, std::size_t routeIndex,
                                      const ExportOptions& options) {
    auto items = missionItems(ctx, routeIndex, options);
    if (!items)
        return std::nullopt; // the writer reports why the route cannot be written
    FlightItems out{items->size(), std::nullopt};
    if (options.trigger == CameraTrigger::PerPhoto) {
        ExportOptions d = options;
        d.trigger = CameraTrigger::Distance;
        if (auto fewer = missionItems(ctx, routeIndex, d))
            out.byDistance = fewer->size();
    }
    return out;
}

// "sortie 3", "sorties 1 and 2", "sorties 1 to 5", "sorties 1, 2 and 4" (0-based in, 1-based out).
std::string sortieList(const std::vector<std::size_t>& s) {
    if (s.size() == 1)
        return "sortie " + std::to_string(s[0] + 1);
    if (s.size() > 2 && s.back() - s.front() + 1 == s.size())
        return "sorties " + std::to_string(s.front() + 1) + " to " + std::to_string(s.back() + 1);
    std::string out = "sorties ";
    for (std::size_t i = 0; i < s.size(); ++i)
        out += (i == 0 ? "" : i + 1 == s.size() ? " and " : ", ") + std::to_string(s[i] + 1);
    return out;
}

// The one warning of an aircraft whose flights `over` hold more items than its autopilot stores.
std::string itemWarning(const std::string& aircraft, bool several,
                        const std::vector<std::size_t>& over,
                        const std::vector<FlightItems>& counts,
                        const std::vector<std::string>& files, Autopilot autopilot) {
    std::vector<std::size_t> items, byDistance;
    for (std::size_t s : over) {
        items.push_back(counts[s].items);
        if (counts[s].byDistance)
            byDistance.push_back(*counts[s].byDistance);
    }
    std::string where = files[over.front()];
    if (over.size() > 2 && over.back() - over.front() + 1 == over.size())
        where += " to " + files[over.back()];
    else
        for (std::size_t k = 1; k < over.size(); ++k)
            where += (k + 1 == over.size() ? " and " : ", ") + files[over[k]];
    return itemLimitWarning(aircraft + (several ? ", " + sortieList(over) : std::string()) + " (" +
                                where + ")",
                            items, autopilot, byDistance);
}

} // namespace

Result<MissionExportReport> exportVehicleFlights(const ExportContext& ctx, std::size_t i,
                                                 WaypointFormat format, const std::string& path,
                                                 const ExportOptions& options) {
    if (i >= ctx.routes.size())
        return makeError(ErrorCode::InvalidInput,
                         "there is no route " + std::to_string(i + 1) + " to export");
    MissionExportReport report;
    // The aircraft is checked once for all its flights: one note, and no .kmz for an aircraft
    // that is not a DJI Enterprise model.
    auto check = checkAircraftFormat(ctx, i, format, options);
    if (!check)
        return check.error();
    if (!check->note.empty())
        report.notes.push_back(check->note);
    if (check->leaveOut)
        return report;
    const std::size_t extLength = detail::extensionOf(path).size();
    const std::string stem = path.substr(0, path.size() - extLength);
    const std::string ext = path.substr(path.size() - extLength);
    const auto autopilot = autopilotFor(format, options);
    const ExportContext flights = sortieContext(ctx, i);
    const bool several = flights.routes.size() > 1;
    std::vector<std::string> files;
    std::vector<FlightItems> counts(flights.routes.size());
    std::vector<std::size_t> over;
    for (std::size_t s = 0; s < flights.routes.size(); ++s) {
        const std::string file = several ? stem + "-sortie" + std::to_string(s + 1) + ext : path;
        auto r = detail::writeRouteFiles(flights, s, format, file, options);
        if (auto st = appendReport(report, r); !st)
            return st.error();
        files.push_back(detail::baseName(r->files.front()));
        if (!autopilot)
            continue;
        if (auto n = countItems(flights, s, options); n && !fitsAutopilot(n->items, autopilot)) {
            counts[s] = *n;
            over.push_back(s);
        }
    }
    if (!over.empty())
        report.warnings.push_back(
            itemWarning(ctx.routeLabel(i), several, over, counts, files, *autopilot));
    if (several)
        report.notes.push_back(
            ctx.routeLabel(i) + " needs " + std::to_string(flights.routes.size()) +
            " batteries: written as " + std::to_string(flights.routes.size()) +
            " flights, one per battery, each from home and back home (" + files.front() + " to " +
            files.back() + "); no " + formatInfo(format).extension +
            " file flies them all. Fly them in order, changing the battery at home.");
    return report;
}

namespace {

// One aircraft's vehicle files: "<stem>-<aircraft>.<ext>", or one per sortie.
Status exportVehicleRoute(const ExportContext& ctx, std::size_t i, WaypointFormat format,
                          const MissionExportRequest& request, MissionExportReport& report) {
    const std::string path = folderPrefix(request) + request.stem + "-" + routeFileStem(ctx, i) +
                             formatInfo(format).extension;
    auto r = exportVehicleFlights(ctx, i, format, path, request.options);
    if (!r)
        return r.error();
    report.files.insert(report.files.end(), r->files.begin(), r->files.end());
    report.notes.insert(report.notes.end(), r->notes.begin(), r->notes.end());
    report.warnings.insert(report.warnings.end(), r->warnings.begin(), r->warnings.end());
    return {};
}

Status exportDisplayFormat(const ExportContext& ctx, WaypointFormat format,
                           const MissionExportRequest& request, MissionExportReport& report) {
    const auto& info = formatInfo(format);
    // KML is for looking at the flights: each sortie in a folder of its own. GPX and GeoJSON are
    // read back for editing, so they keep each aircraft's route whole (through home between
    // sorties).
    std::vector<std::size_t> owner;
    ExportContext shown = displayContext(ctx, format == WaypointFormat::Kml, owner);
    if (format == WaypointFormat::Kml && request.kmlTrajectories)
        (void)addTrajectories(shown); // without them the KML still holds every waypoint
    const std::string prefix = folderPrefix(request) + request.stem;
    if (request.perAircraft)
        for (std::size_t i = 0; i < ctx.routes.size(); ++i) {
            std::vector<std::size_t> mine;
            for (std::size_t k = 0; k < owner.size(); ++k)
                if (owner[k] == i)
                    mine.push_back(k);
            const std::string path = prefix + "-" + routeFileStem(ctx, i) + info.extension;
            if (auto st = exportCombined(subContext(shown, mine), format, path, request.options);
                !st)
                return st;
            report.files.push_back(path);
        }
    if (request.combined && (ctx.routes.size() > 1 || !request.perAircraft)) {
        const std::string path = prefix + info.extension;
        if (auto st = exportCombined(shown, format, path, request.options); !st)
            return st;
        report.files.push_back(path);
    }
    return {};
}

} // namespace

std::optional<Autopilot> autopilotFor(WaypointFormat format, const ExportOptions& options) {
    if (format == WaypointFormat::QgcPlan)
        return options.firmware == QgcFirmware::PX4 ? Autopilot::PX4 : Autopilot::ArduPilot;
    if (format == WaypointFormat::QgcWpl)
        return Autopilot::ArduPilot;
    return std::nullopt;
}

std::string flightItemWarning(const ExportContext& ctx, std::size_t routeIndex,
                              const ExportOptions& options, std::optional<Autopilot> autopilot,
                              const std::string& name) {
    const auto n = countItems(ctx, routeIndex, options);
    if (!n)
        return {};
    return itemLimitWarning(name.empty() ? ctx.routeLabel(routeIndex) : name, n->items, autopilot,
                            n->byDistance);
}

ExportContext sortieContext(const ExportContext& ctx, std::size_t i) {
    auto sorties = route::splitSorties(ctx.routes[i], ctx.homeFor(i));
    if (sorties.size() < 2)
        return subContext(ctx, {i});
    ExportContext out;
    out.mission = ctx.mission;
    // Every sortie comes back home, the last one too (the plan's flight times count them so).
    out.mission.landing.reset();
    for (std::size_t s = 0; s < sorties.size(); ++s) {
        if (!sorties[s].home)
            sorties[s].home = ctx.homeFor(i);
        out.routes.push_back(std::move(sorties[s]));
        out.footprints.push_back(ctx.footprintFor(i));
        out.labels.push_back(ctx.routeLabel(i) + ", sortie " + std::to_string(s + 1));
    }
    return out;
}

std::size_t sortieCount(const ExportContext& ctx, std::size_t i) {
    return std::max<std::size_t>(1, route::sortieRanges(ctx.routes[i], ctx.homeFor(i)).size());
}

ExportContext sortieFlight(const ExportContext& ctx, std::size_t i, std::size_t sortie) {
    const ExportContext all = sortieContext(ctx, i);
    const std::size_t s = std::min(sortie, all.routes.size() - 1);
    ExportContext one = subContext(all, {s});
    if (all.routes.size() > 1)
        one.labels = {all.routeLabel(s) + " of " + std::to_string(all.routes.size())};
    return one;
}

Result<MissionExportReport> exportFormat(const ExportContext& ctx, WaypointFormat format,
                                         const MissionExportRequest& request) {
    MissionExportReport report;
    if (formatInfo(format).vehicle) {
        for (std::size_t i = 0; i < ctx.routes.size(); ++i)
            if (auto st = exportVehicleRoute(ctx, i, format, request, report); !st)
                return st.error();
    } else if (auto st = exportDisplayFormat(ctx, format, request, report); !st) {
        return st.error();
    }
    return report;
}

Result<MissionExportReport> exportMission(const mission::Mission& mission,
                                          const std::vector<route::Route>& routes,
                                          const MissionExportRequest& request) {
    if (routes.empty())
        return makeError(ErrorCode::InvalidInput,
                         "nothing to export: no route is planned or chosen");
    if (request.formats.empty())
        return makeError(ErrorCode::InvalidInput, "no waypoint format chosen");
    const ExportContext ctx = makeExportContext(mission, routes);
    MissionExportReport all;
    for (const auto format : request.formats) {
        auto r = exportFormat(ctx, format, request);
        if (!r)
            return r.error();
        all.files.insert(all.files.end(), r->files.begin(), r->files.end());
        all.notes.insert(all.notes.end(), r->notes.begin(), r->notes.end());
        all.warnings.insert(all.warnings.end(), r->warnings.begin(), r->warnings.end());
    }
    return all;
}

} // namespace pf::io
