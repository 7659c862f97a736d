// Writing the document's routes through the core's waypoint exporters (what the export dialog
// runs).
#pragma once

#include "core/io/waypoint_formats.h"
#include "core/mission/mission.h"
#include "core/route/waypoint.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace pf::ui {

struct ExportRequest {
    QString folder;
    QString stem = QStringLiteral("mission");
    std::vector<io::WaypointFormat> formats;
    std::vector<int> routes; // indices into the routes given; empty: all
    // Display formats (KML, GPX, GeoJSON): one file per aircraft "<stem>-<aircraft>.<ext>", and one
    // "<stem>.<ext>" with every route. Vehicle formats are always one file per aircraft and sortie.
    bool perAircraft = true;
    bool combined = true;
    io::ExportOptions options;
    // Routes the route check finds errors in (mission::checkRoute) are written only when the user
    // has confirmed them.
    bool allowRouteErrors = false;
};

// The mission with the DJI drone and payload types of its catalog aircraft and cameras filled in (a
// mission file written before the catalog knew them): what the .kmz export and the check of each
// aircraft against the formats need.
mission::Mission withDjiTypes(const mission::Mission& mission);

// The formats the export offers ticked: the DJI Pilot 2 / FlightHub 2 .kmz and KML when every
// aircraft of the mission is a DJI Enterprise model (they fly no MAVLink mission), else the
// QGroundControl .plan and KML.
std::vector<io::WaypointFormat> defaultExportFormats(const mission::Mission& mission);

// Writes the files; returns the paths written. On the first failure stops, and `error` names the
// file and the problem. Chosen routes with errors are refused (nothing written) unless
// request.allowRouteErrors: `error` then says so and `routeProblems` lists every problem. `notes`
// receives what the user should know (one file per sortie, merged waypoints, a Litchi route split
// into several missions), `warnings` each flight holding more mission items than its autopilot
// stores. The files are io::exportMission's: exactly what `photoflight-cli plan --format` writes.
QStringList exportRoutes(const mission::Mission& mission, const std::vector<route::Route>& routes,
                         const ExportRequest& request, QString* error,
                         QStringList* routeProblems = nullptr, QStringList* notes = nullptr,
                         QStringList* warnings = nullptr);

} // namespace pf::ui
