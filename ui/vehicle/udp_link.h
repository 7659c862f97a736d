// UdpLink: MAVLink over UDP. As a client it sends to HOST:PORT from an ephemeral port (the vehicle
// answers to where the datagrams came from); as a server it listens on PORT and sends to every
// address it has heard from (autopilots and SITL stream to a ground station on 14550, several
// vehicles may share that port; each only listens to messages for its own system id).
#pragma once

#include "ui/vehicle/vehicle_link.h"

#include <QHostAddress>

#include <vector>

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
    struct Peer {
        QHostAddress address;
        quint16 port = 0;
    };
    std::vector<Peer> m_peers;
};

} // namespace pf::ui
