// GdalTileSource: tiles rendered by GDAL from any raster it reads (GeoTIFF, MBTiles, VRT, WMS/TMS XML).
#pragma once

#include "ui/map/tile_source.h"

#include <QMap>
#include <QMutex>

#include <memory>
#include <vector>

namespace pf::ui {

class GdalTileSource : public TileSource {
public:
    // Opens `datasetName` (a path or a GDAL connection string such as <GDAL_WMS> XML) and checks that
    // it has a coordinate reference system; any CRS is warped to Web Mercator on the fly.
    static std::unique_ptr<GdalTileSource> open(const QString& datasetName, const QString& displayName,
                                                QString* error);
    // An online XYZ service (e.g. "https://tile.openstreetmap.org/${z}/${x}/${y}.png") through GDAL's
    // WMS driver in TMS mode, with a disk cache in `cacheDir` and a short network timeout.
    static std::unique_ptr<GdalTileSource> openXyz(const QString& displayName, const QString& urlTemplate,
                                                   const QString& cacheDir, const QString& attribution,
                                                   int maxZoom = 19, int timeoutSeconds = 5);
    // The <GDAL_WMS> description used by openXyz (exposed for tests; no network is touched).
    static QString xyzServiceXml(const QString& urlTemplate, const QString& cacheDir, int maxZoom, int timeoutSeconds);

    ~GdalTileSource() override;

    QString name() const override { return m_displayName; }
    QString attribution() const override { return m_attribution; }
    int maxZoom() const override { return m_maxZoom; }
    QRectF coverage() const override { return m_coverage; }
    QImage renderTile(const TileKey& key) override;
    bool isOnline() const override { return m_online; }

    // Metadata item of the dataset (e.g. "PF_SYNTHETIC"), empty if absent.
    QString metadataItem(const QString& key) const;

private:
    GdalTileSource() = default;
    // Every worker thread uses its own dataset handle: GDAL datasets are not thread-safe. Handles are
    // pooled so a thread borrows one for the duration of a tile and gives it back.
    void* acquire();
    void release(void* ds);

    QByteArray m_datasetName; // what each pooled handle opens
    QString m_displayName;
    QString m_attribution;
    QRectF m_coverage;
    int m_maxZoom = 18;
    int m_colourBands = 3; // 1 (grey) or 3 (RGB); an alpha band is added when warping
    bool m_online = false;
    QByteArray m_resampling = "bilinear";
    QByteArray m_timeout = "5"; // GDAL_HTTP_TIMEOUT for online sources, seconds
    QString m_vsimemPath; // a normalising VRT kept in GDAL's in-memory file system, removed on destruction
    QMutex m_mutex;
    std::vector<void*> m_free;
    std::vector<void*> m_all;
    QMap<QString, QString> m_metadata;
};

} // namespace pf::ui
