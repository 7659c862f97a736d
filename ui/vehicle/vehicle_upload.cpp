#include "ui/vehicle/vehicle_upload.h"

#include "ui/vehicle/vehicle_link.h"

#include <QTimer>

namespace pf::ui {

VehicleUpload::VehicleUpload(QString aircraft, mavlink::VehiclePlan plan,
                             mavlink::TransferOptions options, VehicleLink* link, QObject* parent)
    : QObject(parent), m_aircraft(std::move(aircraft)), m_transfer(std::move(plan), options),
      m_link(link), m_timer(new QTimer(this)) {
    m_timer->setInterval(20);
    connect(m_timer, &QTimer::timeout, this, &VehicleUpload::pump);
    connect(m_link, &VehicleLink::received, this, &VehicleUpload::onBytes);
    connect(m_link, &VehicleLink::failed, this, [this](const QString& why) { abort(why); });
}

void VehicleUpload::start() {
    m_clock.start();
    m_transfer.start(0);
    m_timer->start();
    pump();
}

void VehicleUpload::abort(const QString& why) {
    if (isFinished())
        return;
    m_aborted = true;
    m_abortReason = why;
    m_timer->stop();
    emit progressChanged();
    emit finished(false);
}

void VehicleUpload::onBytes(const QByteArray& bytes) {
    if (isFinished())
        return;
    m_transfer.receive(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                       std::size_t(bytes.size()), m_clock.elapsed());
    pump();
}

void VehicleUpload::pump() {
    if (m_aborted)
        return;
    m_transfer.tick(m_clock.elapsed());
    const mavlink::Bytes out = m_transfer.takeOutgoing();
    if (!out.empty())
        m_link->write(QByteArray(reinterpret_cast<const char*>(out.data()), int(out.size())));
    if (!m_reportedVehicle && m_transfer.vehicle()) {
        m_reportedVehicle = true;
        emit vehicleFound(vehicleText());
    }
    const auto p = m_transfer.progress();
    if (p.phase != m_lastProgress.phase || p.done != m_lastProgress.done || p.type != m_lastProgress.type) {
        m_lastProgress = p;
        emit progressChanged();
    }
    if (m_transfer.finished() && !m_reportedEnd) {
        m_reportedEnd = true;
        m_timer->stop();
        emit finished(m_transfer.succeeded());
    }
}

QString VehicleUpload::vehicleText() const {
    const auto v = m_transfer.vehicle();
    if (!v)
        return QString();
    return tr("%1, %2, system id %3")
        .arg(QString::fromStdString(mavlink::vehicleTypeName(v->type)),
             QString::fromStdString(mavlink::autopilotName(v->autopilot)))
        .arg(v->systemId);
}

QString VehicleUpload::phaseText() const {
    if (m_aborted)
        return tr("Failed");
    const auto p = m_transfer.progress();
    const QString type = QString::fromLatin1(mavlink::missionTypeName(p.type));
    switch (p.phase) {
    case mavlink::TransferPhase::NotStarted:
        return tr("Not started");
    case mavlink::TransferPhase::WaitingForVehicle:
        return tr("Waiting for the vehicle's heartbeat…");
    case mavlink::TransferPhase::Uploading:
        return tr("Sending the %1…").arg(type);
    case mavlink::TransferPhase::Verifying:
        return tr("Reading the %1 back…").arg(type);
    case mavlink::TransferPhase::Succeeded:
        return tr("Uploaded");
    case mavlink::TransferPhase::Failed:
        return tr("Failed");
    }
    return QString();
}

QStringList VehicleUpload::vehicleMessages() const {
    QStringList out;
    for (const auto& m : m_transfer.vehicleMessages())
        out << QString::fromStdString(m);
    return out;
}

QString VehicleUpload::resultText() const {
    QString text = m_aborted ? m_abortReason : QString::fromStdString(m_transfer.message());
    for (const auto& n : m_transfer.notes())
        text += QStringLiteral("\n") + tr("Note: %1").arg(QString::fromStdString(n));
    const QStringList said = vehicleMessages();
    if (!said.isEmpty())
        text += QStringLiteral("\n") + tr("The vehicle said: %1").arg(said.join(QStringLiteral(" | ")));
    return text;
}

} // namespace pf::ui
