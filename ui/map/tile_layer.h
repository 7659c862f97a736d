// TileLayer: the base-map layer of the scene; draws cached tiles and requests missing ones off the GUI thread.
#pragma once

#include "ui/map/tile_source.h"

#include <QCache>
#include <QGraphicsObject>
#include <QMutex>
#include <QSet>
#include <QThreadPool>

#include <memory>

namespace pf::ui {

class TileLayer : public QGraphicsObject {
    Q_OBJECT
public:
    explicit TileLayer(QGraphicsItem* parent = nullptr);
    ~TileLayer() override;

    // Replaces the source; the cache is emptied and visible tiles are requested again.
    void setSource(std::shared_ptr<TileSource> source);
    std::shared_ptr<TileSource> source() const { return m_source; }

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

    // Tiles requested and not yet back.
    int pendingCount() const { return m_pending.size(); }
    int cachedCount() const { return m_cache.size(); }
    // Tiles drawn by the last paint from a scaled-up ancestor because their own was not ready.
    int lastFallbackCount() const { return m_lastFallbacks; }
    // Tiles the last paint could not draw from their own level (fallback or blank).
    int lastMissingCount() const { return m_lastMissing; }
    // The tile image if cached (null otherwise); for tests.
    QImage cachedTile(const TileKey& key) const;

signals:
    // Every requested tile has arrived (useful to wait for a complete picture, e.g. screenshots).
    void idle();
    void tileArrived(const TileKey& key);

private:
    struct Wanted {
        QMutex mutex;
        QSet<TileKey> keys;
    };
    void request(const TileKey& key);
    void onTileReady(int generation, const TileKey& key, const QImage& image, bool skipped);
    // Draws the nearest cached ancestor of `key` scaled into the tile's rectangle.
    bool drawFromAncestor(QPainter* painter, const TileKey& key);

    std::shared_ptr<TileSource> m_source;
    QCache<TileKey, QImage> m_cache;
    QSet<TileKey> m_pending;
    std::shared_ptr<Wanted> m_wanted = std::make_shared<Wanted>();
    QThreadPool m_pool;
    int m_generation = 0;
    int m_lastFallbacks = 0;
    int m_lastMissing = 0;
};

} // namespace pf::ui
