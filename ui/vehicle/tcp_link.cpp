#include "ui/vehicle/tcp_link.h"

#include <QTcpSocket>

namespace pf::ui {

TcpLink::TcpLink(mavlink::ConnectionSpec spec, QObject* parent)
    : VehicleLink(std::move(spec), parent), m_socket(new QTcpSocket(this)) {
    connect(m_socket, &QTcpSocket::connected, this, [this] {
        m_connected = true;
        if (!m_pending.isEmpty())
            m_socket->write(m_pending);
        m_pending.clear();
    });
    connect(m_socket, &QTcpSocket::readyRead, this, [this] { emit received(m_socket->readAll()); });
    connect(m_socket, &QAbstractSocket::errorOccurred, this, [this](QAbstractSocket::SocketError) {
        emit failed(tr("%1: %2").arg(describe(), m_socket->errorString()));
    });
}

bool TcpLink::open(QString*) {
    m_socket->connectToHost(QString::fromStdString(spec().host), quint16(spec().port));
    return true;
}

void TcpLink::write(const QByteArray& bytes) {
    if (m_connected)
        m_socket->write(bytes);
    else if (m_pending.size() < 65536)
        m_pending += bytes;
}

} // namespace pf::ui
