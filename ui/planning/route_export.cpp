#include "ui/planning/route_export.h"

#include "core/io/catalog.h"
#include "core/io/mission_export.h"
#include "core/mission/route_check.h"

#include <QCoreApplication>
#include <QDir>

#include <algorithm>

namespace pf::ui {

mission::Mission withDjiTypes(const mission::Mission& mission) {
    mission::Mission out = mission;
    if (auto cat = io::loadDefaultCatalog(); cat)
        io::addDjiTypesFromCatalog(out, *cat);
    return out;
}

std::vector<io::WaypointFormat> defaultExportFormats(const mission::Mission& mission) {
    const mission::Mission typed = withDjiTypes(mission);
    const bool allDji =
        !typed.aircraft.empty() &&
        std::all_of(typed.aircraft.begin(), typed.aircraft.end(),
                    [](const mission::AircraftConfig& a) { return a.dji.has_value(); });
    if (allDji)
        return {io::WaypointFormat::WpmlKmz, io::WaypointFormat::Kml};
    return {io::WaypointFormat::QgcPlan, io::WaypointFormat::Kml};
}

QStringList exportRoutes(const mission::Mission& mission, const std::vector<route::Route>& routes,
                         const ExportRequest& request, QString* error, QStringList* routeProblems,
                         QStringList* notes, QStringList* warnings) {
    if (routeProblems)
        routeProblems->clear();
    QStringList written;
    std::vector<route::Route> chosen;
    if (request.routes.empty()) {
        chosen = routes;
    } else {
        for (int i : request.routes)
            if (i >= 0 && i < int(routes.size()))
                chosen.push_back(routes[std::size_t(i)]);
    }
    auto fail = [&](const QString& why) {
        if (error)
            *error = why;
        return written;
    };
    if (chosen.empty())
        return fail(QCoreApplication::translate(
            "Export", "Nothing to export: no route is planned or chosen."));
    if (request.formats.empty())
        return fail(QCoreApplication::translate("Export", "Choose at least one format."));
    const mission::Mission withTypes = withDjiTypes(mission);
    io::ExportContext ctx = io::makeExportContext(withTypes, chosen);
    // A file the aircraft cannot fly (a .kmz for an aircraft that is not a DJI Enterprise model,
    // Litchi or MAVLink for one) is listed with the route check's problems and needs the user's
    // confirmation, as the CLI's --force: then the others are written and such a .kmz is left out,
    // with a note.
    QStringList unflyable;
    for (auto fmt : request.formats)
        for (std::size_t i = 0; i < ctx.routes.size(); ++i)
            if (const std::string why = io::aircraftFormatProblem(ctx, i, fmt); !why.empty())
                unflyable << QString::fromStdString(why);
    io::ExportOptions options = request.options;
    options.forceAircraft = request.allowRouteErrors;
    if (!request.allowRouteErrors) {
        const auto problems = mission::routeErrors(mission, chosen);
        if (!problems.empty() || !unflyable.isEmpty()) {
            if (routeProblems) {
                for (const auto& p : problems)
                    routeProblems->append(QString::fromStdString(p));
                routeProblems->append(unflyable);
            }
            return fail(QCoreApplication::translate(
                "Export",
                "Not exported: the route check found %n problem(s) (a waypoint or "
                "leg in a no-fly margin, an altitude out of limits, or a file the "
                "aircraft cannot fly).",
                nullptr, int(problems.size()) + unflyable.size()));
        }
    }
    QDir dir(request.folder);
    if (request.folder.isEmpty() || (!dir.exists() && !dir.mkpath(QStringLiteral("."))))
        return fail(QCoreApplication::translate("Export", "The folder %1 cannot be created.")
                        .arg(request.folder));
    // The same files as `photoflight-cli plan --format` (one vehicle file per sortie).
    io::MissionExportRequest files;
    files.formats = request.formats;
    files.folder = dir.path().toStdString();
    files.stem = request.stem.toStdString();
    files.perAircraft = request.perAircraft;
    files.combined = request.combined;
    files.options = options;
    auto report = io::exportMission(withTypes, chosen, files);
    if (!report)
        return fail(QString::fromStdString(report.error().message));
    if (report->files.empty()) // every file asked for was a .kmz left out (its note says why)
        return fail(QCoreApplication::translate("Export", "Nothing written: %1")
                        .arg(QString::fromStdString(report->notes.empty() ? std::string()
                                                                          : report->notes.front())));
    for (const auto& f : report->files)
        written << QString::fromStdString(f);
    if (notes)
        for (const auto& n : report->notes)
            *notes << QString::fromStdString(n);
    if (warnings)
        for (const auto& w : report->warnings)
            *warnings << QString::fromStdString(w);
    if (error)
        error->clear();
    return written;
}

} // namespace pf::ui
