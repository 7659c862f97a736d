#include "ui/ground_station.h"

#include "ui/geo_adapter.h"
#include "ui/map/web_mercator.h"

#include <QFile>
#include <QFileInfo>
#include <QGraphicsScene>
#include <QNmeaPositionInfoSource>
#include <QPainter>
#include <QTimer>

#include <cstring>

namespace pf::ui {

namespace {

// A character device (e.g. /dev/ttyACM0 of a USB GNSS receiver) read by polling. QFile never emits
// readyRead(), which QNmeaPositionInfoSource needs in real-time mode; this wrapper reads what has
// arrived every 100 ms and announces it. (QtSerialPort would do the same but is not a dependency.)
class PolledDevice : public QIODevice {
public:
    PolledDevice(const QString& path, QObject* parent) : QIODevice(parent), m_file(path) {
        connect(&m_timer, &QTimer::timeout, this, [this] {
            const QByteArray chunk = m_file.read(4096);
            if (chunk.isEmpty()) return;
            m_buffer.append(chunk);
            emit readyRead();
        });
    }
    bool openDevice(QString* error) {
        if (!m_file.open(QIODevice::ReadOnly | QIODevice::Unbuffered)) {
            if (error) *error = m_file.errorString();
            return false;
        }
        m_timer.start(100);
        return QIODevice::open(QIODevice::ReadOnly);
    }
    bool isSequential() const override { return true; }
    qint64 bytesAvailable() const override { return m_buffer.size() + QIODevice::bytesAvailable(); }
    bool canReadLine() const override { return m_buffer.contains('\n') || QIODevice::canReadLine(); }

protected:
    qint64 readData(char* data, qint64 max) override {
        const qint64 n = std::min<qint64>(max, m_buffer.size());
        std::memcpy(data, m_buffer.constData(), std::size_t(n));
        m_buffer.remove(0, int(n));
        return n;
    }
    qint64 writeData(const char*, qint64) override { return -1; }

private:
    QFile m_file;
    QTimer m_timer;
    QByteArray m_buffer;
};

} // namespace

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
    QString why;
    if (simulation) {
        auto* file = new QFile(path, this);
        if (!file->open(QIODevice::ReadOnly)) why = file->errorString();
        m_device = file;
    } else {
        auto* dev = new PolledDevice(path, this);
        if (!dev->openDevice(&why) && why.isEmpty()) why = tr("cannot open it");
        m_device = dev;
    }
    if (!why.isEmpty()) {
        if (error) *error = tr("Cannot read the NMEA source %1: %2").arg(path, why);
        delete m_device;
        m_device = nullptr;
        return false;
    }
    m_source = new QNmeaPositionInfoSource(simulation ? QNmeaPositionInfoSource::SimulationMode
                                                      : QNmeaPositionInfoSource::RealTimeMode,
                                           this);
    m_source->setDevice(m_device);
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
    delete m_device;
    m_device = nullptr;
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
