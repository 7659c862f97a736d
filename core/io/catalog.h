// The catalog of cameras and aircraft (resources/catalog.json plus the user's own additions).
#pragma once

#include "core/fleet/aircraft.h"
#include "core/mission/mission.h"
#include "core/result.h"
#include "core/sensor/camera.h"

#include <string>
#include <vector>

namespace pf::io {

struct Catalog {
    std::vector<sensor::Camera> cameras;
    std::vector<fleet::AircraftSpec> aircraft;
    const sensor::Camera* findCamera(const std::string& name) const;   // case-insensitive
    const fleet::AircraftSpec* findAircraft(const std::string& name) const;
};

Result<Catalog> loadCatalog(const std::string& path);
// The catalog in the catalog file format (resources/catalog.json); loadCatalog reads it back to an
// equal catalog, so a user can save the bundled list, edit it and use it as their own catalog.
std::string catalogToJson(const Catalog& catalog);
// Entries of `extra` are added to `base`; an entry with the same name replaces the base one.
Catalog mergeCatalogs(Catalog base, const Catalog& extra);
// The bundled catalog found in $PHOTOFLIGHT_DATA_DIR, the installed data directory or the source
// tree's resources/, merged with the user's catalog (~/.local/share/photoflight/catalog.json) if any.
Result<Catalog> loadDefaultCatalog();

// The DJI types a mission file written before the catalog had them lacks: the drone type of each
// aircraft whose model is a catalog aircraft with one, the payload type of each camera named like a
// catalog camera with one (what the DJI .kmz export needs). Values already set are kept. Returns
// the number of aircraft changed.
int addDjiTypesFromCatalog(mission::Mission& mission, const Catalog& catalog);

} // namespace pf::io
