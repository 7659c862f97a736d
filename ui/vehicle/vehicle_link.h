// VehicleLink: a byte pipe to one or more vehicles (UDP client or server, TCP, serial), created from
// a mavlink::ConnectionSpec. The MAVLink protocol itself lives in core/mavlink.
#pragma once

#include "core/mavlink/connection_spec.h"

#include <QByteArray>
#include <QObject>
#include <QString>

#include <memory>

namespace pf::ui {

class VehicleLink : public QObject {
    Q_OBJECT
public:
    explicit VehicleLink(mavlink::ConnectionSpec spec, QObject* parent = nullptr)
        : QObject(parent), m_spec(std::move(spec)) {}
    // Opens the link; false with `error` in words when it cannot (port in use, no such device).
    // A TCP connection is made in the background: a refusal arrives as failed().
    virtual bool open(QString* error) = 0;
    virtual void write(const QByteArray& bytes) = 0;
    const mavlink::ConnectionSpec& spec() const { return m_spec; }
    QString describe() const { return QString::fromStdString(m_spec.describe()); }

signals:
    void received(const QByteArray& bytes);
    // The link broke or could not be made; the reason in words.
    void failed(const QString& why);

private:
    mavlink::ConnectionSpec m_spec;
};

std::unique_ptr<VehicleLink> createLink(const mavlink::ConnectionSpec& spec);

} // namespace pf::ui
