#include "ui/vehicle/udp_link.h"

#include <QHostInfo>
#include <QNetworkDatagram>
#include <QUdpSocket>

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
    if (!server) {
        m_peer = host;
        m_peerPort = quint16(s.port);
    }
    return true;
}

void UdpLink::write(const QByteArray& bytes) {
    if (m_peerPort == 0)
        return; // a server answers once the vehicle has spoken
    m_socket->writeDatagram(bytes, m_peer, m_peerPort);
}

void UdpLink::readPending() {
    const bool server = spec().kind == mavlink::ConnectionSpec::Kind::UdpServer;
    while (m_socket->hasPendingDatagrams()) {
        const QNetworkDatagram d = m_socket->receiveDatagram();
        if (server) {
            m_peer = d.senderAddress();
            m_peerPort = quint16(d.senderPort());
        }
        emit received(d.data());
    }
}

} // namespace pf::ui
