// VehicleUpload: one mission transfer (core/mavlink) driven by Qt: bytes from a shared link, a timer
// for the protocol's timeouts, progress and the result as signals.
#pragma once

#include "core/mavlink/mission_transfer.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QStringList>

class QTimer;

namespace pf::ui {

class VehicleLink;

class VehicleUpload : public QObject {
    Q_OBJECT
public:
    VehicleUpload(QString aircraft, mavlink::VehiclePlan plan, mavlink::TransferOptions options,
                  VehicleLink* link, QObject* parent = nullptr);

    void start();
    // Ends the transfer as failed (the user cancelled or the link broke).
    void abort(const QString& why);

    const QString& aircraft() const { return m_aircraft; }
    bool isFinished() const { return m_transfer.finished() || m_aborted; }
    bool succeeded() const { return !m_aborted && m_transfer.succeeded(); }
    mavlink::TransferProgress progress() const { return m_transfer.progress(); }
    // The result in words, with the vehicle's own messages and notes.
    QString resultText() const;
    QString phaseText() const;
    // "quadrotor, ArduPilot, system id 1" once its heartbeat was heard.
    QString vehicleText() const;
    QStringList vehicleMessages() const;

signals:
    void progressChanged();
    void vehicleFound(const QString& description);
    void finished(bool ok);

private:
    void pump();
    void onBytes(const QByteArray& bytes);

    QString m_aircraft;
    mavlink::MissionTransfer m_transfer;
    VehicleLink* m_link;
    QTimer* m_timer;
    QElapsedTimer m_clock;
    bool m_aborted = false;
    bool m_reportedVehicle = false;
    bool m_reportedEnd = false;
    QString m_abortReason;
    mavlink::TransferProgress m_lastProgress;
};

} // namespace pf::ui
