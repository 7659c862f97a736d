// MosaicLayer: a mosaic on the map, over the base map and under the mission, with its opacity, the
// gaps it leaves in the planned area (hatched) and, on demand, its seams.
#pragma once

#include "core/mosaic/mosaic_types.h"

#include <QObject>
#include <QRectF>
#include <QString>

#include <vector>

class QGraphicsPathItem;
class QGraphicsScene;

namespace pf::ui {

class TileLayer;

class MosaicLayer : public QObject {
    Q_OBJECT
public:
    explicit MosaicLayer(QGraphicsScene* scene, QObject* parent = nullptr);
    ~MosaicLayer() override;

    // Shows the report's GeoTIFF with its gaps and seams, replacing any mosaic shown before.
    bool show(const mosaic::MosaicReport& report, QString* error = nullptr);
    void clear();
    bool isShown() const { return m_shown; }

    void setOpacity(double opacity); // 0..1
    double opacity() const { return m_opacity; }
    void setGapsVisible(bool on);
    void setSeamsVisible(bool on);
    bool gapsVisible() const { return m_gapsVisible; }
    bool seamsVisible() const { return m_seamsVisible; }

    // Scene rectangle of the mosaic (empty when none is shown).
    QRectF bounds() const { return m_bounds; }
    TileLayer* tiles() const { return m_tiles; }
    int gapItemCount() const { return static_cast<int>(m_gaps.size()); }
    const mosaic::MosaicReport& report() const { return m_report; }

    // Between the base map (-100) and the mission's area (10).
    static constexpr double kZMosaic = -50.0;
    static constexpr double kZSeams = -45.0;
    static constexpr double kZGaps = 35.0; // over the area and the plan's partition: gaps must show

private:
    QGraphicsScene* m_scene;
    TileLayer* m_tiles = nullptr;
    std::vector<QGraphicsPathItem*> m_gaps;
    QGraphicsPathItem* m_seams = nullptr;
    mosaic::MosaicReport m_report;
    QRectF m_bounds;
    double m_opacity = 1.0;
    bool m_gapsVisible = true;
    bool m_seamsVisible = false;
    bool m_shown = false;
};

} // namespace pf::ui
