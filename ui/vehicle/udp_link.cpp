#include "ui/vehicle/udp_link.h"

#include <QHostInfo>
#include <QNetworkDatagram>
#include <QUdpSocket>

#include <algorithm>

namespace pf::ui {

UdpLink::UdpLink(mavlink::ConnectionSpec spec, QObject* parent)
    : VehicleLink(std::move(spec), parent), m_socket(new QUdpSocket(this)) {
    connect(m_socket, &QUdpSocket::readyRead, this, &UdpLink::readPending);
}

bool UdpLink::open(QString* error) {
    const auto& s = spec();
    const bool server = s.kind == mavlink::ConnectionSpec::Kind::UdpServer;
    QHostAddress host(QString::fromStdString(s.host));
    if (host.isNull()) {
        const QHostInfo info = QHostInfo::fromName(QString::fromStdString(s.host));
        for (const auto& a : info.addresses())
            if (a.protocol() == QAbstractSocket::IPv4Protocol) {
                host = a;
                break;
            }
        if (host.isNull()) {
            if (error)
                *error = tr("%1: the host name %2 is not known").arg(describe(), QString::fromStdString(s.host));
            return false;
        }
    }
    const bool ok = server ? m_socket->bind(host, quint16(s.port))
                           : m_socket->bind(QHostAddress(QHostAddress::AnyIPv4), 0);
    if (!ok) {
        if (error)
            *error = tr("%1: %2").arg(describe(), m_socket->errorString());
        return false;
    }
    if (!server)
        m_peers.push_back({host, quint16(s.port)});
    return true;
}

void UdpLink::write(const QByteArray& bytes) {
    // A server has no one to send to until a vehicle has spoken.
    for (const auto& p : m_peers)
        m_socket->writeDatagram(bytes, p.address, p.port);
}

void UdpLink::readPending() {
    const bool server = spec().kind == mavlink::ConnectionSpec::Kind::UdpServer;
    while (m_socket->hasPendingDatagrams()) {
        const QNetworkDatagram d = m_socket->receiveDatagram();
        if (server) {
            const auto known = std::find_if(m_peers.begin(), m_peers.end(), [&](const Peer& p) {
                return p.address == d.senderAddress() && p.port == quint16(d.senderPort());
            });
            if (known == m_peers.end() && m_peers.size() < 32)
                m_peers.push_back({d.senderAddress(), quint16(d.senderPort())});
        }
        emit received(d.data());
    }
}

} // namespace pf::ui
