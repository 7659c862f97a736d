// TcpLink: MAVLink over a TCP connection (SITL's 5760, telemetry bridges); bytes written before the
// connection is up are sent once it is.
#pragma once

#include "ui/vehicle/vehicle_link.h"

class QTcpSocket;

namespace pf::ui {

class TcpLink : public VehicleLink {
    Q_OBJECT
public:
    explicit TcpLink(mavlink::ConnectionSpec spec, QObject* parent = nullptr);
    bool open(QString* error) override;
    void write(const QByteArray& bytes) override;

private:
    QTcpSocket* m_socket;
    QByteArray m_pending;
    bool m_connected = false;
};

} // namespace pf::ui
