// GroundStation: the operator's own position from an NMEA source (Qt Positioning), shown on the map.
#pragma once

#include "core/geo/types.h"

#include <QGeoPositionInfo>
#include <QGraphicsItem>
#include <QObject>

#include <optional>

class QGraphicsScene;
class QIODevice;
class QNmeaPositionInfoSource;

namespace pf::ui {

// A blue dot with a translucent accuracy circle, the usual "you are here" marker.
class OperatorItem : public QGraphicsItem {
public:
    OperatorItem();
    void setAccuracyPixels(double px);
    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    double m_accuracyPx = 0;
};

class GroundStation : public QObject {
    Q_OBJECT
public:
    explicit GroundStation(QGraphicsScene* scene, QObject* parent = nullptr);
    ~GroundStation() override;

    // Replays an NMEA log (QNmeaPositionInfoSource in simulation mode, at the log's own pace).
    bool openNmeaFile(const QString& path, QString* error);
    // Reads live NMEA from a character device such as a USB GNSS receiver (/dev/ttyACM0), polled.
    bool openNmeaDevice(const QString& path, QString* error);
    void stop();
    bool isActive() const { return m_source != nullptr; }

    std::optional<geo::LonLat> position() const { return m_position; }
    std::optional<double> accuracyM() const { return m_accuracy; }
    // Keeps the accuracy circle's size right when the map zooms.
    void setMetresPerPixel(double mpp);

signals:
    void positionChanged(const geo::LonLat& p);
    void statusChanged(const QString& text);

private:
    bool start(const QString& path, bool simulation, QString* error);
    void onUpdate(const QGeoPositionInfo& info);

    QGraphicsScene* m_scene;
    QNmeaPositionInfoSource* m_source = nullptr;
    QIODevice* m_device = nullptr;
    OperatorItem* m_item = nullptr;
    std::optional<geo::LonLat> m_position;
    std::optional<double> m_accuracy;
    double m_mpp = 1.0;
};

} // namespace pf::ui
