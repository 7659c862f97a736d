// UdpLink: MAVLink over UDP. As a client it sends to HOST:PORT from an ephemeral port (the vehicle
// answers to where the datagrams came from); as a server it listens on PORT and answers the last
// sender (how autopilots and SITL stream to a ground station on 14550).
#pragma once

#include "ui/vehicle/vehicle_link.h"

#include <QHostAddress>

class QUdpSocket;

namespace pf::ui {

class UdpLink : public VehicleLink {
    Q_OBJECT
public:
    explicit UdpLink(mavlink::ConnectionSpec spec, QObject* parent = nullptr);
    bool open(QString* error) override;
    void write(const QByteArray& bytes) override;

private:
    void readPending();
    QUdpSocket* m_socket;
    QHostAddress m_peer;
    quint16 m_peerPort = 0;
};

} // namespace pf::ui
