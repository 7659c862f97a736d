#include "ui/map/base_maps.h"

#include "core/data_dir.h"
#include "ui/map/gdal_tile_source.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace pf::ui {

QString demoMapPath() {
    QStringList candidates;
    const QString env = qEnvironmentVariable("PHOTOFLIGHT_DEMO_MAP");
    if (!env.isEmpty()) candidates << env;
#ifdef PF_BUILD_DEMO_MAP
    candidates << QStringLiteral(PF_BUILD_DEMO_MAP);
#endif
    const QString data = QString::fromStdString(pf::dataDirectory());
    if (!data.isEmpty()) candidates << data + QStringLiteral("/maps/demo_map.tif");
    candidates << QCoreApplication::applicationDirPath() + QStringLiteral("/../share/photoflight/maps/demo_map.tif");
    for (const QString& c : candidates)
        if (QFileInfo::exists(c)) return QFileInfo(c).absoluteFilePath();
    return {};
}

std::shared_ptr<TileSource> openDemoMap(QString* error) {
    const QString path = demoMapPath();
    if (path.isEmpty()) {
        if (error) *error = QCoreApplication::translate("BaseMaps", "The bundled demo map was not found.");
        return nullptr;
    }
    return GdalTileSource::open(path, QCoreApplication::translate("BaseMaps", "Demo map (synthetic, offline)"), error);
}

std::shared_ptr<TileSource> openOpenStreetMap(QString* error) {
    const QString cache = QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/tiles/osm");
    auto src = GdalTileSource::openXyz(QCoreApplication::translate("BaseMaps", "OpenStreetMap (online)"),
                                       QStringLiteral("https://tile.openstreetmap.org/${z}/${x}/${y}.png"), cache,
                                       QStringLiteral("© OpenStreetMap contributors"), 19, 5);
    if (!src && error) *error = QCoreApplication::translate("BaseMaps", "GDAL cannot open the OpenStreetMap tile service.");
    return src;
}

std::shared_ptr<TileSource> openMapFile(const QString& path, QString* error) {
    return GdalTileSource::open(path, QFileInfo(path).fileName(), error);
}

bool looksLikeRasterMap(const QString& path) {
    static const QStringList suffixes{QStringLiteral("tif"), QStringLiteral("tiff"), QStringLiteral("mbtiles"),
                                      QStringLiteral("vrt"), QStringLiteral("jp2"), QStringLiteral("ecw"),
                                      QStringLiteral("img"), QStringLiteral("sid")};
    return suffixes.contains(QFileInfo(path).suffix().toLower());
}

} // namespace pf::ui
