#include "ui/map/tile_layer.h"

#include "ui/map/web_mercator.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>
#include <QtConcurrent>

#include <cmath>

namespace pf::ui {

namespace {
constexpr int kCacheKiB = 96 * 1024; // ~380 tiles of 256 KiB
}

TileLayer::TileLayer(QGraphicsItem* parent) : QGraphicsObject(parent) {
    setFlag(ItemUsesExtendedStyleOption);
    m_cache.setMaxCost(kCacheKiB);
    // Two workers: the machine is shared and GDAL warping is CPU-bound; network latency of online
    // sources is bounded by their short timeout.
    m_pool.setMaxThreadCount(2);
    setZValue(-100);
}

TileLayer::~TileLayer() {
    // Workers post results to this object: none may still run once it is gone.
    m_pool.clear();
    m_pool.waitForDone();
}

void TileLayer::setSource(std::shared_ptr<TileSource> source) {
    m_pool.clear();
    ++m_generation;
    m_pending.clear();
    m_cache.clear();
    m_lastMissing = 0;
    m_lastFallbacks = 0;
    prepareGeometryChange();
    m_source = std::move(source);
    update();
}

QRectF TileLayer::boundingRect() const {
    if (!m_source) return {};
    return m_source->coverage();
}

QImage TileLayer::cachedTile(const TileKey& key) const {
    const QImage* img = m_cache.object(key);
    return img ? *img : QImage();
}

void TileLayer::request(const TileKey& key) {
    if (m_pending.contains(key)) return;
    m_pending.insert(key);
    const int generation = m_generation;
    std::shared_ptr<TileSource> source = m_source;
    std::shared_ptr<Wanted> wanted = m_wanted;
    QtConcurrent::run(&m_pool, [this, source, wanted, key, generation] {
        bool stillWanted = true;
        {
            QMutexLocker lock(&wanted->mutex);
            stillWanted = wanted->keys.contains(key);
        }
        // The view moved on before this tile's turn came: skip it rather than waste a worker.
        const QImage img = stillWanted ? source->renderTile(key) : QImage();
        QMetaObject::invokeMethod(
            this, [this, generation, key, img, stillWanted] { onTileReady(generation, key, img, !stillWanted); },
            Qt::QueuedConnection);
    });
}

void TileLayer::onTileReady(int generation, const TileKey& key, const QImage& image, bool skipped) {
    if (generation != m_generation) return;
    m_pending.remove(key);
    if (!skipped) {
        // Failed tiles are cached as null images too, so a missing tile is not asked for again and
        // again while offline; choosing the source again retries them.
        m_cache.insert(key, new QImage(image), image.isNull() ? 1 : int(image.sizeInBytes() / 1024));
        update(mercator::tileRect(key.z, key.x, key.y));
        emit tileArrived(key);
    } else {
        // Skipped because a partial repaint did not list it: if it is still on screen, this repaint
        // asks for it again.
        update(mercator::tileRect(key.z, key.x, key.y));
    }
    if (m_pending.isEmpty()) emit idle();
}

bool TileLayer::drawFromAncestor(QPainter* painter, const TileKey& key) {
    TileKey k = key;
    for (int up = 1; up <= 8 && k.z > 0; ++up) {
        k = k.parent();
        const QImage* img = m_cache.object(k);
        if (!img || img->isNull()) continue;
        const int div = 1 << up;
        const double part = double(mercator::kTileSize) / div;
        const QRectF src((key.x - (k.x << up)) * part, (key.y - (k.y << up)) * part, part, part);
        painter->drawImage(mercator::tileRect(key.z, key.x, key.y), *img, src);
        return true;
    }
    return false;
}

void TileLayer::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*) {
    if (!m_source) return;
    const double pixelsPerMetre = QStyleOptionGraphicsItem::levelOfDetailFromTransform(painter->worldTransform());
    if (pixelsPerMetre <= 0) return;
    const int z = std::min(mercator::zoomForResolution(1.0 / pixelsPerMetre), m_source->maxZoom());
    const QRectF visible = option->exposedRect.intersected(m_source->coverage());
    if (visible.isEmpty()) {
        m_lastMissing = 0;
        return;
    }
    const double span = mercator::tileSpan(z);
    const int n = 1 << z;
    const int x0 = std::max(0, int(std::floor((visible.left() + mercator::kHalfWorld) / span)));
    const int x1 = std::min(n - 1, int(std::floor((visible.right() + mercator::kHalfWorld) / span)));
    const int y0 = std::max(0, int(std::floor((visible.top() + mercator::kHalfWorld) / span)));
    const int y1 = std::min(n - 1, int(std::floor((visible.bottom() + mercator::kHalfWorld) / span)));

    QSet<TileKey> wanted;
    QVector<TileKey> missing;
    painter->setRenderHint(QPainter::SmoothPixmapTransform);
    m_lastFallbacks = 0;
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const TileKey key{z, x, y};
            wanted.insert(key);
            if (const QImage* img = m_cache.object(key)) {
                if (!img->isNull()) painter->drawImage(mercator::tileRect(z, x, y), *img);
                continue;
            }
            missing.push_back(key);
            if (drawFromAncestor(painter, key)) ++m_lastFallbacks;
        }
    }
    {
        QMutexLocker lock(&m_wanted->mutex);
        m_wanted->keys = wanted;
    }
    // Nearest the centre first, so the middle of the view fills in before the edges.
    const QPointF c = visible.center();
    std::sort(missing.begin(), missing.end(), [&](const TileKey& a, const TileKey& b) {
        const QPointF da = mercator::tileRect(a.z, a.x, a.y).center() - c;
        const QPointF db = mercator::tileRect(b.z, b.x, b.y).center() - c;
        return QPointF::dotProduct(da, da) < QPointF::dotProduct(db, db);
    });
    m_lastMissing = missing.size();
    for (const auto& key : missing) request(key);
}

} // namespace pf::ui
