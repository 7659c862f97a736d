#include "ui/planning/route_export.h"

#include "core/io/catalog.h"
#include "core/mission/route_check.h"

#include <QCoreApplication>
#include <QDir>

#include <algorithm>

namespace pf::ui {

QStringList exportRoutes(const mission::Mission& mission, const std::vector<route::Route>& routes,
                         const ExportRequest& request, QString* error, QStringList* routeProblems,
                         QStringList* notes) {
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
    // A mission file written before the catalog knew DJI drone and payload types: the .kmz needs
    // them.
    mission::Mission withTypes = mission;
    if (auto cat = io::loadDefaultCatalog(); cat)
        io::addDjiTypesFromCatalog(withTypes, *cat);
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
    // The KML export draws the smoothed path; without it the KML still holds the waypoints.
    if (std::find(request.formats.begin(), request.formats.end(), io::WaypointFormat::Kml) !=
        request.formats.end())
        (void)io::addTrajectories(ctx);
    for (auto fmt : request.formats) {
        const auto& info = io::formatInfo(fmt);
        if (request.perAircraft || !info.combined) {
            for (std::size_t i = 0; i < ctx.routes.size(); ++i) {
                const QString path =
                    dir.filePath(request.stem + QLatin1Char('-') +
                                 QString::fromStdString(io::routeFileName(ctx, i, fmt)));
                auto st = io::exportRouteFiles(ctx, i, fmt, path.toStdString(), options);
                if (!st)
                    return fail(QString::fromStdString(st.error().message));
                for (const auto& f : st->files)
                    written << QString::fromStdString(f);
                if (notes)
                    for (const auto& n : st->notes)
                        *notes << QString::fromStdString(n);
            }
        }
        if (request.combined && info.combined) {
            const QString path = dir.filePath(request.stem + QString::fromLatin1(info.extension));
            auto st = io::exportCombined(ctx, fmt, path.toStdString(), options);
            if (!st)
                return fail(QString::fromStdString(st.error().message));
            written << path;
        }
    }
    if (error)
        error->clear();
    return written;
}

} // namespace pf::ui
