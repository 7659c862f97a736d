// DJI WPML missions: one aircraft's route as a .kmz (wpmz/template.kml and wpmz/waylines.wpml in a
// ZIP archive) that DJI Pilot 2 imports as a waypoint route and FlightHub 2 sends to a DJI Dock;
// and reading such a file back (a route adjusted in DJI Pilot 2) for editing.
#pragma once

#include "core/io/export_context.h"
#include "core/result.h"

#include <cstddef>
#include <string>

namespace pf::io {

// Why the route's aircraft cannot fly a .kmz: no catalog aircraft flies it, the aircraft is not a
// DJI Enterprise model with a WPML drone type, its camera is not a DJI payload with a payload type,
// or the type is not one DJI documents. Empty when it can.
std::string wpmlAircraftProblem(const ExportContext& ctx, std::size_t routeIndex);

// The two documents of the route's .kmz, as writeWpmlKmz stores them.
struct WpmlDocuments {
    std::string templateKml;
    std::string waylinesWpml;
    std::size_t waypoints =
        0;                  // the wayline's waypoints (a distance-triggered lane counts its ends)
    std::size_t photos = 0; // the photos the aircraft takes
};
// Heights: above the take-off point; over a terrain model (options.altitudeFrame Auto) or with
// AboveSeaLevel, EGM96 heights in template.kml and WGS84 ellipsoidal heights in waylines.wpml
// (PROJ's EGM96 grid). Photos: lanes of equally spaced photos by distance, other photos by a photo
// action at their waypoint. Errors: wpmlAircraftProblem, AboveTerrain (not a WPML waypoint frame),
// AboveSeaLevel without the home's elevation, an empty route.
Result<WpmlDocuments> wpmlDocuments(const ExportContext& ctx, std::size_t routeIndex,
                                    const ExportOptions& options);
Status writeWpmlKmz(const ExportContext& ctx, std::size_t routeIndex, const std::string& path,
                    const ExportOptions& options);

// Reads every wayline of wpmz/waylines.wpml as a route (named after the aircraft the file
// declares): positions, heights above the take-off point (ellipsoidal heights converted through the
// take-off reference point), speeds, headings, the photo actions (a photo waypoint per reachPoint
// photo, the photos of a distance trigger placed along its waypoints). Errors name the file and the
// problem: not a ZIP archive, no wpmz/waylines.wpml, not XML, not the WPML namespace, a waypoint
// without coordinates or height, a height mode it cannot turn into heights above take-off.
Result<ImportedWaypoints> readWpmlKmz(const std::string& path);

} // namespace pf::io
