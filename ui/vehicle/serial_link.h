// SerialLink: MAVLink over a serial port (telemetry radio, USB to the flight controller).
#pragma once

#include "ui/vehicle/vehicle_link.h"

class QSerialPort;

namespace pf::ui {

class SerialLink : public VehicleLink {
    Q_OBJECT
public:
    explicit SerialLink(mavlink::ConnectionSpec spec, QObject* parent = nullptr);
    bool open(QString* error) override;
    void write(const QByteArray& bytes) override;

private:
    QSerialPort* m_port;
};

} // namespace pf::ui
