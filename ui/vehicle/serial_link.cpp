#include "ui/vehicle/serial_link.h"

#include <QSerialPort>

namespace pf::ui {

SerialLink::SerialLink(mavlink::ConnectionSpec spec, QObject* parent)
    : VehicleLink(std::move(spec), parent), m_port(new QSerialPort(this)) {
    connect(m_port, &QSerialPort::readyRead, this, [this] { emit received(m_port->readAll()); });
    connect(m_port, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError e) {
        if (e == QSerialPort::ResourceError || e == QSerialPort::WriteError || e == QSerialPort::ReadError)
            emit failed(tr("%1: %2").arg(describe(), m_port->errorString()));
    });
}

bool SerialLink::open(QString* error) {
    m_port->setPortName(QString::fromStdString(spec().device));
    m_port->setBaudRate(spec().baud);
    m_port->setDataBits(QSerialPort::Data8);
    m_port->setParity(QSerialPort::NoParity);
    m_port->setStopBits(QSerialPort::OneStop);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    if (!m_port->open(QIODevice::ReadWrite)) {
        if (error)
            *error = tr("%1: %2").arg(describe(), m_port->errorString());
        return false;
    }
    return true;
}

void SerialLink::write(const QByteArray& bytes) {
    if (m_port->isOpen())
        m_port->write(bytes);
}

} // namespace pf::ui
