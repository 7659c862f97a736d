// The base maps the application offers: the bundled synthetic demo map, OpenStreetMap, a user's raster file.
#pragma once

#include "ui/map/tile_source.h"

#include <memory>

namespace pf::ui {

// Where the demo map is: $PHOTOFLIGHT_DEMO_MAP, the build tree, the data directory or the installed
// share/photoflight/maps. Empty if none exists.
QString demoMapPath();
std::shared_ptr<TileSource> openDemoMap(QString* error);
// Tiles from tile.openstreetmap.org through GDAL's WMS driver, cached under the user's cache directory.
// Only ever used when the user picks it.
std::shared_ptr<TileSource> openOpenStreetMap(QString* error);
std::shared_ptr<TileSource> openMapFile(const QString& path, QString* error);
// File name suffixes opened as base maps when dropped on the map.
bool looksLikeRasterMap(const QString& path);

} // namespace pf::ui
