#include "ui/mosaic/mosaic_layer.h"

#include "ui/map/gdal_tile_source.h"
#include "ui/map/tile_layer.h"
#include "ui/map/web_mercator.h"

#include <QBrush>
#include <QFileInfo>
#include <QGraphicsPathItem>
#include <QGraphicsScene>
#include <QPainterPath>
#include <QPen>

namespace pf::ui {

namespace {

void addRing(QPainterPath& path, const geo::GeoRing& ring) {
    if (ring.size() < 3)
        return;
    path.moveTo(mercator::toScene(ring.front().lon, ring.front().lat));
    for (std::size_t i = 1; i < ring.size(); ++i)
        path.lineTo(mercator::toScene(ring[i].lon, ring[i].lat));
    path.closeSubpath();
}

QPainterPath polygonsPath(const std::vector<geo::GeoPolygon>& polys) {
    QPainterPath path;
    path.setFillRule(Qt::OddEvenFill);
    for (const auto& p : polys) {
        addRing(path, p.outer);
        for (const auto& h : p.holes)
            addRing(path, h);
    }
    return path;
}

} // namespace

MosaicLayer::MosaicLayer(QGraphicsScene* scene, QObject* parent)
    : QObject(parent), m_scene(scene) {}

MosaicLayer::~MosaicLayer() {
    clear();
}

void MosaicLayer::clear() {
    for (auto* g : m_gaps) {
        m_scene->removeItem(g);
        delete g;
    }
    m_gaps.clear();
    if (m_seams) {
        m_scene->removeItem(m_seams);
        delete m_seams;
        m_seams = nullptr;
    }
    if (m_tiles) {
        m_scene->removeItem(m_tiles);
        delete m_tiles;
        m_tiles = nullptr;
    }
    m_bounds = QRectF();
    m_shown = false;
}

bool MosaicLayer::show(const mosaic::MosaicReport& report, QString* error) {
    const QString path = QString::fromStdString(report.outputPath);
    auto source =
        GdalTileSource::open(path, tr("Mosaic %1").arg(QFileInfo(path).fileName()), error);
    if (!source)
        return false;
    clear();
    m_report = report;
    m_bounds = source->coverage();
    m_tiles = new TileLayer();
    m_tiles->setZValue(kZMosaic);
    m_tiles->setOpacity(m_opacity);
    m_tiles->setSource(std::shared_ptr<TileSource>(std::move(source)));
    m_scene->addItem(m_tiles);

    // Gaps: hatched orange over everything but the routes, with their area.
    for (const auto& gap : report.gaps) {
        auto* item = new QGraphicsPathItem(polygonsPath(gap.shape));
        QPen pen(QColor(230, 90, 0), 2.0);
        pen.setCosmetic(true);
        item->setPen(pen);
        item->setBrush(QBrush(QColor(255, 120, 0, 190), Qt::FDiagPattern));
        item->setZValue(kZGaps);
        item->setToolTip(
            tr("No photo covers this part of the area: %1 m²").arg(gap.areaM2, 0, 'f', 1));
        item->setVisible(m_gapsVisible);
        m_scene->addItem(item);
        m_gaps.push_back(item);
    }
    // Seams: the outline of the part each photo gives, in one item.
    QPainterPath seams;
    for (const auto& p : report.photos)
        seams.addPath(polygonsPath(p.seam));
    m_seams = new QGraphicsPathItem(seams);
    QPen seamPen(QColor(255, 255, 255, 200), 1.0);
    seamPen.setCosmetic(true);
    m_seams->setPen(seamPen);
    m_seams->setZValue(kZSeams);
    m_seams->setVisible(m_seamsVisible);
    m_scene->addItem(m_seams);
    m_shown = true;
    return true;
}

void MosaicLayer::setOpacity(double opacity) {
    m_opacity = std::clamp(opacity, 0.0, 1.0);
    if (m_tiles)
        m_tiles->setOpacity(m_opacity);
}

void MosaicLayer::setGapsVisible(bool on) {
    m_gapsVisible = on;
    for (auto* g : m_gaps)
        g->setVisible(on);
}

void MosaicLayer::setSeamsVisible(bool on) {
    m_seamsVisible = on;
    if (m_seams)
        m_seams->setVisible(on);
}

} // namespace pf::ui
