#include "ui/planning/route_export.h"

#include "core/io/mission_export.h"
#include "core/mission/route_check.h"

#include <QCoreApplication>
#include <QDir>

namespace pf::ui {

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
    if (!request.allowRouteErrors) {
        const auto problems = mission::routeErrors(mission, chosen);
        if (!problems.empty()) {
            if (routeProblems)
                for (const auto& p : problems)
                    routeProblems->append(QString::fromStdString(p));
            return fail(QCoreApplication::translate(
                            "Export", "Not exported: the route check found %n problem(s) (a waypoint or "
                                      "leg in a no-fly margin, or an altitude out of limits).",
                            nullptr, int(problems.size())));
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
    files.options = request.options;
    auto report = io::exportMission(mission, chosen, files);
    if (!report)
        return fail(QString::fromStdString(report.error().message));
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
