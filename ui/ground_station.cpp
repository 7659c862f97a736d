#include "ui/ground_station.h"

#include "ui/geo_adapter.h"
#include "ui/map/web_mercator.h"

#include <QFile>
#include <QFileInfo>
#include <QGraphicsScene>
#include <QNmeaPositionInfoSource>
#include <QPainter>

namespace pf::ui {

OperatorItem::OperatorItem() {
    setFlag(ItemIgnoresTransformations);
    setZValue(45);
}

void OperatorItem::setAccuracyPixels(double px) {
    prepareGeometryChange();
    m_accuracyPx = std::min(px, 2000.0);
}

QRectF OperatorItem::boundingRect() const {
    const double r = std::max(12.0, m_accuracyPx) + 2;
    return {-r, -r, 2 * r, 2 * r};
}

void OperatorItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
    p->setRenderHint(QPainter::Antialiasing);
    if (m_accuracyPx > 8) {
        p->setPen(QPen(QColor(30, 110, 240, 140), 1));
        p->setBrush(QColor(30, 110, 240, 40));
        p->drawEllipse(QPointF(0, 0), m_accuracyPx, m_accuracyPx);
    }
    p->setPen(QPen(Qt::white, 3));
    p->setBrush(QColor(30, 110, 240));
    p->drawEllipse(QPointF(0, 0), 7, 7);
}

GroundStation::GroundStation(QGraphicsScene* scene, QObject* parent) : QObject(parent), m_scene(scene) {}

GroundStation::~GroundStation() { stop(); }

bool GroundStation::openNmeaFile(const QString& path, QString* error) { return start(path, true, error); }

bool GroundStation::openNmeaDevice(const QString& path, QString* error) { return start(path, false, error); }

bool GroundStation::start(const QString& path, bool simulation, QString* error) {
    stop();
    auto* file = new QFile(path, this);
    if (!file->open(QIODevice::ReadOnly)) {
        if (error) *error = tr("Cannot read the NMEA source %1: %2").arg(path, file->errorString());
        delete file;
        return false;
    }
    m_file = file;
    m_source = new QNmeaPositionInfoSource(simulation ? QNmeaPositionInfoSource::SimulationMode
                                                      : QNmeaPositionInfoSource::RealTimeMode,
                                           this);
    m_source->setDevice(m_file);
    connect(m_source, &QGeoPositionInfoSource::positionUpdated, this, &GroundStation::onUpdate);
    connect(m_source, QOverload<QGeoPositionInfoSource::Error>::of(&QGeoPositionInfoSource::error), this,
            [this](QGeoPositionInfoSource::Error) { emit statusChanged(tr("Ground station: position source failed")); });
    m_source->startUpdates();
    emit statusChanged(tr("Ground station: reading %1").arg(QFileInfo(path).fileName()));
    return true;
}

void GroundStation::stop() {
    if (m_source) {
        m_source->stopUpdates();
        delete m_source;
        m_source = nullptr;
    }
    delete m_file;
    m_file = nullptr;
}

void GroundStation::setMetresPerPixel(double mpp) {
    m_mpp = mpp;
    if (m_item && m_accuracy && m_position)
        m_item->setAccuracyPixels(*m_accuracy / mercator::groundScale(m_position->lat) / m_mpp);
}

void GroundStation::onUpdate(const QGeoPositionInfo& info) {
    if (!info.coordinate().isValid()) return;
    m_position = fromQGeo(info.coordinate());
    m_accuracy.reset();
    if (info.hasAttribute(QGeoPositionInfo::HorizontalAccuracy))
        m_accuracy = info.attribute(QGeoPositionInfo::HorizontalAccuracy);
    if (!m_item) {
        m_item = new OperatorItem();
        m_item->setToolTip(tr("Ground station (operator)"));
        m_scene->addItem(m_item);
    }
    m_item->setPos(toScene(*m_position));
    setMetresPerPixel(m_mpp);
    emit positionChanged(*m_position);
}

} // namespace pf::ui
