// TileSource: one base map (a raster file, the demo map or an online XYZ service) cut into XYZ tiles.
#pragma once

#include <QHash>
#include <QImage>
#include <QRectF>
#include <QString>

namespace pf::ui {

// A tile of the Web Mercator XYZ pyramid (row 0 at the north).
struct TileKey {
    int z = 0;
    int x = 0;
    int y = 0;
    friend bool operator==(const TileKey& a, const TileKey& b) { return a.z == b.z && a.x == b.x && a.y == b.y; }
    TileKey parent() const { return {z - 1, x >> 1, y >> 1}; }
};
inline uint qHash(const TileKey& k, uint seed = 0) { return ::qHash((quint64(k.z) << 48) ^ (quint64(k.x) << 24) ^ quint64(k.y), seed); }

class TileSource {
public:
    virtual ~TileSource() = default;
    virtual QString name() const = 0;
    // Text the map must show for this source (copyright), or empty.
    virtual QString attribution() const { return {}; }
    // Deepest zoom level with its own detail; deeper views magnify these tiles.
    virtual int maxZoom() const = 0;
    // Scene rectangle (Web Mercator metres, y down) where the source has data.
    virtual QRectF coverage() const = 0;
    // Renders one 256x256 tile. Called from worker threads, several at once: implementations must be
    // thread-safe. Returns a null image when the tile cannot be made (no data, offline, ...).
    virtual QImage renderTile(const TileKey& key) = 0;
    // True when tiles come over the network (the UI says so and never blocks on them).
    virtual bool isOnline() const { return false; }
};

} // namespace pf::ui
